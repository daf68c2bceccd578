// Surface shader variants (render/ShaderVariant): which defines a material and scene ask for,
// which maps are sampled at all, which scalar slots share one fetch, and that those variants
// compile. The rendered values of the same variants are checked against the CPU twin in
// MaterialMapsGLTest.
#include <epoxy/gl.h>

#include "core/image/MapImage.h"
#include "core/material/Material.h"
#include "core/material/MaterialProperties.h"
#include "render/HeadlessGLContext.h"
#include "render/ShaderProgram.h"
#include "render/ShaderVariant.h"

#include "TestSupport.h"

#include <QtTest/QTest>

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

using namespace facet;

class ShaderVariantGLTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { facet::test::forgetDisplayServer(); }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void variantDefines();
    void irrelevantMapsAreNotSampled_data();
    void irrelevantMapsAreNotSampled();
    void sharedTexels_data();
    void sharedTexels();
    void lobesOnlyWhereTheMaterialHasThem_data();
    void lobesOnlyWhereTheMaterialHasThem();
    void packedLobeTexture_data();
    void packedLobeTexture();

private:
    std::optional<HeadlessGLContext> m_context; // sharedTexels compiles its variants
};

void ShaderVariantGLTest::initTestCase()
{
    std::string error;
    m_context = HeadlessGLContext::create(&error);
    QVERIFY2(m_context, error.c_str());
}

void ShaderVariantGLTest::cleanupTestCase()
{
    m_context.reset();
}

void ShaderVariantGLTest::variantDefines()
{
    Material material; // constant inputs
    const bool noImages[kMapSlotCount] = {};
    SurfaceFeatures features = surfaceFeaturesFor(material, noImages, false, false);
    SurfaceVariantKey key {features, DebugView::None};
    std::vector<std::string> defines = surfaceDefines(key);
    auto has = [&defines](const std::string& name) {
        return std::find(defines.begin(), defines.end(), name) != defines.end();
    };
    // Default model: glTF, GGX, correlated Smith, Schlick, fresnel_mix, multi-scatter on.
    QVERIFY(has("MULTI_SCATTER"));
    for (const char* absent : {"HAS_BASE_COLOR_MAP", "HAS_NORMAL_MAP", "HAS_METALLIC_MAP",
             "HAS_ROUGHNESS_MAP", "HAS_OCCLUSION_MAP", "HAS_PUNCTUAL_LIGHTS", "COMPOSITION_LEARNOPENGL",
             "DISTRIBUTION_BECKMANN", "VISIBILITY_SCHLICK", "IRRADIANCE_SH"})
        QVERIFY2(!has(absent), absent);
    QVERIFY(has("DEBUG_VIEW 0"));
    // Every debug view's id, named from core/shading/DebugView's table.
    QCOMPARE(debugViewDefine(DebugView::BaseColor), std::string("DEBUG_BASE_COLOR"));
    QCOMPARE(debugViewDefine(DebugView::TexelDensity), std::string("DEBUG_TEXEL_DENSITY"));
    for (int view = 0; view < kDebugViewCount; ++view)
        QVERIFY2(
            has(debugViewDefine(DebugView(view)) + ' ' + std::to_string(view)), toString(DebugView(view)));
    QVERIFY(has("DEBUG_WHITE_FURNACE 17") && has("DEBUG_DISTRIBUTION 7"));

    // A texture path without an image is still constant (nothing to sample).
    material.map(MapSlot::Normal).path = "/x/normal.png";
    QVERIFY(!hasFeature(surfaceFeaturesFor(material, noImages, false, false), SurfaceFeature::HasNormalMap));
    const bool normalImage[kMapSlotCount] = {false, true, false, false, false};
    material.shading = ShadingModel::learnOpenGL();
    features = surfaceFeaturesFor(material, normalImage, true, true);
    key = {features, DebugView::WhiteFurnace};
    defines = surfaceDefines(key);
    for (const char* present : {"HAS_NORMAL_MAP", "HAS_PUNCTUAL_LIGHTS", "IRRADIANCE_SH",
             "COMPOSITION_LEARNOPENGL", "VISIBILITY_SCHLICK", "MULTI_SCATTER", "DEBUG_VIEW 17"})
        QVERIFY2(has(present), present);
    QVERIFY(!has("HAS_BASE_COLOR_MAP"));
    QCOMPARE(debugViewFromString("white-furnace").value(), DebugView::WhiteFurnace);
    QCOMPARE(std::string(toString(DebugView::BaseColor)), std::string("base-color"));
    QVERIFY(!debugViewFromString("bogus"));
}

