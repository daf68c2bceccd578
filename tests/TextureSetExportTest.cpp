// core/export/ExportTemplate and core/export/TextureSetExport: a material written as engine texture sets.
// Each built-in template's files are read back with OpenImageIO and every channel of every file
// is held to the engine's documented layout (a table written from the engines' docs, not from
// resources/export/*.json), on a test material whose maps hold a distinct value per channel, once
// with unit factors and once with factors, strengths and the DirectX flip to bake in. Then user
// templates: bit depths and formats as declared (PNG 16, TIFF 16/32, EXR half/float, TGA 8),
// colour-space tags; sizes (the largest map's, --size with its aspect, a filtered downsample, a
// material of constants as 1x1); texel placement (no row flip, UV transforms baked); a round trip
// per engine; plan-time refusals. Reading templates: tests/ExportTemplateTest.cpp.

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include <QDir>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <OpenImageIO/imageio.h>

#include <glm/geometric.hpp>

#include "TestAssets.h"
#include "TestSupport.h"
#include "core/export/ExportTemplate.h"
#include "core/export/TextureSetExport.h"
#include "core/image/MapImage.h"
#include "core/image/ToneMap.h"
#include "core/support/FileSet.h"

using namespace facet;

namespace {

// The test material's maps: uniform 4x4 8-bit textures, every channel a different value.
constexpr int kBase[4] = {51, 102, 153, 204}; // sRGB RGB, linear alpha
constexpr int kNormal[3] = {160, 100, 230}; // OpenGL tangent-space normal, encoded
constexpr int kPacked[3] = {178, 77, 230}; // R occlusion, G roughness, B metallic (an ORM file)
constexpr int kEmissive[3] = {128, 64, 32}; // sRGB

MapImage uniformMap(int width, int height, const int* values, int channels)
{
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 4; ++c)
                image.at(x, y)[c] = c < channels ? float(values[c]) / 255.0f : 1.0f;
    return MapImage::fromImage(image, channels == 4 ? MapLayout::Rgba : MapLayout::Rgb, MapSampleType::UInt8);
}

struct TestMaterial {
    Material material;
    MapImage base = uniformMap(4, 4, kBase, 4);
    MapImage normal = uniformMap(4, 4, kNormal, 3);
    MapImage packed = uniformMap(4, 4, kPacked, 3);
    MapImage emissive = uniformMap(4, 4, kEmissive, 3);
    bool withFactors = false;

    explicit TestMaterial(bool factors)
        : withFactors(factors)
    {
        material.name = "Test Mat";
        material.map(MapSlot::BaseColor).path = "base.png";
        material.map(MapSlot::Normal).path = "normal.png";
        for (const MapSlot slot : {MapSlot::Occlusion, MapSlot::Roughness, MapSlot::Metallic})
            material.map(slot).path = "orm.png";
        material.map(MapSlot::Occlusion).channel = MapChannel::R;
        material.map(MapSlot::Roughness).channel = MapChannel::G;
        material.map(MapSlot::Metallic).channel = MapChannel::B;
        material.map(MapSlot::Emissive).path = "emissive.png";
        material.map(MapSlot::Emissive).colorSpace = ColorEncoding::SRGB;
        material.setBaseColor(glm::dvec3(1.0), 1.0);
        material.setFactor(MapSlot::Metallic, 1.0);
        material.setFactor(MapSlot::Roughness, 1.0);
        material.setFactor(MapSlot::Occlusion, 1.0);
        material.setFactor(MapSlot::Normal, 1.0);
        material.map(MapSlot::Emissive).factor = glm::dvec4(1.0);
        material.emissiveStrength = 7.0; // a parameter, never in the texture
        if (factors) {
            material.setBaseColor(glm::dvec3(0.5, 0.25, 1.0), 0.5);
            material.setFactor(MapSlot::Metallic, 0.5);
            material.setFactor(MapSlot::Roughness, 0.75);
            material.setFactor(MapSlot::Occlusion, 0.5); // strength
            material.setFactor(MapSlot::Normal, 2.0); // strength
            material.map(MapSlot::Normal).flipGreen = true;
            material.map(MapSlot::Emissive).factor = glm::dvec4(0.5, 1.0, 0.25, 1.0);
        }
    }

    MaterialMapImages images() const
    {
        MaterialMapImages result {};
        result[std::size_t(MapSlot::BaseColor)] = &base;
        result[std::size_t(MapSlot::Normal)] = &normal;
        result[std::size_t(MapSlot::Occlusion)] = &packed;
        result[std::size_t(MapSlot::Roughness)] = &packed;
        result[std::size_t(MapSlot::Metallic)] = &packed;
        result[std::size_t(MapSlot::Emissive)] = &emissive;
        return result;
    }

