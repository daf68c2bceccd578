// core/export/ExportTemplate and core/export/TextureSetExport: a material written as engine texture sets.
// Each built-in template's files are read back with OpenImageIO and every channel of every file
// is held to the engine's documented layout (a table written from the engines' docs, not from
// resources/export/*.json), on a test material whose maps hold a distinct value per channel, once
// with unit factors and once with factors, strengths and the DirectX flip to bake in; a round trip
// per engine; the optional outputs each template skips. User templates' formats and colour tags,
// sizes, texel placement and plan-time refusals: tests/TextureSetFormatsTest.cpp. Reading
// templates: tests/ExportTemplateTest.cpp.

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include <QDir>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <OpenImageIO/imageio.h>

#include <glm/geometric.hpp>

#include "TestAssets.h"
#include "TestSupport.h"
#include "TextureSetTestMaterial.h"
#include "core/export/ExportTemplate.h"
#include "core/export/TextureSetExport.h"
#include "core/image/MapImage.h"
#include "core/image/ToneMap.h"
#include "core/material/MaterialProperties.h"

using namespace facet;
using facet::test::ReadBack;
using facet::test::readBack;
using facet::test::TestMaterial;
using facet::test::writeSet;

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

    // Every channel source the registry names (core/material/MaterialProperties, exportField),
    // read at a texel of a material of factors alone, each a distinct number: the name parses
    // back to the row and the value is the row's factor (a unit vector's stored v * 0.5 + 0.5).
    // The table is written here, not from the registry: a row that gains or loses a source, or
    // a source exportTexel leaves unset (it reads 0), turns a row red.
    void everySourceReadsItsRow_data()
    {
        QTest::addColumn<QString>("source");
        QTest::addColumn<double>("expected");
        const double c60 = 0.5 * 0.5 + 0.5; // the direction turned 60 degrees: (cos, sin) stored
        const double s60 = std::sqrt(3.0) / 2.0 * 0.5 + 0.5;
        const std::map<std::string, double> expected = {{"baseColor.r", 0.11}, {"baseColor.g", 0.12},
            {"baseColor.b", 0.13}, {"baseColor.a", 0.14}, {"metallic", 0.21}, {"roughness", 0.31},
            {"occlusion", 1.0}, // the strength mixes toward a texture; without one, unoccluded
            {"normal.x", 0.5}, {"normal.y", 0.5}, {"normal.z", 1.0}, {"emissive.r", 0.41},
            {"emissive.g", 0.42}, {"emissive.b", 0.43}, {"clearcoat", 0.51}, {"clearcoatRoughness", 0.52},
            {"clearcoatNormal.x", 0.5}, {"clearcoatNormal.y", 0.5}, {"clearcoatNormal.z", 1.0},
            {"sheenColor.r", 0.61}, {"sheenColor.g", 0.62}, {"sheenColor.b", 0.63}, {"sheenRoughness", 0.64},
            {"specular", 0.71}, {"specularColor.r", 0.72}, {"specularColor.g", 0.73},
            {"specularColor.b", 0.74}, {"anisotropy", 0.81}, {"anisotropyDirection.x", c60},
            {"anisotropyDirection.y", s60}, {"iridescence", 0.91},
            {"iridescenceThickness", 1.0}}; // no thickness texture: the maximum
        std::size_t found = 0;
        for (const ExportSource& source : exportSources()) {
            const std::string name = toString(source);
            const auto it = expected.find(name);
            if (it == expected.end())
                QFAIL(qPrintable(QStringLiteral("the registry's source %1 has no row here")
                                     .arg(QString::fromStdString(name))));
            QTest::newRow(name.c_str()) << QString::fromStdString(name) << it->second;
            ++found;
        }
        QCOMPARE(found, expected.size());
    }

    void everySourceReadsItsRow()
    {
        QFETCH(QString, source);
        QFETCH(double, expected);
        using P = MaterialProperty;
        Material material;
        setColor(material, P::BaseColor, {0.11, 0.12, 0.13});
        setScalar(material, P::Alpha, 0.14);
        setScalar(material, P::Metallic, 0.21);
        setScalar(material, P::Roughness, 0.31);
        setScalar(material, P::Occlusion, 0.35);
        setColor(material, P::Emissive, {0.41, 0.42, 0.43});
        setScalar(material, P::Clearcoat, 0.51);
        setScalar(material, P::ClearcoatRoughness, 0.52);
        setColor(material, P::SheenColor, {0.61, 0.62, 0.63});
        setScalar(material, P::SheenRoughness, 0.64);
        setScalar(material, P::Specular, 0.71);
        setColor(material, P::SpecularColor, {0.72, 0.73, 0.74});
        setScalar(material, P::Anisotropy, 0.81);
        setScalar(material, P::AnisotropyRotation, 60.0);
        setScalar(material, P::Iridescence, 0.91);

        const std::optional<ExportSource> parsed = exportSourceFromString(source.toStdString());
        QVERIFY(parsed);
        QCOMPARE(QString::fromStdString(toString(*parsed)), source);
        const MaterialMapImages images {};
        const ExportTexel texel = exportTexel(material, images, glm::dvec2(0.5));
        QVERIFY(std::abs(channelValue(ExportChannel {parsed, 0.0, false}, texel) - expected) < 1e-9);
        QVERIFY(std::abs(channelValue(ExportChannel {parsed, 0.0, true}, texel) - (1.0 - expected)) < 1e-9);
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
        row("unity-hdrp, plain", "unity-hdrp", false, false,
            {"Emissive", "CoatMask", "AnisotropyMap", "TangentMap", "IridescenceMask", "IridescenceThickness"});
        row("unity-hdrp, coated", "unity-hdrp", false, true,
            {"Emissive", "AnisotropyMap", "TangentMap", "IridescenceMask", "IridescenceThickness"});
        row("unity-urp, emitting and coated (no coat channel)", "unity-urp", true, true, {"Occlusion"});
        row("godot, coated (no coat channel)", "godot", false, true, {"emission"});
        // glTF's coat textures: strength and roughness in one (R, G), and a coat normal map only
        // where there is one to write.
        row("gltf-textures, plain", "gltf-textures", false, false,
            {"emissive", "clearcoat", "clearcoatNormal", "sheen", "specular", "anisotropy", "iridescence"});
        row("gltf-textures, coated", "gltf-textures", false, true,
            {"emissive", "clearcoatNormal", "sheen", "specular", "anisotropy", "iridescence"});
        // The sheen's one texture (colour RGB, roughness A) only for a material with a sheen; the
        // specular layer's (colour RGB, strength A) only for one that is not the default.
        row("gltf-textures, sheen", "gltf-textures", false, false,
            {"emissive", "clearcoat", "clearcoatNormal", "specular", "anisotropy", "iridescence"}, "sheen");
        row("unreal, sheen (no sheen channel)", "unreal", false, false, {"E", "CC", "ANI"}, "sheen");
        row("gltf-textures, specular", "gltf-textures", false, false,
            {"emissive", "clearcoat", "clearcoatNormal", "sheen", "anisotropy", "iridescence"},
            "specular");
        // The anisotropy's (direction RG, strength B, linear) only for an anisotropic material.
        row("gltf-textures, anisotropy", "gltf-textures", false, false,
            {"emissive", "clearcoat", "clearcoatNormal", "sheen", "specular", "iridescence"}, "anisotropy");
        row("unreal, specular (no specular colour channel)", "unreal", false, false, {"E", "CC", "ANI"}, "specular");
        // The engines' anisotropy: Unreal's one texture (direction RG, G flipped; strength B), HDRP's
        // Anisotropy Map (strength) and Tangent Map (direction, z 0); URP and Godot have none.
        row("unreal, anisotropy", "unreal", false, false, {"E", "CC"}, "anisotropy");
        row("unity-hdrp, anisotropy", "unity-hdrp", false, false,
            {"Emissive", "CoatMask", "IridescenceMask", "IridescenceThickness"}, "anisotropy");
        row("unity-urp, anisotropy (no anisotropy channel)", "unity-urp", false, false, {"Occlusion", "Emission"},
            "anisotropy");
        row("godot, anisotropy (no anisotropy channel)", "godot", false, false, {"emission"}, "anisotropy");
        // The film's: glTF's one texture (strength R, thickness G, linear) and HDRP's Iridescence
        // Mask (its thickness map only for a thickness texture); Unreal has no film channel.
        row("gltf-textures, iridescence", "gltf-textures", false, false,
            {"emissive", "clearcoat", "clearcoatNormal", "sheen", "specular", "anisotropy"}, "iridescence");
        row("unity-hdrp, iridescence", "unity-hdrp", false, false,
            {"Emissive", "CoatMask", "AnisotropyMap", "TangentMap", "IridescenceThickness"}, "iridescence");
        row("unreal, iridescence (no film channel)", "unreal", false, false, {"E", "CC", "ANI"}, "iridescence");
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
        if (lobe == QLatin1String("iridescence"))
            plain.setIridescence(0.7, 1.5, 200.0, 500.0);
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
        if (lobe == QLatin1String("anisotropy") || lobe == QLatin1String("iridescence")) {
            // The anisotropy's direction turned 60 degrees, (0.5, 0.866) x 0.5 + 0.5, and its
            // strength 0.6; the film's strength 0.7 and, without a thickness texture, its maximum (1);
            // all linear, per template.
            const double x = 0.5 * 0.5 + 0.5;
            const double y = std::sqrt(0.75) * 0.5 + 0.5;
            const std::map<QString, std::vector<std::pair<QString, std::vector<double>>>> expected = {
                {QStringLiteral("anisotropy gltf-textures"), {{QStringLiteral("Plain_anisotropy.png"), {x, y, 0.6}}}},
                {QStringLiteral("anisotropy unreal"), {{QStringLiteral("T_Plain_ANI.png"), {x, 1.0 - y, 0.6}}}},
                {QStringLiteral("anisotropy unity-hdrp"),
                    {{QStringLiteral("Plain_AnisotropyMap.png"), {0.6}},
                        {QStringLiteral("Plain_TangentMap.png"), {x, y, 0.5}}}},
                {QStringLiteral("iridescence gltf-textures"),
                    {{QStringLiteral("Plain_iridescence.png"), {0.7, 1.0, 0.0}}}},
                {QStringLiteral("iridescence unity-hdrp"), {{QStringLiteral("Plain_IridescenceMask.png"), {0.7}}}},
            };
            const auto files = expected.find(lobe + QLatin1Char(' ') + templateId);
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
};

QTEST_GUILESS_MAIN(TextureSetExportTest)
#include "TextureSetExportTest.moc"