void ShaderVariantGLTest::irrelevantMapsAreNotSampled_data()
{
    // Every slot has a texture; one factor changes; which slots sample their texture.
    QTest::addColumn<int>("slot");
    QTest::addColumn<double>("factor");
    QTest::addColumn<bool>("sampled");
    const auto row = [](const char* name, MapSlot slot, double factor, bool sampled) {
        QTest::newRow(name) << int(slot) << factor << sampled;
    };
    row("metallic 0", MapSlot::Metallic, 0.0, false);
    row("metallic 0.5", MapSlot::Metallic, 0.5, true);
    row("roughness 0", MapSlot::Roughness, 0.0, false);
    row("roughness 1", MapSlot::Roughness, 1.0, true);
    row("occlusion strength 0", MapSlot::Occlusion, 0.0, false);
    row("occlusion strength 0.3", MapSlot::Occlusion, 0.3, true);
    row("normal strength 0", MapSlot::Normal, 0.0, false);
    row("normal strength 2", MapSlot::Normal, 2.0, true);
    row("emissive black", MapSlot::Emissive, 0.0, false);
    row("emissive 0.1", MapSlot::Emissive, 0.1, true);
    row("base colour black (alpha still read)", MapSlot::BaseColor, 0.0, true);
}

void ShaderVariantGLTest::irrelevantMapsAreNotSampled()
{
    QFETCH(int, slot);
    QFETCH(double, factor);
    QFETCH(bool, sampled);
    Material material;
    bool hasImage[kMapSlotCount] = {};
    for (MapSlot s : kAllMapSlots) {
        material.map(s).path = std::string("/t/") + toString(s) + ".png";
        material.map(s).factor = glm::dvec4(1.0);
        hasImage[int(s)] = true;
    }
    if (MapSlot(slot) == MapSlot::Emissive)
        material.map(MapSlot::Emissive).factor = glm::dvec4(factor, factor, factor, 1.0);
    else if (MapSlot(slot) == MapSlot::BaseColor)
        material.setBaseColor(glm::dvec3(factor));
    else
        material.setFactor(MapSlot(slot), factor);
    const SurfaceFeatures features = surfaceFeaturesFor(material, hasImage, false, false);
    for (MapSlot s : kAllMapSlots)
        QCOMPARE(hasFeature(features, mapFeature(s)), s == MapSlot(slot) ? sampled : true);
    if (!sampled && MapSlot(slot) == MapSlot::Normal)
        QVERIFY(!hasFeature(features, SurfaceFeature::HasNormalMap)); // no tangent frame either
}

void ShaderVariantGLTest::sharedTexels_data()
{
    // Which scalar slots read one texture (a letter per slot: metallic, roughness, occlusion;
    // equal letters are one decoded file, '-' no map), a change that keeps two apart, and the
    // fetches the variant shares.
    QTest::addColumn<QString>("files");
    QTest::addColumn<QString>("change");
    QTest::addColumn<SurfaceFeatures>("expected");
    using F = SurfaceFeature;
    const SurfaceFeatures none = 0;
    QTest::newRow("three files") << "abc" << "" << none;
    QTest::newRow("metallic-roughness packed") << "aab" << "" << SurfaceFeatures(F::RoughnessTexelFromMetallic);
    QTest::newRow("ORM packed") << "aaa" << "" << (F::RoughnessTexelFromMetallic | F::OcclusionTexelFromMetallic);
    QTest::newRow("metallic-occlusion packed") << "aba" << "" << SurfaceFeatures(F::OcclusionTexelFromMetallic);
    QTest::newRow("roughness-occlusion packed") << "abb" << "" << SurfaceFeatures(F::OcclusionTexelFromRoughness);
    QTest::newRow("roughness-occlusion, no metallic") << "-bb" << "" << SurfaceFeatures(F::OcclusionTexelFromRoughness);
    QTest::newRow("ORM, roughness UV offset") << "aaa" << "roughness-uv" << SurfaceFeatures(F::OcclusionTexelFromMetallic);
    QTest::newRow("ORM, occlusion sRGB") << "aaa" << "occlusion-srgb" << SurfaceFeatures(F::RoughnessTexelFromMetallic);
    QTest::newRow("ORM, metallic path without image") << "aaa" << "metallic-no-image"
                                                     << SurfaceFeatures(F::OcclusionTexelFromRoughness);
}