    // What a channel naming `source` must hold, as a linear value, worked out here from the
    // texels and factors (the glTF 2.0 rules), not by core/.
    double expected(const QString& source) const
    {
        if (source.startsWith(QStringLiteral("1-")))
            return 1.0 - expected(source.mid(2));
        if (source.startsWith(QStringLiteral("const:")))
            return source.mid(6).toDouble();
        const glm::dvec4 baseFactor = material.baseColorFactor();
        const auto srgb = [](int v) { return tonemap::srgbToLinear(v / 255.0); };
        if (source == QStringLiteral("baseColor.r"))
            return baseFactor.r * srgb(kBase[0]);
        if (source == QStringLiteral("baseColor.g"))
            return baseFactor.g * srgb(kBase[1]);
        if (source == QStringLiteral("baseColor.b"))
            return baseFactor.b * srgb(kBase[2]);
        if (source == QStringLiteral("baseColor.a"))
            return baseFactor.a * kBase[3] / 255.0;
        if (source.startsWith(QStringLiteral("normal."))) {
            glm::dvec3 n = glm::dvec3(kNormal[0], kNormal[1], kNormal[2]) / 255.0 * 2.0 - 1.0;
            if (withFactors) {
                n.y = -n.y; // DirectX map read as OpenGL
                n.x *= 2.0;
                n.y *= 2.0;
            }
            n = glm::normalize(n);
            const int axis = source.endsWith(QLatin1Char('x')) ? 0
                : source.endsWith(QLatin1Char('y'))            ? 1
                                                               : 2;
            return n[axis] * 0.5 + 0.5;
        }
        if (source == QStringLiteral("occlusion"))
            return 1.0 + material.occlusionStrength() * (kPacked[0] / 255.0 - 1.0);
        if (source == QStringLiteral("roughness"))
            return material.roughness() * kPacked[1] / 255.0;
        if (source == QStringLiteral("metallic"))
            return material.metallic() * kPacked[2] / 255.0;
        const glm::dvec4 emissiveFactor = material.map(MapSlot::Emissive).factor;
        if (source == QStringLiteral("emissive.r"))
            return emissiveFactor.r * srgb(kEmissive[0]);
        if (source == QStringLiteral("emissive.g"))
            return emissiveFactor.g * srgb(kEmissive[1]);
        if (source == QStringLiteral("emissive.b"))
            return emissiveFactor.b * srgb(kEmissive[2]);
        qFatal("unknown source %s", qPrintable(source));
    }
};

struct ReadBack {
    int width = 0;
    int height = 0;
    int channels = 0;
    OIIO::TypeDesc format;
    std::string colorSpace;
    std::vector<float> values; // as stored, normalised
};

std::optional<ReadBack> readBack(const QString& path)
{
    // Alpha as stored: OIIO would otherwise premultiply the colour by it.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto input = OIIO::ImageInput::open(path.toStdString(), &config);
    if (!input)
        return std::nullopt;
    const OIIO::ImageSpec& spec = input->spec();
    ReadBack r;
    r.width = spec.width;
    r.height = spec.height;
    r.channels = spec.nchannels;
    r.format = spec.format;
    r.colorSpace = spec.get_string_attribute("oiio:ColorSpace");
    r.values.resize(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, r.values.data()))
        return std::nullopt;
    return r;
}

// Writes `plan` into `folder` and returns the files' paths; fails the test on an error.
bool writeSet(const TextureSetPlan& plan, const TestMaterial& test, const QString& folder, std::string* error)
{
    FileSet files(folder.toStdString());
    return files.begin(error) && writeTextureSet(plan, test.material, test.images(), files, error)
        && files.commit(error);
}

std::optional<ExportTemplate> templateFrom(const QByteArray& json, std::string* error)
{
    const QJsonDocument document = QJsonDocument::fromJson(json);
    return ExportTemplate::fromJson(document.object(), error);
}

} // namespace

class TextureSetExportTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void builtinsAreThere()
    {
        QCOMPARE(ExportTemplate::builtinIds().size(), std::size_t(5));
        for (const std::string& id : ExportTemplate::builtinIds()) {
            const std::optional<ExportTemplate> t = ExportTemplate::builtin(id);
            QVERIFY2(t, id.c_str());
            QCOMPARE(t->id, id);
            QVERIFY(!t->name.empty());
        }
        QVERIFY(!ExportTemplate::builtin("unreal5"));
    }

    // Every file of every built-in template, every channel, against the engine's layout.
    void engineLayouts_data()
    {
        QTest::addColumn<QString>("templateId");
        QTest::addColumn<QString>("fileName");
        QTest::addColumn<QStringList>("sources"); // per channel; "1-" inverts, "const:V" a constant
        QTest::addColumn<bool>("srgb");
        QTest::addColumn<bool>("withFactors");
        const auto rows = [](bool factors) {
            const char* suffix = factors ? " (factors, strengths, DirectX flip)" : "";
            const auto row = [&](const char* id, const char* file, QStringList sources, bool srgb) {
                QTest::newRow(qPrintable(QStringLiteral("%1 %2%3").arg(
                    QLatin1String(id), QLatin1String(file), QLatin1String(suffix))))
                    << QString::fromLatin1(id) << QString::fromLatin1(file) << sources << srgb << factors;
            };
            const QStringList rgb = test::strings({"baseColor.r", "baseColor.g", "baseColor.b"});
            const QStringList rgba
                = test::strings({"baseColor.r", "baseColor.g", "baseColor.b", "baseColor.a"});
            const QStringList openGl = test::strings({"normal.x", "normal.y", "normal.z"});
            const QStringList emissive = test::strings({"emissive.r", "emissive.g", "emissive.b"});
            const QStringList orm = test::strings({"occlusion", "roughness", "metallic"});
            // Unreal: sRGB base colour, DirectX normal (green down), ORM packed R/G/B.
            row("unreal", "T_Test_Mat_BC.png", rgb, true);
            row("unreal", "T_Test_Mat_N.png", test::strings({"normal.x", "1-normal.y", "normal.z"}), false);
            row("unreal", "T_Test_Mat_ORM.png", orm, false);
            row("unreal", "T_Test_Mat_E.png", emissive, true);
            // Unity HDRP Lit: MaskMap R metallic, G occlusion, B detail mask, A smoothness.
            row("unity-hdrp", "Test_Mat_BaseMap.png", rgba, true);
            row("unity-hdrp", "Test_Mat_Normal.png", openGl, false);
            row("unity-hdrp", "Test_Mat_MaskMap.png",
                test::strings({"metallic", "occlusion", "const:1", "1-roughness"}), false);
            row("unity-hdrp", "Test_Mat_Emissive.png", emissive, true);
            // Unity URP Lit: metallic in R, smoothness in A; occlusion a map of its own.
            row("unity-urp", "Test_Mat_BaseMap.png", rgba, true);
            row("unity-urp", "Test_Mat_Normal.png", openGl, false);
            row("unity-urp", "Test_Mat_MetallicSmoothness.png",
                test::strings({"metallic", "metallic", "metallic", "1-roughness"}), false);
            row("unity-urp", "Test_Mat_Occlusion.png", test::strings({"occlusion"}), false);
            row("unity-urp", "Test_Mat_Emission.png", emissive, true);
            // Godot 4 ORMMaterial3D: OpenGL normal, ORM.
            row("godot", "Test_Mat_albedo.png", rgba, true);
            row("godot", "Test_Mat_normal.png", openGl, false);
            row("godot", "Test_Mat_orm.png", orm, false);
            row("godot", "Test_Mat_emission.png", emissive, true);
            // glTF 2.0: occlusion R, roughness G, metallic B (one texture serves both inputs).
            row("gltf-textures", "Test_Mat_baseColor.png", rgba, true);
            row("gltf-textures", "Test_Mat_normal.png", openGl, false);
            row("gltf-textures", "Test_Mat_occlusionRoughnessMetallic.png", orm, false);
            row("gltf-textures", "Test_Mat_emissive.png", emissive, true);
        };
        rows(false);
        rows(true);
    }

    void engineLayouts()
    {
        QFETCH(QString, templateId);
        QFETCH(QString, fileName);
        QFETCH(QStringList, sources);
        QFETCH(bool, srgb);
        QFETCH(bool, withFactors);
        const TestMaterial test(withFactors);
        const std::optional<ExportTemplate> t = ExportTemplate::builtin(templateId.toStdString());
        QVERIFY(t);
        std::string error;
        const std::optional<TextureSetPlan> plan
            = planTextureSet(*t, test.material, test.images(), {}, &error);
        QVERIFY2(plan, error.c_str());
        QTemporaryDir dir;
        QVERIFY2(writeSet(*plan, test, dir.path(), &error), error.c_str());

        const std::optional<ReadBack> file = readBack(dir.filePath(fileName));
        QVERIFY2(file,
            qPrintable(fileName + QStringLiteral(" missing: ")
                + QDir(dir.path()).entryList().join(QStringLiteral(", "))));
        QCOMPARE(file->width, 4);
        QCOMPARE(file->height, 4);
        QCOMPARE(file->channels, int(sources.size()));
        QCOMPARE(file->format, OIIO::TypeDesc(OIIO::TypeDesc::UINT8));
        QCOMPARE(QString::fromStdString(file->colorSpace),
            srgb ? QStringLiteral("sRGB") : QStringLiteral("Linear"));
        for (int c = 0; c < int(sources.size()); ++c) {
            const double linear = test.expected(sources[c]);
            const bool encoded = srgb && !sources[c].startsWith(QStringLiteral("const:"))
                && !((sources.size() == 4 || sources.size() == 2) && c == int(sources.size()) - 1);
            const double stored = encoded ? tonemap::linearToSrgb(linear) : linear;
            for (int p = 0; p < 16; ++p) {
                const double got = file->values[std::size_t(p * file->channels + c)];
                if (std::abs(got - stored) > 0.5 / 255.0 + 1e-6)
                    QFAIL(qPrintable(QStringLiteral("%1 channel %2 (%3): %4, expected %5 (%6 linear)")
                                         .arg(fileName)
                                         .arg(c)
                                         .arg(sources[c])
                                         .arg(got * 255.0)
                                         .arg(stored * 255.0)
                                         .arg(linear)));
            }
        }
    }

    // Export, read the files back as a new material would (the engine's convention: Unreal's
    // DirectX normal, Unity's smoothness in MaskMap alpha), and the material's inputs at every
    // texel match the original's to the files' 8-bit precision: a varied 16x8 material with
    // factors, strengths and the DirectX flip baked in.
    void roundTrip_data()
    {
        QTest::addColumn<QString>("templateId");
        QTest::newRow("gltf-textures") << QStringLiteral("gltf-textures");
        QTest::newRow("unreal") << QStringLiteral("unreal");
        QTest::newRow("unity-hdrp") << QStringLiteral("unity-hdrp");
        QTest::newRow("godot") << QStringLiteral("godot");
    }

    void roundTrip()
    {
        QFETCH(QString, templateId);
        // Every texel different: a gradient per channel, rows and columns in opposite senses.
        const auto varied = [](int seed, int channels) {
            return MapImage::fromImage(test::variedImage(seed, channels),
                channels == 4 ? MapLayout::Rgba : MapLayout::Rgb, MapSampleType::UInt8);
        };
        TestMaterial test(true);
        test.base = varied(1, 4);
        test.normal = varied(2, 3);
        test.packed = varied(3, 3);
        test.emissive = varied(4, 3);
        std::string error;
        const std::optional<ExportTemplate> t = ExportTemplate::builtin(templateId.toStdString());
        const std::optional<TextureSetPlan> plan
            = planTextureSet(*t, test.material, test.images(), {}, &error);
        QVERIFY2(plan, error.c_str());
        QTemporaryDir dir;
        QVERIFY2(writeSet(*plan, test, dir.path(), &error), error.c_str());

        // The files as an engine's material reads them.
        const auto load = [&](const QString& name) {
            std::optional<MapImage> image = MapImage::load(dir.filePath(name).toStdString(), &error);
            if (!image)
                qFatal("%s", error.c_str());
            return std::make_unique<MapImage>(std::move(*image));
        };
        Material back;
        back.setBaseColor(glm::dvec3(1.0), 1.0);
        for (const MapSlot slot :
            {MapSlot::Metallic, MapSlot::Roughness, MapSlot::Occlusion, MapSlot::Normal})
            back.setFactor(slot, 1.0);
        back.map(MapSlot::Emissive).factor = glm::dvec4(1.0);
        back.emissiveStrength = test.material.emissiveStrength;
        std::vector<std::unique_ptr<MapImage>> keep;
        MaterialMapImages images {};
        const auto use = [&](MapSlot slot, const QString& name, MapChannel channel, bool invert) {
            keep.push_back(load(name));
            images[std::size_t(slot)] = keep.back().get();
            MaterialMap& map = back.map(slot);
            map.path = name.toStdString();
            map.channel = channel;
            map.invert = invert;
            map.colorSpace = isColorSlot(slot) ? ColorEncoding::SRGB : ColorEncoding::Linear;
        };
        const QString m = QStringLiteral("Test_Mat_");
        if (templateId == QStringLiteral("unreal")) {
            use(MapSlot::BaseColor, QStringLiteral("T_") + m + QStringLiteral("BC.png"), MapChannel::Rgb,
                false);
            use(MapSlot::Normal, QStringLiteral("T_") + m + QStringLiteral("N.png"), MapChannel::Rgb, false);
            back.map(MapSlot::Normal).flipGreen = true;
            use(MapSlot::Occlusion, QStringLiteral("T_") + m + QStringLiteral("ORM.png"), MapChannel::R,
                false);
            use(MapSlot::Roughness, QStringLiteral("T_") + m + QStringLiteral("ORM.png"), MapChannel::G,
                false);
            use(MapSlot::Metallic, QStringLiteral("T_") + m + QStringLiteral("ORM.png"), MapChannel::B,
                false);
            use(MapSlot::Emissive, QStringLiteral("T_") + m + QStringLiteral("E.png"), MapChannel::Rgb,
                false);
        } else if (templateId == QStringLiteral("unity-hdrp")) {
            use(MapSlot::BaseColor, m + QStringLiteral("BaseMap.png"), MapChannel::Rgb, false);
            use(MapSlot::Normal, m + QStringLiteral("Normal.png"), MapChannel::Rgb, false);
            use(MapSlot::Metallic, m + QStringLiteral("MaskMap.png"), MapChannel::R, false);
            use(MapSlot::Occlusion, m + QStringLiteral("MaskMap.png"), MapChannel::G, false);
            use(MapSlot::Roughness, m + QStringLiteral("MaskMap.png"), MapChannel::A, true);
            use(MapSlot::Emissive, m + QStringLiteral("Emissive.png"), MapChannel::Rgb, false);
        } else {
            const bool godot = templateId == QStringLiteral("godot");
            use(MapSlot::BaseColor,
                m + (godot ? QStringLiteral("albedo.png") : QStringLiteral("baseColor.png")), MapChannel::Rgb,
                false);
            use(MapSlot::Normal, m + QStringLiteral("normal.png"), MapChannel::Rgb, false);
            const QString orm
                = m + (godot ? QStringLiteral("orm.png") : QStringLiteral("occlusionRoughnessMetallic.png"));
            use(MapSlot::Occlusion, orm, MapChannel::R, false);
            use(MapSlot::Roughness, orm, MapChannel::G, false);
            use(MapSlot::Metallic, orm, MapChannel::B, false);
            use(MapSlot::Emissive,
                m + (godot ? QStringLiteral("emission.png") : QStringLiteral("emissive.png")),
                MapChannel::Rgb, false);
        }

        // 8-bit steps: a data value within half a step; an sRGB-encoded colour within half a
        // step of its encoding (relative to the value, plus the dark end's linear toe).
        double worstScalar = 0.0;
        double worstColor = 0.0;
        double worstNormal = 0.0;
        for (int y = 0; y < 8; ++y) {
            for (int x = 0; x < 16; ++x) {
                const glm::dvec2 uv((x + 0.5) / 16.0, (y + 0.5) / 8.0);
                const MaterialInfo a = materialInputs(test.material, test.images(), uv);
                const MaterialInfo b = materialInputs(back, images, uv);
                worstScalar = std::max({worstScalar, std::abs(a.metallic - b.metallic),
                    std::abs(a.perceptualRoughness - b.perceptualRoughness),
                    std::abs(a.occlusion - b.occlusion)});
                for (int c = 0; c < 3; ++c)
                    worstColor = std::max({worstColor,
                        std::abs(
                            tonemap::linearToSrgb(a.baseColor[c]) - tonemap::linearToSrgb(b.baseColor[c])),
                        std::abs(tonemap::linearToSrgb(a.emissive[c] / 7.0)
                            - tonemap::linearToSrgb(b.emissive[c] / 7.0))});
                if (templateId != QStringLiteral("unreal")) // Unreal's base colour has no alpha
                    worstScalar = std::max(worstScalar, std::abs(a.alpha - b.alpha));
                const glm::dvec3 ng(0.0, 0.0, 1.0);
                const glm::dvec4 tangent(1.0, 0.0, 0.0, 1.0);
                const MaterialMap& na = test.material.map(MapSlot::Normal);
                const glm::dvec3 nA
                    = shadingNormal(ng, tangent, sampleTexture(test.normal, na.colorSpace, uv),
                        test.material.normalStrength(), na.flipGreen);
                const glm::dvec3 nB = shadingNormal(ng, tangent,
                    sampleTexture(*images[std::size_t(MapSlot::Normal)], ColorEncoding::Linear, uv), 1.0,
                    back.map(MapSlot::Normal).flipGreen);
                worstNormal = std::max(worstNormal, glm::length(nA - nB));
            }
        }
        qInfo("%s: worst scalar %.5f, colour %.5f (sRGB), normal %.5f", qPrintable(templateId), worstScalar,
            worstColor, worstNormal);
        QVERIFY2(worstScalar <= 0.5 / 255.0 + 1e-6, qPrintable(QString::number(worstScalar * 255.0)));
        QVERIFY2(worstColor <= 0.5 / 255.0 + 1e-6, qPrintable(QString::number(worstColor * 255.0)));
        QVERIFY2(worstNormal <= 2.0 / 255.0, qPrintable(QString::number(worstNormal * 255.0)));
    }

    // Optional outputs are skipped when the material does not use their sources; the rest
    // always. A row per template and per thing a material may or may not use.
    void optionalOutputs_data()
    {
        QTest::addColumn<QString>("templateId");
        QTest::addColumn<bool>("emits");
        QTest::addColumn<bool>("coated");
        QTest::addColumn<QStringList>("skipped");
        QTest::addColumn<QString>("lobe"); // "sheen", "specular" or none
        const auto row = [](const char* name, const char* templateId, bool emits, bool coated,
                             std::initializer_list<const char*> skipped, const char* lobe = "") {
            QStringList maps;
            for (const char* map : skipped)
                maps.append(QString::fromLatin1(map));
            QTest::newRow(name) << QString::fromLatin1(templateId) << emits << coated << maps
                                << QString::fromLatin1(lobe);
        };
        row("unreal, plain", "unreal", false, false, {"E", "CC", "ANI"});
        row("unreal, emitting", "unreal", true, false, {"CC", "ANI"});
        row("unreal, coated", "unreal", false, true, {"E", "ANI"});
        row("unreal, both", "unreal", true, true, {"ANI"});
        row("unity-hdrp, plain", "unity-hdrp", false, false, {"Emissive", "CoatMask", "AnisotropyMap", "TangentMap"});
        row("unity-hdrp, coated", "unity-hdrp", false, true, {"Emissive", "AnisotropyMap", "TangentMap"});
        row("unity-urp, emitting and coated (no coat channel)", "unity-urp", true, true, {"Occlusion"});
        row("godot, coated (no coat channel)", "godot", false, true, {"emission"});
        // glTF's coat textures: strength and roughness in one (R, G), and a coat normal map only
        // where there is one to write.
        row("gltf-textures, plain", "gltf-textures", false, false,
            {"emissive", "clearcoat", "clearcoatNormal", "sheen", "specular", "anisotropy"});
        row("gltf-textures, coated", "gltf-textures", false, true,
            {"emissive", "clearcoatNormal", "sheen", "specular", "anisotropy"});
        // The sheen's one texture (colour RGB, roughness A) only for a material with a sheen; the
        // specular layer's (colour RGB, strength A) only for one that is not the default.
        row("gltf-textures, sheen", "gltf-textures", false, false,
            {"emissive", "clearcoat", "clearcoatNormal", "specular", "anisotropy"}, "sheen");
        row("unreal, sheen (no sheen channel)", "unreal", false, false, {"E", "CC", "ANI"}, "sheen");
        row("gltf-textures, specular", "gltf-textures", false, false,
            {"emissive", "clearcoat", "clearcoatNormal", "sheen", "anisotropy"}, "specular");
        // The anisotropy's (direction RG, strength B, linear) only for an anisotropic material.
        row("gltf-textures, anisotropy", "gltf-textures", false, false,
            {"emissive", "clearcoat", "clearcoatNormal", "sheen", "specular"}, "anisotropy");
        row("unreal, specular (no specular colour channel)", "unreal", false, false, {"E", "CC", "ANI"}, "specular");
        // The engines' anisotropy: Unreal's one texture (direction RG, G flipped; strength B), HDRP's
        // Anisotropy Map (strength) and Tangent Map (direction, z 0); URP and Godot have none.
        row("unreal, anisotropy", "unreal", false, false, {"E", "CC"}, "anisotropy");
        row("unity-hdrp, anisotropy", "unity-hdrp", false, false, {"Emissive", "CoatMask"}, "anisotropy");
        row("unity-urp, anisotropy (no anisotropy channel)", "unity-urp", false, false, {"Occlusion", "Emission"},
            "anisotropy");
        row("godot, anisotropy (no anisotropy channel)", "godot", false, false, {"emission"}, "anisotropy");
    }
    void optionalOutputs()
    {
        QFETCH(QString, templateId);
        QFETCH(bool, emits);
        QFETCH(bool, coated);
        QFETCH(QStringList, skipped);
        QFETCH(QString, lobe);
        Material plain;
        plain.name = "Plain";
        if (emits)
            plain.map(MapSlot::Emissive).factor = glm::dvec4(0.0, 0.1, 0.0, 1.0); // no texture
        if (coated)
            plain.setClearcoat(0.75, 0.25);
        if (lobe == QLatin1String("sheen"))
            plain.setSheen(glm::dvec3(0.5, 0.25, 1.0), 0.6);
        if (lobe == QLatin1String("specular"))
            plain.setSpecular(0.6, glm::dvec3(0.5, 0.25, 1.0));
        if (lobe == QLatin1String("anisotropy"))
            plain.setAnisotropy(0.6, 60.0);
        const std::optional<ExportTemplate> exportTemplate
            = ExportTemplate::builtin(templateId.toStdString());
        QVERIFY(exportTemplate);
        std::string error;
        const std::optional<TextureSetPlan> plan = planTextureSet(*exportTemplate, plain, {}, {}, &error);
        QVERIFY2(plan, error.c_str());
        QStringList actual;
        for (const std::string& map : plan->skipped)
            actual.append(QString::fromStdString(map));
        QCOMPARE(actual, skipped);
        QCOMPARE(plan->files.size() + plan->skipped.size(), exportTemplate->outputs.size());
        if (lobe == QLatin1String("anisotropy")) {
            // The direction turned 60 degrees, (0.5, 0.866) x 0.5 + 0.5, and the strength 0.6; all
            // linear, per template.
            const double x = 0.5 * 0.5 + 0.5;
            const double y = std::sqrt(0.75) * 0.5 + 0.5;
            const std::map<QString, std::vector<std::pair<QString, std::vector<double>>>> expected = {
                {QStringLiteral("gltf-textures"), {{QStringLiteral("Plain_anisotropy.png"), {x, y, 0.6}}}},
                {QStringLiteral("unreal"), {{QStringLiteral("T_Plain_ANI.png"), {x, 1.0 - y, 0.6}}}},
                {QStringLiteral("unity-hdrp"),
                    {{QStringLiteral("Plain_AnisotropyMap.png"), {0.6}},
                        {QStringLiteral("Plain_TangentMap.png"), {x, y, 0.5}}}},
            };
            const auto files = expected.find(templateId);
            if (files == expected.end())
                return;
            TestMaterial test(false);
            test.material = plain;
            QTemporaryDir dir;
            QVERIFY2(writeSet(*plan, test, dir.path(), &error), error.c_str());
            for (const auto& [name, values] : files->second) {
                const std::optional<ReadBack> file = readBack(dir.filePath(name));
                QVERIFY2(file && file->values.size() == values.size(), qPrintable(name));
                for (std::size_t c = 0; c < values.size(); ++c)
                    QVERIFY2(std::abs(file->values[c] - values[c]) < 0.5 / 255.0 + 1e-6,
                        qPrintable(QStringLiteral("%1 channel %2: %3").arg(name).arg(c).arg(file->values[c])));
            }
            return;
        }
        if (!lobe.isEmpty() && templateId == QLatin1String("gltf-textures")) {
            // The lobe's texture: RGB the colour sRGB-encoded, A the scalar (linear).
            TestMaterial test(false);
            test.material = plain;
            QTemporaryDir dir;
            QVERIFY2(writeSet(*plan, test, dir.path(), &error), error.c_str());
            const std::optional<ReadBack> file
                = readBack(dir.filePath(QStringLiteral("Plain_%1.png").arg(lobe)));
            QVERIFY(file && file->channels == 4 && file->values.size() == 4);
            const double expected[4] = {tonemap::linearToSrgb(0.5), tonemap::linearToSrgb(0.25), 1.0, 0.6};
            for (int c = 0; c < 4; ++c)
                QVERIFY2(std::abs(file->values[std::size_t(c)] - expected[c]) < 0.5 / 255.0 + 1e-6,
                    qPrintable(QStringLiteral("channel %1: %2").arg(c).arg(file->values[std::size_t(c)])));
        }
        if (templateId != QLatin1String("unreal") || !coated)
            return;
        // Unreal's CC: R the coat's strength, G its roughness, B 0 (a material of constants: 1x1).
        TestMaterial test(false);
        test.material = plain;
        QTemporaryDir dir;
        QVERIFY2(writeSet(*plan, test, dir.path(), &error), error.c_str());
        const std::optional<ReadBack> cc = readBack(dir.filePath(QStringLiteral("T_Plain_CC.png")));
        QVERIFY(cc && cc->channels == 3 && cc->values.size() == 3);
        QVERIFY2(std::abs(cc->values[0] - 0.75f) < 0.5f / 255.0f
                && std::abs(cc->values[1] - 0.25f) < 0.5f / 255.0f && cc->values[2] == 0.0f,
            qPrintable(QStringLiteral("%1 %2 %3").arg(cc->values[0]).arg(cc->values[1]).arg(cc->values[2])));
    }

    // A material of constants: 1x1 files holding its factors (or --size's size).
    void constantsOnly()
    {
        TestMaterial test(false);
        Material constant;
        constant.name = "Gold";
        constant.setBaseColor(glm::dvec3(1.0, 0.766, 0.336));
        constant.setFactor(MapSlot::Metallic, 1.0);
        constant.setFactor(MapSlot::Roughness, 0.3);
        test.material = constant;
        const std::optional<ExportTemplate> t = ExportTemplate::builtin("gltf-textures");
        std::string error;
        for (const int size : {0, 8}) {
            TextureSetOptions options;
            options.size = size;
            const std::optional<TextureSetPlan> plan = planTextureSet(*t, constant, {}, options, &error);
            QVERIFY2(plan, error.c_str());
            QTemporaryDir dir;
            QVERIFY2(writeSet(*plan, test, dir.path(), &error), error.c_str());
            const std::optional<ReadBack> orm
                = readBack(dir.filePath(QStringLiteral("Gold_occlusionRoughnessMetallic.png")));
            QVERIFY(orm);
            QCOMPARE(orm->width, size == 0 ? 1 : 8);
            QCOMPARE(orm->height, size == 0 ? 1 : 8);
            QCOMPARE(orm->values[0], 1.0f); // no occlusion map: 1
            QVERIFY(std::abs(orm->values[1] - 0.3) <= 0.5 / 255.0 + 1e-6);
            QCOMPARE(orm->values[2], 1.0f);
            const std::optional<ReadBack> base = readBack(dir.filePath(QStringLiteral("Gold_baseColor.png")));
            QCOMPARE(qRound(base->values[1] * 255.0f), qRound(tonemap::linearToSrgb(0.766) * 255.0));
            QCOMPARE(base->values[3], 1.0f);
            const std::optional<ReadBack> normal = readBack(dir.filePath(QStringLiteral("Gold_normal.png")));
            QCOMPARE(qRound(normal->values[0] * 255.0f), 128); // (0, 0, 1) stored as (0.5, 0.5, 1)
            QCOMPARE(qRound(normal->values[1] * 255.0f), 128);
            QCOMPARE(normal->values[2], 1.0f);
        }
    }

    // Texels land where the material has them: the file's top row is v = 1 (no flip), a UV
    // transform is baked in (scale 2 repeats the map twice), a smaller map is magnified.
    void texelPlacement()
    {
        // A 4x2 base colour map, one texel per (x, row) with its own red value; row 0 of the
        // Image is its top row, v = 1.
        Image image(4, 2);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 4; ++x)
                image.at(x, y) = glm::vec4(float(y * 4 + x) * 30.0f / 255.0f, 0.0f, 0.0f, 1.0f);
        TestMaterial test(false);
        test.base = MapImage::fromImage(image, MapLayout::Rgba, MapSampleType::UInt8);
        test.material.map(MapSlot::BaseColor).colorSpace = ColorEncoding::Linear;
        test.material.map(MapSlot::Emissive).path.clear();
        for (const MapSlot slot :
            {MapSlot::Normal, MapSlot::Occlusion, MapSlot::Roughness, MapSlot::Metallic})
            test.material.map(slot).path.clear();
        const QByteArray json = test::exportTemplateJson(
            R"({"map": "R", "channels": ["baseColor.r"], "colorSpace": "linear"})");
        std::string error;
        const std::optional<ExportTemplate> t = templateFrom(json, &error);
        QVERIFY2(t, error.c_str());

        const auto exported = [&](const TestMaterial& m, ReadBack* out) {
            std::optional<TextureSetPlan> plan = planTextureSet(*t, m.material, m.images(), {}, &error);
            QTemporaryDir dir;
            if (!plan || !writeSet(*plan, m, dir.path(), &error))
                return false;
            *out = *readBack(dir.filePath(QStringLiteral("Test_Mat_R.png")));
            return true;
        };
        ReadBack file;
        QVERIFY2(exported(test, &file), error.c_str());
        QCOMPARE(file.width, 4);
        QCOMPARE(file.height, 2);
        for (int i = 0; i < 8; ++i)
            QCOMPARE(qRound(file.values[std::size_t(i)] * 255.0f), i * 30);

        test.material.map(MapSlot::BaseColor).uv.scale = glm::dvec2(2.0, 1.0);
        QVERIFY2(exported(test, &file), error.c_str());
        // u' = 2u: the file's texel x reads the map at column 2x + 0.5 -> between two texels.
        for (int x = 0; x < 4; ++x) {
            const double mapX = std::fmod(2.0 * (x + 0.5) - 0.5, 4.0);
            const int x0 = int(std::floor(mapX));
            const double f = mapX - x0;
            const double expected = ((1.0 - f) * (x0 % 4) + f * ((x0 + 1) % 4)) * 30.0;
            QCOMPARE(qRound(file.values[std::size_t(x)] * 255.0f), qRound(expected));
        }
    }

    // The set's size is the largest map's; --size keeps the aspect; a downsample is filtered.
    void sizes()
    {
        // A 64x32 checker of 0 and 1 in the roughness map (linear), the other maps 4x4.
        Image checker(64, 32);
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 64; ++x)
                checker.at(x, y) = glm::vec4(glm::vec3(float((x + y) % 2)), 1.0f);
        TestMaterial test(false);
        test.packed = MapImage::fromImage(checker, MapLayout::Rgb, MapSampleType::UInt8);
        const std::optional<ExportTemplate> t = ExportTemplate::builtin("unreal");
        std::string error;
        std::optional<TextureSetPlan> plan = planTextureSet(*t, test.material, test.images(), {}, &error);
        QVERIFY2(plan, error.c_str());
        for (const PlannedTexture& file : plan->files) {
            QCOMPARE(file.width, 64);
            QCOMPARE(file.height, 32);
        }
        TextureSetOptions options;
        options.size = 16;
        plan = planTextureSet(*t, test.material, test.images(), options, &error);
        QCOMPARE(plan->files[0].width, 16);
        QCOMPARE(plan->files[0].height, 8);
        QCOMPARE(QString::fromStdString(plan->files[0].fileName), QStringLiteral("T_Test_Mat_BC.png"));
        QTemporaryDir dir;
        QVERIFY2(writeSet(*plan, test, dir.path(), &error), error.c_str());
        const std::optional<ReadBack> orm = readBack(dir.filePath(QStringLiteral("T_Test_Mat_ORM.png")));
        QVERIFY(orm);
        QCOMPARE(orm->width, 16);
        QCOMPARE(orm->height, 8);
        // A point-sampled 4:1 reduction of a one-texel checker is all 0 or all 1; a filter gives
        // the checker's mean, 0.5, everywhere.
        for (int p = 0; p < 16 * 8; ++p) {
            const float roughness = orm->values[std::size_t(p * 3 + 1)];
            if (std::abs(roughness - 0.5f) > 0.02f)
                QFAIL(qPrintable(QStringLiteral("texel %1: roughness %2, the checker's mean is 0.5")
                                     .arg(p)
                                     .arg(roughness)));
        }
    }

    // User templates: each bit depth and format as declared, colour tags, tokens.
    void userTemplateFormats_data()
    {
        QTest::addColumn<QByteArray>("output");
        QTest::addColumn<QString>("fileName");
        QTest::addColumn<int>("type"); // OIIO::TypeDesc::BASETYPE
        QTest::addColumn<QString>("colorSpace");
        QTest::addColumn<int>("channels");
        QTest::newRow("png 16 linear grey")
            << QByteArray(R"({"map": "R", "channels": ["roughness"], "bitDepth": 16})")
            << QStringLiteral("Test_Mat_R.png") << int(OIIO::TypeDesc::UINT16) << QStringLiteral("Linear")
            << 1;
        QTest::newRow("png 8 sRGB grey+alpha")
            << QByteArray(
                   R"({"map": "BA", "channels": ["baseColor.g", "baseColor.a"], "colorSpace": "srgb"})")
            << QStringLiteral("Test_Mat_BA.png") << int(OIIO::TypeDesc::UINT8) << QStringLiteral("sRGB") << 2;
        QTest::newRow("tiff 16") << QByteArray(
            R"({"map": "M", "channels": ["metallic", "roughness"], "bitDepth": 16, "fileFormat": "tiff"})")
                                 << QStringLiteral("Test_Mat_M.tif") << int(OIIO::TypeDesc::UINT16)
                                 << QStringLiteral("Linear") << 2;
        QTest::newRow("tiff 32 float")
            << QByteArray(R"({"map": "M", "channels": ["metallic"], "bitDepth": 32, "fileFormat": "tiff"})")
            << QStringLiteral("Test_Mat_M.tif") << int(OIIO::TypeDesc::FLOAT) << QStringLiteral("Linear")
            << 1;
        QTest::newRow("exr half") << QByteArray(
            R"({"map": "E", "channels": ["emissive.r", "emissive.g", "emissive.b"], "bitDepth": 16, "fileFormat": "exr"})")
                                  << QStringLiteral("Test_Mat_E.exr") << int(OIIO::TypeDesc::HALF)
                                  << QStringLiteral("Linear") << 3;
        QTest::newRow("exr float") << QByteArray(
            R"({"map": "N", "channels": ["normal.x", "normal.y", "normal.z", 0.25], "bitDepth": 32, "fileFormat": "exr"})")
                                   << QStringLiteral("Test_Mat_N.exr") << int(OIIO::TypeDesc::FLOAT)
                                   << QStringLiteral("Linear") << 4;
        QTest::newRow("tga 8 sRGB") << QByteArray(
            R"({"map": "C", "channels": ["baseColor.r", "baseColor.g", "baseColor.b"], "colorSpace": "srgb", "fileFormat": "tga"})")
                                    << QStringLiteral("Test_Mat_C.tga") << int(OIIO::TypeDesc::UINT8)
                                    << QStringLiteral("sRGB") << 3;
    }

    void userTemplateFormats()
    {
        QFETCH(QByteArray, output);
        QFETCH(QString, fileName);
        QFETCH(int, type);
        QFETCH(QString, colorSpace);
        QFETCH(int, channels);
        std::string error;
        const std::optional<ExportTemplate> t = templateFrom(test::exportTemplateJson(output), &error);
        QVERIFY2(t, error.c_str());
        const TestMaterial test(true);
        const std::optional<TextureSetPlan> plan
            = planTextureSet(*t, test.material, test.images(), {}, &error);
        QVERIFY2(plan, error.c_str());
        QTemporaryDir dir;
        QVERIFY2(writeSet(*plan, test, dir.path(), &error), error.c_str());
        const std::optional<ReadBack> file = readBack(dir.filePath(fileName));
        QVERIFY2(file, qPrintable(QDir(dir.path()).entryList().join(QStringLiteral(", "))));
        QCOMPARE(int(file->format.basetype), type);
        QCOMPARE(file->channels, channels);
        // TIFF and TGA have no colour-space tag OpenImageIO writes and reads back.
        if (fileName.endsWith(QStringLiteral(".tga")) || fileName.endsWith(QStringLiteral(".tif")))
            QVERIFY2(file->colorSpace.empty() || QString::fromStdString(file->colorSpace) == colorSpace,
                file->colorSpace.c_str());
        else
            QCOMPARE(QString::fromStdString(file->colorSpace), colorSpace);
        // The first channel's value, to the file's precision.
        const ExportChannel& first = t->outputs[0].channels[0];
        const ExportTexel texel = exportTexel(test.material, test.images(), glm::dvec2(0.5));
        double expected = channelValue(first, texel);
        if (colorSpace == QStringLiteral("sRGB"))
            expected = tonemap::linearToSrgb(expected);
        const double step = type == int(OIIO::TypeDesc::UINT8) ? 0.5 / 255.0
            : type == int(OIIO::TypeDesc::UINT16)              ? 0.5 / 65535.0
            : type == int(OIIO::TypeDesc::HALF)                ? 1e-3
                                                               : 1e-6;
        QVERIFY2(std::abs(file->values[0] - expected) <= step + 1e-7,
            qPrintable(QStringLiteral("%1, expected %2").arg(file->values[0]).arg(expected)));
    }

    // Plan-time refusals: a bit depth the format cannot hold, two files of one name.
    void badPlans()
    {
        const TestMaterial test(false);
        std::string error;
        TextureSetOptions options;
        options.bitDepth = 32;
        QVERIFY(!planTextureSet(
            *ExportTemplate::builtin("unreal"), test.material, test.images(), options, &error));
        QCOMPARE(error,
            std::string("unreal's BC is png, which cannot hold 32-bit channels (png: 8, 16; tga: 8; "
                        "tiff: 8, 16, 32; exr: 16, 32)"));
        options.bitDepth = 16;
        const std::optional<TextureSetPlan> plan = planTextureSet(
            *ExportTemplate::builtin("unreal"), test.material, test.images(), options, &error);
        QVERIFY2(plan, error.c_str());
        QCOMPARE(plan->files[0].output.bitDepth, 16);
        const std::optional<ExportTemplate> twice = templateFrom(
            test::exportTemplateJson(
                R"({"map": "R", "channels": ["roughness"]}, {"map": "R", "channels": ["metallic"]})"),
            &error);
        QVERIFY2(twice, error.c_str());
        QVERIFY(!planTextureSet(*twice, test.material, test.images(), {}, &error));
        QVERIFY2(QString::fromStdString(error).contains(QStringLiteral("names two files Test_Mat_R.png")),
            error.c_str());
    }

    void dryRunDescription()
    {
        const TestMaterial test(false);
        std::string error;
        const std::optional<TextureSetPlan> plan = planTextureSet(
            *ExportTemplate::builtin("unity-hdrp"), test.material, test.images(), {}, &error);
        QCOMPARE(describe(plan->files[2]),
            std::string("Test_Mat_MaskMap.png  4x4  RGBA 8-bit linear: R metallic, G occlusion, B constant "
                        "1.000, A 1 - "
                        "roughness"));
    }
};

QTEST_GUILESS_MAIN(TextureSetExportTest)
#include "TextureSetExportTest.moc"
