// The material value types: map slots and their names, validation, IOR/F0, texture sampling
// (wrap modes, filters, UV sets: core/shading/MaterialInputs' sampleTexture), the built-in presets
// against the LearnOpenGL / Real-Time Rendering F0 table, preset files, and punctual lights
// (KHR_lights_punctual validation, colour temperature).

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <set>

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include "TestSupport.h"
#include "core/gltf/GltfImport.h"
#include "core/image/Image.h"
#include "core/image/MapImage.h"
#include "core/material/Material.h"
#include "core/material/MaterialPresets.h"
#include "core/project/Light.h"
#include "core/shading/MaterialInputs.h"

using namespace facet;

namespace {
QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}
constexpr double kInf = std::numeric_limits<double>::infinity();

// The table (linear F0) the built-ins must reproduce: LearnOpenGL "PBR: Theory", after
// Real-Time Rendering. A scalar entry is a dielectric's F0, a vector one a metal's.
struct TableEntry {
    const char* id;
    glm::dvec3 f0;
    bool metal;
};
const TableEntry kF0Table[] = {
    {"water", glm::dvec3(0.02), false},
    {"plastic-low", glm::dvec3(0.03), false},
    {"plastic-high", glm::dvec3(0.05), false},
    {"glass-high", glm::dvec3(0.08), false},
    {"ruby", glm::dvec3(0.08), false},
    {"diamond", glm::dvec3(0.17), false},
    {"iron", {0.56, 0.57, 0.58}, true},
    {"copper", {0.95, 0.64, 0.54}, true},
    {"gold", {1.00, 0.71, 0.29}, true},
    {"aluminium", {0.91, 0.92, 0.92}, true},
    {"silver", {0.95, 0.93, 0.88}, true},
};

// A 4 x 2 half-float map whose texels hold their own column (R = x / 3) and row from the bottom
// (G: MapImage's row order, v = 0 at the bottom).
MapImage columnsAndRows()
{
    Image image(4, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x)
            image.at(x, y) = glm::vec4(float(x) / 3.0f, float(1 - y), 0.0f, 1.0f); // Image: top row first
    return MapImage::fromImage(image, MapLayout::Rgb, MapSampleType::Half);
}

bool contains(const std::string& text, const char* part)
{
    return text.find(part) != std::string::npos;
}
} // namespace

class MaterialTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void mapSlotNamesRoundTrip()
    {
        const char* const expected[] = {"baseColor", "normal", "metallic", "roughness", "occlusion",
            "emissive", "clearcoat", "clearcoatRoughness", "clearcoatNormal", "sheenColor", "sheenRoughness",
            "specular", "specularColor", "anisotropy", "iridescence", "iridescenceThickness"};
        static_assert(std::size(expected) == kAllMapSlots.size());
        int i = 0;
        for (MapSlot slot : kAllMapSlots) {
            QCOMPARE(toString(slot), expected[i]);
            QCOMPARE(mapSlotFromString(expected[i]), std::optional<MapSlot>(slot));
            ++i;
        }
        QCOMPARE(i, kMapSlotCount);
        QVERIFY(!mapSlotFromString("BaseColor"));
        QVERIFY(!mapSlotFromString(""));
        for (MapChannel channel :
            {MapChannel::Rgb, MapChannel::R, MapChannel::G, MapChannel::B, MapChannel::A})
            QCOMPARE(mapChannelFromString(toString(channel)), std::optional<MapChannel>(channel));
        QVERIFY(!mapChannelFromString("all"));
        for (ColorEncoding encoding : {ColorEncoding::SRGB, ColorEncoding::Linear})
            QCOMPARE(colorEncodingFromString(toString(encoding)), std::optional<ColorEncoding>(encoding));
        for (LightType type : {LightType::Directional, LightType::Point, LightType::Spot})
            QCOMPARE(lightTypeFromString(toString(type)), std::optional<LightType>(type));
        QCOMPARE(intensityUnit(LightType::Directional), "lx");
        QCOMPARE(intensityUnit(LightType::Spot), "cd");
    }

    void materialDefaults()
    {
        const Material m;
        std::string problem;
        QVERIFY2(m.validate(&problem), problem.c_str());
        // docs/architecture.md, "Textures": base colour sRGB, data maps linear.
        QCOMPARE(m.map(MapSlot::BaseColor).colorSpace, ColorEncoding::SRGB);
        for (MapSlot slot : {MapSlot::Normal, MapSlot::Metallic, MapSlot::Roughness, MapSlot::Occlusion})
            QCOMPARE(m.map(slot).colorSpace, ColorEncoding::Linear);
        // ORM packing by default: R occlusion, G roughness, B metallic.
        QCOMPARE(m.map(MapSlot::Occlusion).channel, MapChannel::R);
        QCOMPARE(m.map(MapSlot::Roughness).channel, MapChannel::G);
        QCOMPARE(m.map(MapSlot::Metallic).channel, MapChannel::B);
        // KHR_materials_clearcoat: no coat, its textures' channels the extension's (R strength,
        // G roughness), data; its slots unused while it is off.
        QVERIFY(!m.hasClearcoat());
        QCOMPARE(m.clearcoatRoughness(), 0.0);
        QCOMPARE(m.map(MapSlot::ClearcoatNormal).factor.x, 1.0);
        QCOMPARE(m.map(MapSlot::Clearcoat).channel, MapChannel::R);
        QCOMPARE(m.map(MapSlot::ClearcoatRoughness).channel, MapChannel::G);
        QCOMPARE(m.map(MapSlot::ClearcoatNormal).channel, MapChannel::Rgb);
        for (MapSlot slot : kAllMapSlots) {
            QCOMPARE(m.usesSlot(slot), lobeOf(slot) == MaterialLobe::Core);
            if (!isColorSlot(slot))
                QCOMPARE(m.map(slot).colorSpace, ColorEncoding::Linear);
        }
        // KHR_materials_sheen: no sheen; the colour sRGB RGB, the roughness the texture's alpha.
        QVERIFY(!m.hasSheen());
        QCOMPARE(m.sheenColor(), glm::dvec3(0.0));
        QCOMPARE(m.sheenRoughness(), 0.0);
        QCOMPARE(m.map(MapSlot::SheenColor).colorSpace, ColorEncoding::SRGB);
        QCOMPARE(m.map(MapSlot::SheenColor).channel, MapChannel::Rgb);
        QCOMPARE(m.map(MapSlot::SheenRoughness).channel, MapChannel::A);
        // KHR_materials_specular: the default layer (strength 1, white), which is "off"; the
        // strength the texture's alpha, the colour sRGB RGB.
        QVERIFY(!m.hasSpecular());
        QCOMPARE(m.specular(), 1.0);
        QCOMPARE(m.specularColor(), glm::dvec3(1.0));
        QCOMPARE(m.map(MapSlot::Specular).channel, MapChannel::A);
        QCOMPARE(m.map(MapSlot::SpecularColor).colorSpace, ColorEncoding::SRGB);
        QCOMPARE(m.map(MapSlot::SpecularColor).channel, MapChannel::Rgb);
        // Each lobe's slots count only while that lobe is on.
        Material coated = m;
        coated.setClearcoat(0.25, 0.5);
        Material sheened = m;
        sheened.setSheen(glm::dvec3(0.0, 0.0, 0.1), 0.0); // one component is enough
        QVERIFY(sheened.hasSheen());
        // The specular layer is on when any of its factors differs from the default, or a texture
        // modulates it (factor 1 times a texture is not 1).
        Material weaker = m;
        weaker.setSpecular(0.5, glm::dvec3(1.0));
        Material tinted = m;
        tinted.setSpecular(1.0, glm::dvec3(1.0, 1.0, 2.0));
        Material textured = m;
        textured.map(MapSlot::SpecularColor).path = "/textures/tint.png";
        for (const Material* on : {&weaker, &tinted, &textured})
            QVERIFY(on->hasSpecular());
        for (MapSlot slot : kAllMapSlots) {
            QCOMPARE(coated.usesSlot(slot),
                lobeOf(slot) == MaterialLobe::Core || lobeOf(slot) == MaterialLobe::Clearcoat);
            QCOMPARE(sheened.usesSlot(slot),
                lobeOf(slot) == MaterialLobe::Core || lobeOf(slot) == MaterialLobe::Sheen);
            QCOMPARE(weaker.usesSlot(slot),
                lobeOf(slot) == MaterialLobe::Core || lobeOf(slot) == MaterialLobe::Specular);
        }
        QCOMPARE(m.ior, 1.5);
        QCOMPARE(m.shading, ShadingModel {});
        for (MapSlot slot : kAllMapSlots)
            QVERIFY(!m.map(slot).hasTexture());
    }

    void f0AndIor()
    {
        QVERIFY(std::abs(f0FromIor(1.5) - 0.04) < 1e-12);
        QVERIFY(std::abs(iorFromF0(0.04) - 1.5) < 1e-12);
        QCOMPARE(f0FromIor(1.0), 0.0);
        for (double ior : {1.0, 1.33, 1.5, 2.42, 3.0})
            QVERIFY(std::abs(iorFromF0(f0FromIor(ior)) - ior) < 1e-9);
        Material m;
        m.ior = 1.33;
        QVERIFY(std::abs(m.dielectricF0() - 0.02006) < 1e-4);
    }

    void alphaIsRoughnessSquaredAndClamped()
    {
        Material m;
        m.setFactor(MapSlot::Roughness, 0.5);
        QCOMPARE(m.alpha(), 0.25);
        m.setFactor(MapSlot::Roughness, 0.0); // stored as given, clamped when shading
        QCOMPARE(m.roughness(), 0.0);
        QCOMPARE(m.alpha(), Material::kMinPerceptualRoughness * Material::kMinPerceptualRoughness);
        QCOMPARE(Material::kMinPerceptualRoughness, 0.045);
        m.setFactor(MapSlot::Roughness, 1.0);
        QCOMPARE(m.alpha(), 1.0);
    }

    void materialValidation()
    {
        struct Case {
            const char* field; // the start of the expected message
            std::function<void(Material&)> breakIt;
        };
        const Case cases[] = {
            {"roughness.factor", [](Material& m) { m.setFactor(MapSlot::Roughness, 1.5); }},
            {"roughness.factor", [](Material& m) { m.setFactor(MapSlot::Roughness, std::nan("")); }},
            {"metallic.factor", [](Material& m) { m.setFactor(MapSlot::Metallic, -0.1); }},
            {"metallic.factor", [](Material& m) { m.map(MapSlot::Metallic).factor.z = 0.5; }},
            {"baseColor.factor.g", [](Material& m) { m.map(MapSlot::BaseColor).factor.y = 1.2; }},
            {"normal.factor", [](Material& m) { m.setFactor(MapSlot::Normal, -1.0); }},
            {"ior", [](Material& m) { m.ior = 0.5; }},
            {"normal.channel", [](Material& m) { m.map(MapSlot::Normal).channel = MapChannel::R; }},
            {"occlusion.channel", [](Material& m) { m.map(MapSlot::Occlusion).channel = MapChannel::Rgb; }},
            {"baseColor.flipGreen", [](Material& m) { m.map(MapSlot::BaseColor).flipGreen = true; }},
            {"normal.invert", [](Material& m) { m.map(MapSlot::Normal).invert = true; }},
            {"roughness.uv.scale.v", [](Material& m) { m.map(MapSlot::Roughness).uv.scale.y = 0.0; }},
            {"baseColor.uv.rotationDegrees",
                [](Material& m) { m.map(MapSlot::BaseColor).uv.rotationDegrees = kInf; }},
            {"occlusion.texCoord", [](Material& m) { m.map(MapSlot::Occlusion).texCoord = 2; }},
            {"normal.texCoord", [](Material& m) { m.map(MapSlot::Normal).texCoord = -1; }},
            {"emissive.sampler.magFilter",
                [](Material& m) {
                    m.map(MapSlot::Emissive).sampler.magFilter = TextureFilter::LinearMipmapLinear;
                }},
            // KHR_materials_sheen's fields.
            {"sheenColor.factor.b", [](Material& m) { m.map(MapSlot::SheenColor).factor.z = 1.5; }},
            {"sheenColor.factor.a", [](Material& m) { m.map(MapSlot::SheenColor).factor.w = -1.0; }},
            {"sheenRoughness.factor", [](Material& m) { m.setFactor(MapSlot::SheenRoughness, 2.0); }},
            {"sheenRoughness.factor", [](Material& m) { m.map(MapSlot::SheenRoughness).factor.y = 0.5; }},
            {"sheenColor.channel", [](Material& m) { m.map(MapSlot::SheenColor).channel = MapChannel::A; }},
            {"sheenRoughness.channel",
                [](Material& m) { m.map(MapSlot::SheenRoughness).channel = MapChannel::Rgb; }},
            {"sheenColor.invert", [](Material& m) { m.map(MapSlot::SheenColor).invert = true; }},
            // KHR_materials_specular's fields: a colour above 1 is allowed up to 100.
            {"specular.factor", [](Material& m) { m.setFactor(MapSlot::Specular, 1.5); }},
            {"specularColor.factor.g", [](Material& m) { m.map(MapSlot::SpecularColor).factor.y = 100.5; }},
            {"specularColor.factor.r", [](Material& m) { m.map(MapSlot::SpecularColor).factor.x = -0.5; }},
            {"specularColor.factor.a", [](Material& m) { m.map(MapSlot::SpecularColor).factor.w = 2.0; }},
            {"specularColor.channel",
                [](Material& m) { m.map(MapSlot::SpecularColor).channel = MapChannel::R; }},
            {"specular.channel", [](Material& m) { m.map(MapSlot::Specular).channel = MapChannel::Rgb; }},
        };
        for (const Case& c : cases) {
            Material m;
            c.breakIt(m);
            std::string problem;
            QVERIFY2(!m.validate(&problem), c.field);
            QVERIFY2(problem.rfind(std::string(c.field) + ":", 0) == 0, problem.c_str());
        }
        // Allowed: a single channel of a greyscale texture as base colour, an inverted gloss map.
        Material m;
        m.map(MapSlot::BaseColor).channel = MapChannel::R;
        m.map(MapSlot::Roughness).invert = true;
        m.map(MapSlot::Normal).flipGreen = true;
        m.map(MapSlot::Occlusion).texCoord = 1;
        m.map(MapSlot::Occlusion).sampler = {TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat,
            TextureFilter::Nearest, TextureFilter::NearestMipmapLinear};
        std::string problem;
        QVERIFY2(m.validate(&problem), problem.c_str());
    }

    // sampleTexture against OpenGL 4.6's wrap table (section 8.14.2, table 8.20) on a 4 x 2 image
    // whose texels are their own column and row (R = x / 3, G = y): one row per wrap mode and
    // filter, at coordinates inside, on texel centres and edges, and beyond both ends.
    void samplingFollowsTheWrapTable_data()
    {
        QTest::addColumn<int>("wrap");
        QTest::addColumn<int>("filter");
        QTest::addColumn<double>("u");
        QTest::addColumn<double>("expectedColumn"); // the (interpolated) column read
        const int repeat = int(TextureWrap::Repeat), clamp = int(TextureWrap::ClampToEdge),
                  mirror = int(TextureWrap::MirroredRepeat);
        const int nearest = int(TextureFilter::Nearest), linear = int(TextureFilter::Auto);
        // Nearest: column floor(4u), wrapped.
        QTest::newRow("repeat-nearest-inside") << repeat << nearest << 0.30 << 1.0;
        QTest::newRow("repeat-nearest-beyond-1") << repeat << nearest << 1.30 << 1.0;
        QTest::newRow("repeat-nearest-below-0") << repeat << nearest << -0.10 << 3.0;
        QTest::newRow("repeat-nearest-far") << repeat << nearest << 1.0e6 + 0.6 << 2.0;
        QTest::newRow("clamp-nearest-beyond-1") << clamp << nearest << 1.30 << 3.0;
        QTest::newRow("clamp-nearest-below-0") << clamp << nearest << -0.60 << 0.0;
        QTest::newRow("mirror-nearest-inside") << mirror << nearest << 0.60 << 2.0;
        QTest::newRow("mirror-nearest-beyond-1") << mirror << nearest << 1.10 << 3.0; // texel 4 -> 3
        QTest::newRow("mirror-nearest-beyond-1-far") << mirror << nearest << 1.90 << 0.0; // texel 7 -> 0
        QTest::newRow("mirror-nearest-below-0") << mirror << nearest << -0.10 << 0.0; // texel -1 -> 0
        QTest::newRow("mirror-nearest-below-minus-1") << mirror << nearest << -1.10 << 3.0; // texel -5 -> 3
        QTest::newRow("mirror-nearest-period-2") << mirror << nearest << 2.30 << 1.0;
        // Linear: between the two nearest centres, each wrapped.
        QTest::newRow("repeat-linear-centre") << repeat << linear << 0.375 << 1.0;
        QTest::newRow("repeat-linear-across-the-seam") << repeat << linear << 1.0 << 1.5; // 3 and 0, halfway
        QTest::newRow("clamp-linear-edge") << clamp << linear << 1.0 << 3.0;
        QTest::newRow("clamp-linear-below-0") << clamp << linear << -0.5 << 0.0;
        QTest::newRow("clamp-linear-inside") << clamp << linear << 0.5 << 1.5;
        QTest::newRow("mirror-linear-at-1") << mirror << linear << 1.0 << 3.0; // 3 and its mirror 3
        QTest::newRow("mirror-linear-at-0") << mirror << linear << 0.0 << 0.0;
        QTest::newRow("mirror-linear-beyond-1") << mirror << linear << 1.25 << 2.5; // texels 4.5 -> 3, 2
    }
    void samplingFollowsTheWrapTable()
    {
        QFETCH(int, wrap);
        QFETCH(int, filter);
        QFETCH(double, u);
        QFETCH(double, expectedColumn);
        const MapImage image = columnsAndRows();
        TextureSampler sampler;
        sampler.wrapS = TextureWrap(wrap);
        sampler.wrapT = TextureWrap::ClampToEdge;
        sampler.magFilter = TextureFilter(filter);
        // v at row 0's centre, so only u moves.
        const glm::dvec4 texel = sampleTexture(image, ColorEncoding::Linear, {u, 0.25}, sampler);
        QVERIFY2(std::abs(texel.r * 3.0 - expectedColumn) < 1e-3,
            qPrintable(QStringLiteral("column %1, expected %2").arg(texel.r * 3.0).arg(expectedColumn)));
        QVERIFY2(std::abs(texel.g - 0.0) < 1e-6, qPrintable(QStringLiteral("row %1").arg(texel.g)));
    }

    // The wrap of one axis does not leak into the other, and a map reads its own UV set.
    void samplingAxesAndSetsAreIndependent()
    {
        const MapImage image = columnsAndRows();
        TextureSampler sampler {
            TextureWrap::Repeat, TextureWrap::ClampToEdge, TextureFilter::Nearest, TextureFilter::Auto};
        // u 1.3 repeats to column 1; v 1.7 clamps to the top row (row 1).
        glm::dvec4 texel = sampleTexture(image, ColorEncoding::Linear, {1.3, 1.7}, sampler);
        QCOMPARE(std::lround(texel.r * 3.0), 1L);
        QCOMPARE(texel.g, 1.0);
        std::swap(sampler.wrapS, sampler.wrapT);
        texel = sampleTexture(image, ColorEncoding::Linear, {1.3, 1.7}, sampler);
        QCOMPARE(std::lround(texel.r * 3.0), 3L); // clamped
        QCOMPARE(texel.g, 1.0); // 1.7 * 2 = texel 3 -> repeat -> row 1

        MaterialMap map;
        map.path = "x.png";
        map.colorSpace = ColorEncoding::Linear;
        map.sampler.magFilter = TextureFilter::Nearest;
        const TexCoords uvs = {glm::dvec2(0.1, 0.25), glm::dvec2(0.9, 0.25)};
        QCOMPARE(std::lround(sampleMap(map, image, uvs).r * 3.0), 0L);
        map.texCoord = 1;
        QCOMPARE(std::lround(sampleMap(map, image, uvs).r * 3.0), 3L);
    }

    // Names in files and glTF's numbers, both ways, for every value.
    void samplerNamesAndGltfNumbersRoundTrip()
    {
        for (TextureWrap wrap :
            {TextureWrap::Repeat, TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat}) {
            QCOMPARE(textureWrapFromString(toString(wrap)), std::optional<TextureWrap>(wrap));
            TextureSampler sampler;
            sampler.wrapS = sampler.wrapT = wrap;
            const std::array<int, 4> numbers = gltfSamplerValues(sampler);
            QCOMPARE(textureSamplerFromGltf(numbers[0], numbers[1], numbers[2], numbers[3]).wrapS, wrap);
        }
        QCOMPARE(gltfSamplerValues(TextureSampler {})[2], 10497);
        QCOMPARE(gltfSamplerValues({TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat,
                     TextureFilter::Auto, TextureFilter::Auto}),
            (std::array<int, 4> {-1, -1, 33071, 33648})); // Auto filters are left out of the file
        for (TextureFilter filter : {TextureFilter::Auto, TextureFilter::Nearest, TextureFilter::Linear,
                 TextureFilter::NearestMipmapNearest, TextureFilter::LinearMipmapNearest,
                 TextureFilter::NearestMipmapLinear, TextureFilter::LinearMipmapLinear}) {
            QCOMPARE(textureFilterFromString(toString(filter)), std::optional<TextureFilter>(filter));
            if (filter == TextureFilter::Auto)
                continue;
            TextureSampler sampler;
            sampler.minFilter = filter;
            const std::array<int, 4> numbers = gltfSamplerValues(sampler);
            QCOMPARE(
                textureSamplerFromGltf(numbers[0], numbers[1], numbers[2], numbers[3]).minFilter, filter);
        }
        // Absent (-1) and unknown numbers: Auto filters, repeat; a minification value given as
        // the magnification filter is ignored.
        QVERIFY(textureSamplerFromGltf(-1, -1, 10497, 10497).isDefault());
        QVERIFY(textureSamplerFromGltf(12345, 9729 + 1000, 1, 2).isDefault());
        QCOMPARE(textureSamplerFromGltf(9987, -1, 10497, 10497).magFilter, TextureFilter::Auto);
        QVERIFY(!textureWrapFromString("clamp"));
        QVERIFY(!textureFilterFromString("trilinear"));
    }

    void uvTransformFollowsKhrTextureTransform()
    {
        UvTransform uv;
        QVERIFY(uv.isIdentity());
        QCOMPARE(uv.apply({0.25, 0.75}), glm::dvec2(0.25, 0.75));
        uv.scale = {2.0, 3.0};
        uv.offset = {0.5, -0.25};
        QVERIFY(!uv.isIdentity());
        // Scale first, then offset.
        const glm::dvec2 p = uv.apply({1.0, 1.0});
        QVERIFY(std::abs(p.x - 2.5) < 1e-12 && std::abs(p.y - 2.75) < 1e-12);
        // KHR_texture_transform's rotation matrix maps (1, 0) to (cos r, sin r).
        UvTransform rotation;
        rotation.rotationDegrees = 90.0;
        const glm::dvec2 q = rotation.apply({1.0, 0.0});
        QVERIFY2(std::abs(q.x) < 1e-12 && std::abs(q.y - 1.0) < 1e-12,
            qPrintable(QStringLiteral("%1 %2").arg(q.x).arg(q.y)));
    }

    void presetIdsAreUniqueAndValid()
    {
        const std::vector<MaterialPreset>& presets = builtinPresets();
        QVERIFY(presets.size() >= 15);
        std::set<std::string> ids;
        for (const MaterialPreset& preset : presets) {
            QVERIFY2(isValidPresetId(preset.id), preset.id.c_str());
            QVERIFY2(ids.insert(preset.id).second, ("duplicate id " + preset.id).c_str());
            QVERIFY(!preset.displayName.empty());
            QCOMPARE(preset.material.name, preset.displayName);
            std::string problem;
            QVERIFY2(preset.material.validate(&problem), (preset.id + ": " + problem).c_str());
            QCOMPARE(findPreset(preset.id), &preset);
        }
        QVERIFY(findPreset("unobtainium") == nullptr);
        QVERIFY(findPreset("") == nullptr);
        QVERIFY(!isValidPresetId("Gold"));
        QVERIFY(!isValidPresetId("9lives"));
        QVERIFY(!isValidPresetId("car paint"));
        for (const char* id : {"rubber", "painted-white", "ceramic-glossy", "car-paint-red"})
            QVERIFY2(findPreset(id) != nullptr, id);
    }

    void presetsReproduceTheF0Table()
    {
        for (const TableEntry& entry : kF0Table) {
            const MaterialPreset* preset = findPreset(entry.id);
            QVERIFY2(preset, entry.id);
            const Material& m = preset->material;
            if (entry.metal) {
                QCOMPARE(m.metallic(), 1.0);
                // A metal's F0 is its base colour (glTF 2.0).
                for (int i = 0; i < 3; ++i)
                    QVERIFY2(std::abs(m.baseColorFactor()[i] - entry.f0[i]) < 1e-12, entry.id);
            } else {
                QCOMPARE(m.metallic(), 0.0);
                QVERIFY2(std::abs(f0FromIor(m.ior) - entry.f0.x) < 1e-3, entry.id);
                QVERIFY2(std::abs(m.dielectricF0() - entry.f0.x) < 1e-9, entry.id);
            }
        }
        // The textbook IORs follow from the table: water ~1.33, diamond ~2.4.
        QVERIFY(std::abs(findPreset("water")->material.ior - 1.33) < 0.01);
        QVERIFY(std::abs(findPreset("diamond")->material.ior - 2.42) < 0.03);
        QVERIFY(std::abs(findPreset("rubber")->material.ior - 1.5) < 1e-12);
        QVERIFY(findPreset("rubber")->material.roughness() > 0.7);
    }

    void presetJsonRoundTrip()
    {
        for (const MaterialPreset& preset : builtinPresets()) {
            std::string error;
            const std::optional<MaterialPreset> back = presetFromJson(presetToJson(preset), {}, &error);
            QVERIFY2(back, error.c_str());
            QVERIFY2(*back == preset, preset.id.c_str());
        }
    }

    void presetFileRoundTrip()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        MaterialPreset preset = *findPreset("copper");
        preset.id = "my-copper";
        preset.displayName = "My copper";
        preset.material.shading = ShadingModel::learnOpenGL();
        preset.material.map(MapSlot::Roughness).path
            = QDir(dir.path()).filePath(QStringLiteral("tex/rough.png")).toStdString();
        preset.material.map(MapSlot::Roughness).invert = true;
        preset.material.map(MapSlot::Roughness).uv.scale = {4.0, 4.0};

        // Without texture paths (the default): everything else survives.
        const std::string path = QDir(dir.path()).filePath(QStringLiteral("my-copper.json")).toStdString();
        std::string error;
        QVERIFY2(savePreset(preset, path, &error), error.c_str());
        QFile file(qs(path));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray text = file.readAll();
        file.close();
        QVERIFY(text.contains("facet-material-preset"));
        QVERIFY(!text.contains("rough.png"));
        std::optional<MaterialPreset> loaded = loadPreset(path, &error);
        QVERIFY2(loaded, error.c_str());
        MaterialPreset expected = preset;
        expected.material.map(MapSlot::Roughness).path.clear();
        QVERIFY(*loaded == expected);

        // With texture paths: stored relative to the preset file, resolved back on load.
        QVERIFY2(savePreset(preset, path, &error, true), error.c_str());
        QVERIFY(file.open(QIODevice::ReadOnly));
        QVERIFY(file.readAll().contains("\"tex/rough.png\""));
        file.close();
        loaded = loadPreset(path, &error);
        QVERIFY2(loaded, error.c_str());
        QVERIFY(*loaded == preset);
    }

    void presetFileErrors()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const auto write = [&](const char* name, const QByteArray& content) {
            const QString path = QDir(dir.path()).filePath(QLatin1String(name));
            QFile file(path);
            if (!file.open(QIODevice::WriteOnly))
                return std::string();
            file.write(content);
            return path.toStdString();
        };
        struct Case {
            const char* file;
            QByteArray content;
            const char* expected;
        };
        const Case cases[] = {
            {"project.json", R"({"format": "facet-project", "version": 1})", "format: \"facet-project\""},
            {"newer.json", R"({"format": "facet-material-preset", "version": 2, "id": "x", "material": {}})",
                "written by a newer Facet (version 2)"},
            {"badid.json",
                R"({"format": "facet-material-preset", "version": 1, "id": "Bad Id", "material": {}})",
                "id: \"Bad Id\""},
            {"noid.json", R"({"format": "facet-material-preset", "version": 1, "material": {}})",
                "\"id\" is missing"},
            {"badrough.json",
                R"({"format": "facet-material-preset", "version": 1, "id": "x",)"
                R"( "material": {"roughness": {"factor": "high"}}})",
                "material.roughness.factor: expected a number, got a string"},
            {"broken.json", "{\"format\": ", "line 1, column"},
        };
        for (const Case& c : cases) {
            const std::string path = write(c.file, c.content);
            QVERIFY(!path.empty());
            std::string error;
            QVERIFY2(!loadPreset(path, &error), c.file);
            QVERIFY2(
                contains(error, "loadPreset: ") && contains(error, c.file) && contains(error, c.expected),
                error.c_str());
        }
        std::string error;
        QVERIFY(!loadPreset(QDir(dir.path()).filePath(QStringLiteral("absent.json")).toStdString(), &error));
        QVERIFY2(contains(error, "absent.json: no such file"), error.c_str());

        MaterialPreset invalid = *findPreset("gold");
        invalid.material.setFactor(MapSlot::Roughness, 2.0);
        const std::string target = QDir(dir.path()).filePath(QStringLiteral("invalid.json")).toStdString();
        QVERIFY(!savePreset(invalid, target, &error));
        QVERIFY2(contains(error, "material.roughness.factor"), error.c_str());
        QVERIFY(!QFile::exists(qs(target)));
    }

    void kelvinColours()
    {
        // 6504 K on the Planckian locus is within a few percent of D65 white.
        const glm::dvec3 white = colorFromKelvin(6504.0);
        for (int i = 0; i < 3; ++i)
            QVERIFY2(white[i] > 0.9 && white[i] <= 1.0, qPrintable(QString::number(white[i])));
        // Warm light: red > green > blue, normalised to max 1.
        const glm::dvec3 warm = colorFromKelvin(2700.0);
        QVERIFY(warm.x > warm.y && warm.y > warm.z);
        QCOMPARE(warm.x, 1.0);
        QVERIFY(warm.z < 0.6);
        // Cool light: blue dominates.
        const glm::dvec3 cool = colorFromKelvin(10000.0);
        QVERIFY(cool.z > cool.y && cool.y > cool.x);
        QCOMPARE(cool.z, 1.0);
        // Blue/red grows with temperature across the whole range, and every value is in [0, 1].
        double lastRatio = -1.0;
        for (double k = kMinKelvin; k <= kMaxKelvin; k += 250.0) {
            const glm::dvec3 c = colorFromKelvin(k);
            for (int i = 0; i < 3; ++i)
                QVERIFY(std::isfinite(c[i]) && c[i] >= 0.0 && c[i] <= 1.0);
            QVERIFY(std::max({c.x, c.y, c.z}) == 1.0);
            const double ratio = c.z / c.x;
            QVERIFY2(ratio > lastRatio, qPrintable(QString::number(k)));
            lastRatio = ratio;
        }
        // Outside the fit's range the input is clamped, not extrapolated; NaN gives white-ish.
        QCOMPARE(colorFromKelvin(100.0), colorFromKelvin(kMinKelvin));
        QCOMPARE(colorFromKelvin(1e6), colorFromKelvin(kMaxKelvin));
        const glm::dvec3 nan = colorFromKelvin(std::nan(""));
        QVERIFY(std::isfinite(nan.x) && std::isfinite(nan.y) && std::isfinite(nan.z));

        Light light;
        light.color = {0.2, 0.4, 0.6};
        QCOMPARE(light.linearColor(), light.color);
        light.useTemperature = true;
        light.kelvin = 2700.0;
        QCOMPARE(light.linearColor(), warm);
    }

    void lightValidation()
    {
        std::string problem;
        Light light;
        QVERIFY2(light.validate(&problem), problem.c_str());
        QVERIFY2(Light::defaultDirectional().validate(&problem), problem.c_str());
        light.type = LightType::Spot;
        light.innerConeAngle = 0.2;
        light.outerConeAngle = std::numbers::pi / 2.0; // the limit itself is allowed
        QVERIFY2(light.validate(&problem), problem.c_str());
        light.intensity = 0.0; // a switched-off light is valid
        QVERIFY2(light.validate(&problem), problem.c_str());

        struct Case {
            const char* field;
            std::function<void(Light&)> breakIt;
        };
        const Case cases[] = {
            {"intensity", [](Light& l) { l.intensity = -1.0; }},
            {"intensity", [](Light& l) { l.intensity = std::nan(""); }},
            {"innerConeAngle", [](Light& l) { l.innerConeAngle = l.outerConeAngle; }},
            {"innerConeAngle",
                [](Light& l) {
                    l.innerConeAngle = 1.0;
                    l.outerConeAngle = 0.5;
                }},
            {"innerConeAngle", [](Light& l) { l.innerConeAngle = -0.1; }},
            {"outerConeAngle", [](Light& l) { l.outerConeAngle = std::numbers::pi / 2.0 + 1e-6; }},
            {"range", [](Light& l) { l.range = -1.0; }},
            {"color",
                [](Light& l) {
                    l.color = {1.5, 1.0, 1.0};
                }},
            {"kelvin", [](Light& l) { l.kelvin = 500.0; }},
            {"direction", [](Light& l) { l.direction = glm::dvec3(0.0); }},
            {"position", [](Light& l) { l.position.y = kInf; }},
        };
        for (const Case& c : cases) {
            Light broken = light;
            c.breakIt(broken);
            QVERIFY2(!broken.validate(&problem), c.field);
            QVERIFY2(problem.rfind(std::string(c.field) + ":", 0) == 0, problem.c_str());
        }
    }

    void lightDefaultsFollowKhr()
    {
        const Light light;
        QCOMPARE(light.innerConeAngle, 0.0);
        QCOMPARE(light.outerConeAngle, std::numbers::pi / 4.0);
        QCOMPARE(light.range, 0.0);
        QCOMPARE(light.intensity, 1.0);
        QCOMPARE(light.color, glm::dvec3(1.0));
        QCOMPARE(light.direction, glm::dvec3(0.0, 0.0, -1.0));
    }
};

QTEST_GUILESS_MAIN(MaterialTest)
#include "MaterialTest.moc"