void ShaderVariantGLTest::sharedTexels()
{
    QFETCH(QString, files);
    QFETCH(QString, change);
    QFETCH(SurfaceFeatures, expected);
    const MapSlot slots[3] = {MapSlot::Metallic, MapSlot::Roughness, MapSlot::Occlusion};
    std::map<QChar, std::shared_ptr<const MapImage>> images;
    Material material;
    material.setFactor(MapSlot::Metallic, 1.0); // a map at factor 0 is not sampled at all
    bool hasImage[kMapSlotCount] = {};
    std::array<const void*, kMapSlotCount> textures {};
    for (int i = 0; i < 3; ++i) {
        if (files[i] == QLatin1Char('-'))
            continue;
        auto& image = images[files[i]];
        if (!image)
            image = std::make_shared<const MapImage>(4, 4, MapLayout::Rgb, MapSampleType::UInt8);
        const auto slot = std::size_t(slots[i]);
        material.maps[slot].path = "/t/" + QString(files[i]).toStdString() + ".png";
        hasImage[slot] = true;
        textures[slot] = image.get();
    }
    if (change == QLatin1String("roughness-uv"))
        material.map(MapSlot::Roughness).uv.offset = {0.5, 0.0};
    if (change == QLatin1String("occlusion-srgb"))
        material.map(MapSlot::Occlusion).colorSpace = ColorEncoding::SRGB;
    if (change == QLatin1String("metallic-no-image")) {
        hasImage[std::size_t(MapSlot::Metallic)] = false;
        textures[std::size_t(MapSlot::Metallic)] = nullptr;
    }
    const SurfaceFeatures features = surfaceFeaturesFor(material, hasImage, false, false);
    const SurfaceFeatures shared = sharedTexelFeatures(material, features, textures);
    QCOMPARE(shared, expected);
    // A slot that reuses a texel binds and declares no sampler of its own; the program compiles.
    const SurfaceFeatures all = features | shared;
    for (int i = 0; i < 3; ++i)
        QCOMPARE(samplesOwnTexture(all, slots[i]),
            files[i] != QLatin1Char('-') && hasImage[std::size_t(slots[i])]
                && !(slots[i] == MapSlot::Roughness && hasFeature(shared, SurfaceFeature::RoughnessTexelFromMetallic))
                && !(slots[i] == MapSlot::Occlusion
                    && (hasFeature(shared, SurfaceFeature::OcclusionTexelFromMetallic)
                        || hasFeature(shared, SurfaceFeature::OcclusionTexelFromRoughness))));
    SurfaceProgramCache programs;
    std::string error;
    QVERIFY2(programs.get(SurfaceVariantKey {all, DebugView::None}, &error), error.c_str());
}

// "Skip what a scene doesn't need": a lobe's bit, and with it the lobe's code and uniforms, only
// where the material has the lobe on (a row per lobe and per way of being off).
void ShaderVariantGLTest::lobesOnlyWhereTheMaterialHasThem_data()
{
    QTest::addColumn<QString>("property"); // the registry's name of the lobe's strength
    QTest::addColumn<double>("value");
    QTest::addColumn<bool>("unlit");
    QTest::addColumn<int>("mapSlot"); // a lobe's map with an image, or -1
    QTest::addColumn<double>(
        "lobeRoughness"); // the coat's and the sheen's roughness factors (0 hides their maps)
    QTest::addColumn<SurfaceFeatures>("bit");
    QTest::addColumn<bool>("on");
    QTest::addColumn<QString>("uniform"); // a uniform only the lobe's code declares
    const auto row = [](const char* name, const char* property, double value, bool unlit, int mapSlot,
                         double coatRoughness, SurfaceFeature bit, bool on, const char* uniform) {
        QTest::newRow(name) << QString::fromLatin1(property) << value << unlit << mapSlot << coatRoughness
                            << SurfaceFeatures(bit) << on << QString::fromLatin1(uniform);
    };
    const int none = -1;
    row("clearcoat 0 (default)", "clearcoat", 0.0, false, none, 0.0, SurfaceFeature::Clearcoat, false,
        "uClearcoatFactor");
    row("clearcoat 0.5", "clearcoat", 0.5, false, none, 0.0, SurfaceFeature::Clearcoat, true,
        "uClearcoatFactor");
    row("clearcoat 1, unlit", "clearcoat", 1.0, true, none, 0.0, SurfaceFeature::Clearcoat, false,
        "uClearcoatFactor");
    // The coat's maps: sampled only with the coat on, lit, and a factor that lets them show.
    const int coat = int(MapSlot::Clearcoat);
    const int coatRoughness = int(MapSlot::ClearcoatRoughness);
    const int coatNormal = int(MapSlot::ClearcoatNormal);
    row("clearcoat map, coat 0", "clearcoat", 0.0, false, coat, 0.0, SurfaceFeature::HasClearcoatMap, false,
        "uClearcoatMap");
    row("clearcoat map, coat 0.5", "clearcoat", 0.5, false, coat, 0.0, SurfaceFeature::HasClearcoatMap, true,
        "uClearcoatMap");
    row("clearcoat map, unlit", "clearcoat", 0.5, true, coat, 0.0, SurfaceFeature::HasClearcoatMap, false,
        "uClearcoatMap");
    row("clearcoat roughness map, roughness factor 0", "clearcoat", 1.0, false, coatRoughness, 0.0,
        SurfaceFeature::HasClearcoatRoughnessMap, false, "uClearcoatRoughnessMap");
    row("clearcoat roughness map, roughness factor 0.5", "clearcoat", 1.0, false, coatRoughness, 0.5,
        SurfaceFeature::HasClearcoatRoughnessMap, true, "uClearcoatRoughnessMap");
    row("clearcoat normal map, coat 0", "clearcoat", 0.0, false, coatNormal, 0.0,
        SurfaceFeature::HasClearcoatNormalMap, false, "uClearcoatNormalMap");
    row("clearcoat normal map, coat 1", "clearcoat", 1.0, false, coatNormal, 0.0,
        SurfaceFeature::HasClearcoatNormalMap, true, "uClearcoatNormalMap");
    // The sheen: on while its colour is not black (the value sets all three components).
    row("sheen black (default)", "sheenColor", 0.0, false, none, 0.0, SurfaceFeature::Sheen, false,
        "uSheenColorFactor");
    row("sheen 0.5", "sheenColor", 0.5, false, none, 0.0, SurfaceFeature::Sheen, true, "uSheenColorFactor");
    row("sheen 0.5, its table", "sheenColor", 0.5, false, none, 0.0, SurfaceFeature::Sheen, true,
        "uSheenLut");
    row("sheen black, no table", "sheenColor", 0.0, false, none, 0.0, SurfaceFeature::Sheen, false,
        "uSheenLut");
    row("sheen 1, unlit", "sheenColor", 1.0, true, none, 0.0, SurfaceFeature::Sheen, false,
        "uSheenColorFactor");
    const int sheenColor = int(MapSlot::SheenColor);
    const int sheenRoughness = int(MapSlot::SheenRoughness);
    row("sheen colour map, sheen black", "sheenColor", 0.0, false, sheenColor, 0.0,
        SurfaceFeature::HasSheenColorMap, false, "uSheenColorMap");
    row("sheen colour map, sheen 0.5", "sheenColor", 0.5, false, sheenColor, 0.0,
        SurfaceFeature::HasSheenColorMap, true, "uSheenColorMap");
    row("sheen colour map, unlit", "sheenColor", 0.5, true, sheenColor, 0.0, SurfaceFeature::HasSheenColorMap,
        false, "uSheenColorMap");
    row("sheen roughness map, roughness factor 0", "sheenColor", 1.0, false, sheenRoughness, 0.0,
        SurfaceFeature::HasSheenRoughnessMap, false, "uSheenRoughnessMap");
    row("sheen roughness map, roughness factor 0.5", "sheenColor", 1.0, false, sheenRoughness, 0.5,
        SurfaceFeature::HasSheenRoughnessMap, true, "uSheenRoughnessMap");
    // The specular layer: on while it is not the default (strength 1, white) or a map modulates it.
    row("specular 1 (default)", "specular", 1.0, false, none, 0.0, SurfaceFeature::Specular, false,
        "uSpecularFactor");
    row("specular 0.5", "specular", 0.5, false, none, 0.0, SurfaceFeature::Specular, true, "uSpecularFactor");
    row("specular 0", "specular", 0.0, false, none, 0.0, SurfaceFeature::Specular, true,
        "uSpecularColorFactor");
    row("specular 0.5, unlit", "specular", 0.5, true, none, 0.0, SurfaceFeature::Specular, false,
        "uSpecularFactor");
    row("specular colour 2", "specularColor", 2.0, false, none, 0.0, SurfaceFeature::Specular, true,
        "uSpecularColorFactor");
    const int specular = int(MapSlot::Specular);
    const int specularColor = int(MapSlot::SpecularColor);
    row("specular map, factors the default's (the map turns the layer on)", "specular", 1.0, false, specular,
        0.0, SurfaceFeature::HasSpecularMap, true, "uSpecularMap");
    row("specular colour map, factors the default's", "specular", 1.0, false, specularColor, 0.0,
        SurfaceFeature::HasSpecularColorMap, true, "uSpecularColorMap");
    row("specular colour map, strength 0 (a tint of nothing)", "specular", 0.0, false, specularColor, 0.0,
        SurfaceFeature::HasSpecularColorMap, false, "uSpecularColorMap");
    row("specular map, unlit", "specular", 0.5, true, specular, 0.0, SurfaceFeature::HasSpecularMap, false,
        "uSpecularMap");
    // Anisotropy: on while its strength is above 0, with the tangent frame; its map only then.
    row("anisotropy 0 (default)", "anisotropy", 0.0, false, none, 0.0, SurfaceFeature::Anisotropy, false,
        "uAnisotropyFactor");
    row("anisotropy 0.5", "anisotropy", 0.5, false, none, 0.0, SurfaceFeature::Anisotropy, true,
        "uAnisotropyFactor");
    row("anisotropy 0.5, its rotation", "anisotropy", 0.5, false, none, 0.0, SurfaceFeature::Anisotropy, true,
        "uAnisotropyRotation");
    row("anisotropy 1, unlit", "anisotropy", 1.0, true, none, 0.0, SurfaceFeature::Anisotropy, false,
        "uAnisotropyFactor");
    const int anisotropy = int(MapSlot::Anisotropy);
    row("anisotropy map, strength 0", "anisotropy", 0.0, false, anisotropy, 0.0, SurfaceFeature::HasAnisotropyMap,
        false, "uAnisotropyMap");
    row("anisotropy map, strength 0.5", "anisotropy", 0.5, false, anisotropy, 0.0,
        SurfaceFeature::HasAnisotropyMap, true, "uAnisotropyMap");
    row("anisotropy map, unlit", "anisotropy", 0.5, true, anisotropy, 0.0, SurfaceFeature::HasAnisotropyMap,
        false, "uAnisotropyMap");
    // Iridescence: on while its strength is above 0; its maps only then.
    row("iridescence 0 (default)", "iridescence", 0.0, false, none, 0.0, SurfaceFeature::Iridescence, false,
        "uIridescenceFactor");
    row("iridescence 1", "iridescence", 1.0, false, none, 0.0, SurfaceFeature::Iridescence, true,
        "uIridescenceFactor");
    row("iridescence 1, its thickness range", "iridescence", 1.0, false, none, 0.0, SurfaceFeature::Iridescence,
        true, "uIridescenceThickness");
    row("iridescence 1, unlit", "iridescence", 1.0, true, none, 0.0, SurfaceFeature::Iridescence, false,
        "uIridescenceFactor");
    const int iridescence = int(MapSlot::Iridescence);
    const int iridescenceThickness = int(MapSlot::IridescenceThickness);
    row("iridescence map, strength 0", "iridescence", 0.0, false, iridescence, 0.0,
        SurfaceFeature::HasIridescenceMap, false, "uIridescenceMap");
    row("iridescence map, strength 1", "iridescence", 1.0, false, iridescence, 0.0,
        SurfaceFeature::HasIridescenceMap, true, "uIridescenceMap");
    row("iridescence thickness map, strength 0", "iridescence", 0.0, false, iridescenceThickness, 0.0,
        SurfaceFeature::HasIridescenceThicknessMap, false, "uIridescenceThicknessMap");
    row("iridescence thickness map, strength 1", "iridescence", 1.0, false, iridescenceThickness, 0.0,
        SurfaceFeature::HasIridescenceThicknessMap, true, "uIridescenceThicknessMap");
    row("iridescence thickness map, unlit", "iridescence", 1.0, true, iridescenceThickness, 0.0,
        SurfaceFeature::HasIridescenceThicknessMap, false, "uIridescenceThicknessMap");
}

void ShaderVariantGLTest::lobesOnlyWhereTheMaterialHasThem()
{
    QFETCH(QString, property);
    QFETCH(double, value);
    QFETCH(bool, unlit);
    QFETCH(int, mapSlot);
    QFETCH(double, lobeRoughness);
    QFETCH(SurfaceFeatures, bit);
    QFETCH(bool, on);
    QFETCH(QString, uniform);
    Material material;
    const MaterialProperty lobe = *materialPropertyFromString(property.toStdString());
    if (infoOf(lobe).value == PropertyValue::Color)
        setColor(material, lobe, glm::dvec3(value));
    else
        setScalar(material, lobe, value);
    material.setFactor(MapSlot::ClearcoatRoughness, lobeRoughness);
    material.setFactor(MapSlot::SheenRoughness, lobeRoughness);
    material.unlit = unlit;
    bool images[kMapSlotCount] = {};
    if (mapSlot >= 0) {
        material.maps[std::size_t(mapSlot)].path = "/textures/coat.png";
        images[mapSlot] = true;
    }
    const SurfaceFeatures features = surfaceFeaturesFor(material, images, false, false);
    QCOMPARE((features & bit) != 0, on);
    SurfaceProgramCache programs;
    std::string error;
    const ShaderProgram* program = programs.get(SurfaceVariantKey {features, DebugView::None}, &error);
    QVERIFY2(program, error.c_str());
    QCOMPARE(program->uniformLocation(uniform.toLatin1().constData()) >= 0, on);
    // A coat normal map brings the tangent frame (HAS_TANGENT_FRAME), as the base's does, and so
    // does anisotropy.
    if (mapSlot == int(MapSlot::ClearcoatNormal) || bit == SurfaceFeatures(SurfaceFeature::Anisotropy)) {
        const std::vector<std::string> defines
            = surfaceDefines(SurfaceVariantKey {features, DebugView::None});
        QCOMPARE(std::find(defines.begin(), defines.end(), "HAS_TANGENT_FRAME") != defines.end(), on);
    }
}

// KHR_materials_sheen's and KHR_materials_specular's packing: the colour in RGB (sRGB) and a
// scalar (the sheen's roughness, the specular strength) in A of one texture is one fetch, since
// an sRGB texture's alpha is linear; a scalar read from a colour channel of the sRGB texture is
// not (it would read the decoded colour).
void ShaderVariantGLTest::packedLobeTexture_data()
{
    QTest::addColumn<int>("colorSlot");
    QTest::addColumn<int>("scalarSlot");
    QTest::addColumn<int>("scalarChannel");
    QTest::addColumn<bool>("sameFile");
    QTest::addColumn<bool>("shared");
    QTest::addColumn<SurfaceFeatures>("bit");
    QTest::addColumn<QString>("sampler"); // the scalar's own sampler, declared only when not shared
    const struct {
        const char* lobe;
        MapSlot color, scalar;
        SurfaceFeature bit;
        const char* sampler;
    } lobes[] = {{"sheen", MapSlot::SheenColor, MapSlot::SheenRoughness,
                     SurfaceFeature::SheenRoughnessTexelFromSheenColor, "uSheenRoughnessMap"},
        {"specular", MapSlot::SpecularColor, MapSlot::Specular,
            SurfaceFeature::SpecularTexelFromSpecularColor, "uSpecularMap"}};
    for (const auto& lobe : lobes) {
        const auto row = [&](const char* name, MapChannel channel, bool sameFile, bool shared) {
            QTest::addRow("%s: %s", lobe.lobe, name)
                << int(lobe.color) << int(lobe.scalar) << int(channel) << sameFile << shared
                << SurfaceFeatures(lobe.bit) << QString::fromLatin1(lobe.sampler);
        };
        row("one RGBA texture, the scalar in alpha", MapChannel::A, true, true);
        row("one texture, the scalar in red", MapChannel::R, true, false);
        row("two files", MapChannel::A, false, false);
    }
}

void ShaderVariantGLTest::packedLobeTexture()
{
    QFETCH(int, colorSlot);
    QFETCH(int, scalarSlot);
    QFETCH(int, scalarChannel);
    QFETCH(bool, sameFile);
    QFETCH(bool, shared);
    QFETCH(SurfaceFeatures, bit);
    QFETCH(QString, sampler);
    Material material;
    material.setSheen(glm::dvec3(1.0), 1.0);
    material.setSpecular(0.5, glm::dvec3(1.0));
    const auto color = std::size_t(colorSlot);
    const auto scalar = std::size_t(scalarSlot);
    material.maps[color].path = "/t/packed.png";
    material.maps[scalar].path = sameFile ? "/t/packed.png" : "/t/other.png";
    material.maps[scalar].channel = MapChannel(scalarChannel);
    const auto a = std::make_shared<const MapImage>(4, 4, MapLayout::Rgba, MapSampleType::UInt8);
    const auto b = std::make_shared<const MapImage>(4, 4, MapLayout::Rgba, MapSampleType::UInt8);
    bool hasImage[kMapSlotCount] = {};
    std::array<const void*, kMapSlotCount> textures {};
    hasImage[color] = hasImage[scalar] = true;
    textures[color] = a.get();
    textures[scalar] = sameFile ? a.get() : b.get();
    const SurfaceFeatures features = surfaceFeaturesFor(material, hasImage, false, false);
    QVERIFY(hasFeature(features, mapFeature(MapSlot(colorSlot))));
    QVERIFY(hasFeature(features, mapFeature(MapSlot(scalarSlot))));
    const SurfaceFeatures all = features | sharedTexelFeatures(material, features, textures);
    QCOMPARE((all & bit) != 0, shared);
    QCOMPARE(samplesOwnTexture(all, MapSlot(scalarSlot)), !shared);
    SurfaceProgramCache programs;
    std::string error;
    const ShaderProgram* program = programs.get(SurfaceVariantKey {all, DebugView::None}, &error);
    QVERIFY2(program, error.c_str());
    QCOMPARE(program->uniformLocation(sampler.toLatin1().constData()) >= 0, !shared);
}

QTEST_GUILESS_MAIN(ShaderVariantGLTest)
#include "ShaderVariantGLTest.moc"
