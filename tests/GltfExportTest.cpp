// core/gltf/GltfExport: materials on a mesh written as a glTF 2.0 asset (.gltf with its .bin and
// textures, and .glb), one row per feature: constants only; every map (packed ORM, DirectX normal
// at strength 2, emissive with strength, alpha); a UV transform the maps share (kept as
// KHR_texture_transform) and transforms that differ (baked); IOR; MASK and BLEND; single-sided;
// two materials of one name. Each file passes the Khronos glTF-Validator with no error and no
// warning, and imports back (core/project/AssetProject projectFromAsset) with the same parameters and the
// same material inputs at every texel (0.5/255 for data and sRGB colour, 2/255 for the normal).
// (An asset's own scenes, nodes, skins and animations written back: GltfAssetExportTest.)

#include <cmath>
#include <memory>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <glm/geometric.hpp>

#include "GltfWriter.h"
#include "TestAssets.h"
#include "TestSupport.h"
#include "core/gltf/GltfExport.h"
#include "core/gltf/GltfImport.h"
#include "core/gltf/GltfModel.h"
#include "core/image/MapImage.h"
#include "core/image/ToneMap.h"
#include "core/material/MaterialProperties.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/project/AssetProject.h"
#include "core/project/ProjectAssets.h"
#include "core/shading/MaterialInputs.h"

using namespace facet;

namespace {

// A 16x8 8-bit map, every texel and channel different.
void writeVariedPng(const QString& path, int seed, int channels)
{
    std::string error;
    if (!test::variedImage(seed, channels).save(path.toStdString(), &error, channels == 4))
        qFatal("%s", error.c_str());
}

// A 16x8 normal map of unit normals tilted up to about 30 degrees, each texel its own, encoded
// n * 0.5 + 0.5 (as normal maps are: the shader renormalises, so only unit normals are
// meaningful to compare between texels).
void writeUnitNormalPng(const QString& path)
{
    Image image(16, 8);
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 16; ++x) {
            const glm::vec3 n = glm::normalize(glm::vec3(float((x * 7 + y * 3) % 11) / 10.0f - 0.5f,
                float((x * 5 + y * 9) % 13) / 12.0f - 0.5f, 1.0f));
            image.at(x, y) = glm::vec4(n * 0.5f + 0.5f, 1.0f);
        }
    }
    image.setEncoding(ColorEncoding::Linear);
    std::string error;
    if (!image.save(path.toStdString(), &error, false))
        qFatal("%s", error.c_str());
}

Material texturedMaterial(const QString& folder)
{
    writeVariedPng(folder + QStringLiteral("/base.png"), 1, 4);
    writeUnitNormalPng(folder + QStringLiteral("/normal.png"));
    writeVariedPng(folder + QStringLiteral("/orm.png"), 3, 3);
    writeVariedPng(folder + QStringLiteral("/emissive.png"), 4, 3);
    Material m;
    m.name = "Painted Metal";
    m.map(MapSlot::BaseColor).path = (folder + QStringLiteral("/base.png")).toStdString();
    m.setBaseColor(glm::dvec3(0.9, 0.8, 1.0), 0.9);
    m.map(MapSlot::Normal).path = (folder + QStringLiteral("/normal.png")).toStdString();
    m.map(MapSlot::Normal).flipGreen = true;
    m.setFactor(MapSlot::Normal, 2.0);
    for (const auto& [slot, channel] : {std::pair {MapSlot::Occlusion, MapChannel::R},
             {MapSlot::Roughness, MapChannel::G}, {MapSlot::Metallic, MapChannel::B}}) {
        m.map(slot).path = (folder + QStringLiteral("/orm.png")).toStdString();
        m.map(slot).channel = channel;
    }
    m.setFactor(MapSlot::Occlusion, 0.7);
    m.setFactor(MapSlot::Roughness, 0.8);
    m.setFactor(MapSlot::Metallic, 1.0);
    m.map(MapSlot::Emissive).path = (folder + QStringLiteral("/emissive.png")).toStdString();
    m.map(MapSlot::Emissive).colorSpace = ColorEncoding::SRGB;
    m.map(MapSlot::Emissive).factor = glm::dvec4(1.0, 0.5, 0.25, 1.0);
    m.emissiveStrength = 4.0;
    return m;
}

std::unique_ptr<MapImage> loadMap(const std::string& path)
{
    std::string error;
    std::optional<MapImage> image = MapImage::load(path, &error);
    if (!image)
        qFatal("%s", error.c_str());
    return std::make_unique<MapImage>(std::move(*image));
}

struct Loaded {
    std::vector<std::unique_ptr<MapImage>> keep;
    MaterialMapImages images {};
};
Loaded loadMaps(const Material& material)
{
    Loaded loaded;
    for (const MapSlot slot : kAllMapSlots) {
        if (!material.map(slot).hasTexture())
            continue;
        loaded.keep.push_back(loadMap(material.map(slot).path));
        loaded.images[std::size_t(slot)] = loaded.keep.back().get();
    }
    return loaded;
}

} // namespace

class GltfExportTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // One baked texture set has one parameterisation: maps on two UV sets are refused, naming the
    // material and the map, and nothing is written.
    void mixedUvSetsAreRefused()
    {
        QTemporaryDir dir;
        Material m = texturedMaterial(dir.path());
        m.map(MapSlot::Occlusion).texCoord = 1;
        Mesh mesh = makeSphere(16, 8);
        mesh.hasTexCoord1 = true;
        const QString path = dir.filePath(QStringLiteral("out/asset.glb"));
        GltfExportOptions options;
        options.binary = true;
        std::string error;
        std::vector<std::string> written;
        QVERIFY(!writeGltfAsset(path.toStdString(), mesh, {}, {m}, options, false, &written, &error));
        QVERIFY2(QString::fromStdString(error).contains(QStringLiteral(
                     "material 'Painted Metal': its maps read different texture-coordinate sets")),
            error.c_str());
        QVERIFY(!QFileInfo::exists(path));
        // A mesh without TEXCOORD_1 reads set 0 for every map: nothing to refuse, and the file
        // names no second set.
        mesh.hasTexCoord1 = false;
        QVERIFY2(writeGltfAsset(path.toStdString(), mesh, {}, {m}, options, false, &written, &error),
            error.c_str());
        QCOMPARE(gltfAssetFiles(path.toStdString(), {m}, options, &error, false).size(), std::size_t(1));
        QVERIFY(gltfAssetFiles(path.toStdString(), {m}, options, &error, true).empty());
        FACET_REQUIRE_VALID_GLTF(path);
    }

    void textureTransformRoundTrip()
    {
        // toGltfTextureTransform inverts the importer's conversion.
        for (const UvTransform& uv : {UvTransform {{2.0, 3.0}, {0.25, -0.5}, 30.0},
                 UvTransform {{1.0, 1.0}, {0.1, 0.2}, 0.0}, UvTransform {{0.5, 4.0}, {0.0, 0.0}, -90.0}}) {
            const GltfTextureTransform t = toGltfTextureTransform(uv);
            const UvTransform back = gltfTextureTransform(t.offset, t.rotation, t.scale);
            QVERIFY(glm::length(back.scale - uv.scale) < 1e-12);
            QVERIFY(glm::length(back.offset - uv.offset) < 1e-12);
            QVERIFY(std::abs(back.rotationDegrees - uv.rotationDegrees) < 1e-9);
        }
    }

    // Every extension field of the material property registry (GltfField), a row each: a value
    // that is not the extension's default is written where the registry says, in the file's units
    // (the rotation in radians), passes the validator, and reads back as it was.
    void registryFieldsRoundTrip_data()
    {
        QTest::addColumn<int>("property");
        for (const MaterialPropertyInfo& info : materialProperties())
            if (info.gltf.extension)
                QTest::newRow(info.name) << int(info.property);
    }
    void registryFieldsRoundTrip()
    {
        QFETCH(int, property);
        const MaterialPropertyInfo& info = infoOf(MaterialProperty(property));
        // Every lobe on, so that each extension is written.
        Material m;
        m.name = "Registry";
        m.ior = 1.45;
        m.setFactor(MapSlot::Emissive, 1.0);
        m.emissiveStrength = 2.0;
        m.setFactor(MapSlot::Clearcoat, 0.5);
        m.setSheen(glm::dvec3(0.3, 0.2, 0.1), 0.4);
        m.setSpecular(0.8, glm::dvec3(0.9));
        m.setAnisotropy(0.5, 20.0);
        m.setIridescence(0.6, 1.7, 150.0, 650.0);
        const glm::dvec3 color(0.37, 0.21, 0.83);
        const double scalar
            = info.minimum + 0.37 * (std::min(info.maximum, info.minimum + 10.0) - info.minimum);
        if (info.value == PropertyValue::Color)
            setColor(m, info.property, color);
        else
            setScalar(m, info.property, scalar);
        std::string problem;
        QVERIFY2(m.validate(&problem), problem.c_str());

        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("registry.gltf"));
        std::string error;
        std::vector<std::string> written;
        QVERIFY2(writeGltfAsset(path.toStdString(), makeSphere(16, 8), {}, {m}, GltfExportOptions {}, false,
                     &written, &error),
            error.c_str());
        FACET_REQUIRE_VALID_GLTF(path);
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonObject material = QJsonDocument::fromJson(file.readAll())
                                         .object()[QLatin1String("materials")]
                                         .toArray()
                                         .at(0)
                                         .toObject();
        const QJsonValue field = material[QLatin1String("extensions")]
                                     .toObject()[QLatin1String(info.gltf.extension)]
                                     .toObject()[QLatin1String(info.gltf.field)];
        const auto asset = importGltf(path.toStdString(), &error);
        QVERIFY2(asset, error.c_str());
        const Material& back = asset->materials.at(0);
        if (info.value == PropertyValue::Color) {
            const QJsonArray rgb = field.toArray();
            QCOMPARE(rgb.size(), 3);
            for (int c = 0; c < 3; ++c)
                QCOMPARE(rgb.at(c).toDouble(), color[c] * info.gltf.scale);
            QVERIFY(glm::length(colorOf(back, info.property) - color) < 1e-9);
        } else {
            QVERIFY2(field.isDouble(), info.gltf.field);
            QVERIFY(std::abs(field.toDouble() - scalar * info.gltf.scale) < 1e-12);
            QVERIFY2(std::abs(scalarOf(back, info.property) - scalar) < 1e-9,
                qPrintable(QString::number(scalarOf(back, info.property))));
        }
    }

    void roundTrip_data()
    {
        QTest::addColumn<QString>("feature");
        QTest::addColumn<bool>("binary");
        for (const char* feature : {"constants", "every map", "shared transform", "different transforms",
                 "ior", "clearcoat", "clearcoat, smooth", "unlit, clearcoat", "clearcoat maps",
                 "clearcoat maps, coat off", "sheen", "sheen maps", "sheen maps, sheen off", "unlit, sheen",
                 "clearcoat and sheen maps", "specular", "specular maps", "anisotropy", "anisotropy map", "iridescence",
                 "iridescence maps", "mask",
                 "blend", "single-sided",
                 "unlit", "two of one name", "samplers", "second UV set", "second UV set, mesh without it"}) {
            QTest::newRow(qPrintable(QStringLiteral("%1, .gltf").arg(QLatin1String(feature))))
                << QString::fromLatin1(feature) << false;
            QTest::newRow(qPrintable(QStringLiteral("%1, .glb").arg(QLatin1String(feature))))
                << QString::fromLatin1(feature) << true;
        }
    }

    void roundTrip()
    {
        QFETCH(QString, feature);
        QFETCH(bool, binary);
        QTemporaryDir dir;
        std::vector<Material> materials;
        if (feature == QStringLiteral("constants")) {
            Material gold;
            gold.name = "Gold";
            gold.setBaseColor(glm::dvec3(1.0, 0.766, 0.336));
            gold.setFactor(MapSlot::Metallic, 1.0);
            gold.setFactor(MapSlot::Roughness, 0.3);
            gold.map(MapSlot::Emissive).factor = glm::dvec4(0.1, 0.0, 0.0, 1.0);
            gold.emissiveStrength = 2.0;
            materials.push_back(gold);
        } else {
            Material m = texturedMaterial(dir.path());
            if (feature == QStringLiteral("shared transform"))
                for (const MapSlot slot : kAllMapSlots)
                    m.map(slot).uv = UvTransform {{2.0, 1.5}, {0.25, 0.1}, 30.0};
            if (feature == QStringLiteral("different transforms"))
                m.map(MapSlot::BaseColor).uv = UvTransform {{2.0, 1.0}, {0.0, 0.0}, 0.0};
            if (feature == QStringLiteral("ior"))
                m.ior = 1.45;
            if (feature.contains(QStringLiteral("clearcoat"))) {
                m.setClearcoat(feature.contains(QStringLiteral("off")) ? 0.0 : 0.7,
                    feature.contains(QStringLiteral("smooth")) ? 0.0 : 0.15);
            }
            if (feature.contains(QStringLiteral("sheen")))
                m.setSheen(
                    feature.contains(QStringLiteral("off")) ? glm::dvec3(0.0) : glm::dvec3(0.9, 0.4, 0.2),
                    0.35);
            if (feature.contains(QStringLiteral("sheen maps"))) {
                // The colour (sRGB, RGB) from one file and the roughness from another's green:
                // baked into one RGBA texture, the roughness in its alpha.
                writeVariedPng(dir.filePath(QStringLiteral("sheen.png")), 7, 3);
                writeVariedPng(dir.filePath(QStringLiteral("sheenroughness.png")), 8, 3);
                m.map(MapSlot::SheenColor).path = dir.filePath(QStringLiteral("sheen.png")).toStdString();
                m.map(MapSlot::SheenRoughness).path
                    = dir.filePath(QStringLiteral("sheenroughness.png")).toStdString();
                m.map(MapSlot::SheenRoughness).channel = MapChannel::G;
            }
            if (feature.startsWith(QStringLiteral("specular")))
                m.setSpecular(0.6, glm::dvec3(3.0, 1.0, 0.5)); // a tint above 1: the file holds it over 3
            if (feature == QStringLiteral("specular maps")) {
                // The colour (sRGB) from one file, the strength from another's red: one RGBA texture.
                writeVariedPng(dir.filePath(QStringLiteral("specularcolor.png")), 9, 3);
                writeVariedPng(dir.filePath(QStringLiteral("specular.png")), 10, 3);
                m.map(MapSlot::SpecularColor).path
                    = dir.filePath(QStringLiteral("specularcolor.png")).toStdString();
                m.map(MapSlot::Specular).path = dir.filePath(QStringLiteral("specular.png")).toStdString();
                m.map(MapSlot::Specular).channel = MapChannel::R;
            }
            if (feature.startsWith(QStringLiteral("anisotropy")))
                m.setAnisotropy(0.7, 35.0);
            if (feature == QStringLiteral("anisotropy map")) {
                // A direction texture (RG) with its strength in B: baked without the factor and the
                // rotation, which the extension keeps.
                writeVariedPng(dir.filePath(QStringLiteral("anisotropy.png")), 11, 3);
                m.map(MapSlot::Anisotropy).path = dir.filePath(QStringLiteral("anisotropy.png")).toStdString();
            }
            if (feature.startsWith(QStringLiteral("iridescence")))
                m.setIridescence(0.8, 1.6, 150.0, 550.0);
            if (feature == QStringLiteral("iridescence maps")) {
                // The strength from one file's red and the thickness from another's green: baked
                // into one texture (R, G), the factor 1, the index and thickness range kept.
                writeVariedPng(dir.filePath(QStringLiteral("iridescence.png")), 12, 3);
                writeVariedPng(dir.filePath(QStringLiteral("iridescencethickness.png")), 13, 3);
                m.map(MapSlot::Iridescence).path = dir.filePath(QStringLiteral("iridescence.png")).toStdString();
                m.map(MapSlot::IridescenceThickness).path
                    = dir.filePath(QStringLiteral("iridescencethickness.png")).toStdString();
            }
            if (feature.startsWith(QStringLiteral("clearcoat maps"))
                || feature == QStringLiteral("clearcoat and sheen maps")) {
                // Strength and roughness from two files (baked into one texture, R and G), and the
                // coat's own normal map with its scale.
                writeVariedPng(dir.filePath(QStringLiteral("coat.png")), 5, 3);
                writeVariedPng(dir.filePath(QStringLiteral("coatroughness.png")), 6, 1);
                writeUnitNormalPng(dir.filePath(QStringLiteral("coatnormal.png")));
                m.map(MapSlot::Clearcoat).path = dir.filePath(QStringLiteral("coat.png")).toStdString();
                m.map(MapSlot::Clearcoat).channel = MapChannel::B;
                m.map(MapSlot::ClearcoatRoughness).path
                    = dir.filePath(QStringLiteral("coatroughness.png")).toStdString();
                m.map(MapSlot::ClearcoatRoughness).channel = MapChannel::R;
                m.setFactor(MapSlot::ClearcoatRoughness, 0.6);
                m.map(MapSlot::ClearcoatNormal).path
                    = dir.filePath(QStringLiteral("coatnormal.png")).toStdString();
                m.setFactor(MapSlot::ClearcoatNormal, 0.5);
            }
            if (feature == QStringLiteral("mask")) {
                m.alphaMode = AlphaMode::Mask;
                m.alphaCutoff = 0.3;
            }
            if (feature == QStringLiteral("blend"))
                m.alphaMode = AlphaMode::Blend;
            if (feature == QStringLiteral("single-sided"))
                m.doubleSided = false;
            if (feature == QStringLiteral("samplers")) {
                // Per texture: base colour clamped and nearest; the packed slots agree (mirrored U).
                m.map(MapSlot::BaseColor).sampler = {TextureWrap::ClampToEdge, TextureWrap::ClampToEdge,
                    TextureFilter::Nearest, TextureFilter::NearestMipmapNearest};
                for (const MapSlot slot : {MapSlot::Occlusion, MapSlot::Roughness, MapSlot::Metallic})
                    m.map(slot).sampler.wrapS = TextureWrap::MirroredRepeat;
            }
            if (feature.startsWith(QStringLiteral("second UV set")))
                for (const MapSlot slot : kAllMapSlots)
                    m.map(slot).texCoord = 1;
            if (feature.startsWith(QStringLiteral("unlit"))) {
                m.unlit = true;
                m.emissiveStrength = 1.0; // an unlit material writes no other material extension
            }
            materials.push_back(m);
            if (feature == QStringLiteral("two of one name")) {
                Material other = m;
                other.map(MapSlot::Normal).path.clear();
                other.setBaseColor(glm::dvec3(0.2, 0.4, 0.6), 1.0);
                materials.push_back(other);
            }
        }
        Mesh mesh = makeSphere(16, 8);
        mesh.name = "Ball";
        if (feature == QStringLiteral("second UV set")) {
            mesh.hasTexCoord1 = true;
            for (Vertex& v : mesh.vertices)
                v.uv1 = 0.5f * v.uv + glm::vec2(0.25f);
        }
        std::vector<int> parts;
        if (materials.size() == 2) {
            // Two parts: the upper and lower halves of the index buffer.
            const std::uint32_t half = std::uint32_t(mesh.indices.size() / 6) * 3;
            mesh.subMeshes = {SubMesh {"top", 0, half, 0, true},
                SubMesh {"bottom", half, std::uint32_t(mesh.indices.size()) - half, 1, true}};
            parts = {0, 1};
        }
        const QString path
            = dir.filePath(binary ? QStringLiteral("out/asset.glb") : QStringLiteral("out/asset.gltf"));
        GltfExportOptions options;
        options.binary = binary;
        std::string error;
        std::vector<std::string> written;
        QVERIFY2(writeGltfAsset(path.toStdString(), mesh, parts, materials, options, false, &written, &error),
            error.c_str());
        QCOMPARE(QString::fromStdString(written.back()), path);
        if (binary)
            QCOMPARE(QDir(dir.filePath(QStringLiteral("out"))).entryList(QDir::Files),
                QStringList {QStringLiteral("asset.glb")});
        FACET_REQUIRE_VALID_GLTF(path);

        // The asset's JSON says what glTF readers need.
        if (!binary) {
            QFile file(path);
            QVERIFY(file.open(QIODevice::ReadOnly));
            const QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
            const QJsonArray used = json.value(QStringLiteral("extensionsUsed")).toArray();
            QCOMPARE(used.contains(QStringLiteral("KHR_texture_transform")),
                feature == QStringLiteral("shared transform"));
            QCOMPARE(used.contains(QStringLiteral("KHR_materials_ior")), feature == QStringLiteral("ior"));
            QCOMPARE(used.contains(QStringLiteral("KHR_materials_emissive_strength")),
                !feature.startsWith(QStringLiteral("unlit")));
            QCOMPARE(used.contains(QStringLiteral("KHR_materials_unlit")),
                feature.startsWith(QStringLiteral("unlit")));
            // The coat where it is on, and not on an unlit material (it would mean nothing).
            const bool coated
                = feature.startsWith(QStringLiteral("clearcoat")) && !feature.contains(QStringLiteral("off"));
            QCOMPARE(used.contains(QStringLiteral("KHR_materials_clearcoat")), coated);
            const bool sheened = feature.contains(QStringLiteral("sheen"))
                && !feature.contains(QStringLiteral("off")) && !feature.startsWith(QStringLiteral("unlit"));
            QCOMPARE(used.contains(QStringLiteral("KHR_materials_sheen")), sheened);
            QCOMPARE(used.contains(QStringLiteral("KHR_materials_specular")),
                feature.startsWith(QStringLiteral("specular")));
            QCOMPARE(used.contains(QStringLiteral("KHR_materials_anisotropy")),
                feature.startsWith(QStringLiteral("anisotropy")));
            QCOMPARE(used.contains(QStringLiteral("KHR_materials_iridescence")),
                feature.startsWith(QStringLiteral("iridescence")));
            // The sheen's one texture: colour and roughness read the same image.
            const QJsonObject sheen = json.value(QStringLiteral("materials"))
                                          .toArray()
                                          .at(0)
                                          .toObject()
                                          .value(QStringLiteral("extensions"))
                                          .toObject()
                                          .value(QStringLiteral("KHR_materials_sheen"))
                                          .toObject();
            const bool sheenMaps = sheened && feature.contains(QStringLiteral("maps"));
            QCOMPARE(sheen.contains(QStringLiteral("sheenColorTexture")), sheenMaps);
            QCOMPARE(sheen.contains(QStringLiteral("sheenRoughnessTexture")), sheenMaps);
            if (sheenMaps)
                QCOMPARE(sheen.value(QStringLiteral("sheenColorTexture"))
                             .toObject()
                             .value(QStringLiteral("index")),
                    sheen.value(QStringLiteral("sheenRoughnessTexture"))
                        .toObject()
                        .value(QStringLiteral("index")));
            // The coat's textures: one for the strength (R) and roughness (G), one for its normal.
            const QJsonObject coat = json.value(QStringLiteral("materials"))
                                         .toArray()
                                         .at(0)
                                         .toObject()
                                         .value(QStringLiteral("extensions"))
                                         .toObject()
                                         .value(QStringLiteral("KHR_materials_clearcoat"))
                                         .toObject();
            const bool coatMaps = coated && feature.contains(QStringLiteral("maps"));
            for (const char* texture :
                {"clearcoatTexture", "clearcoatRoughnessTexture", "clearcoatNormalTexture"})
                QVERIFY2(coat.contains(QLatin1String(texture)) == coatMaps, texture);
            if (coatMaps) {
                QCOMPARE(
                    coat.value(QStringLiteral("clearcoatTexture")).toObject().value(QStringLiteral("index")),
                    coat.value(QStringLiteral("clearcoatRoughnessTexture"))
                        .toObject()
                        .value(QStringLiteral("index")));
                QCOMPARE(coat.value(QStringLiteral("clearcoatNormalTexture"))
                             .toObject()
                             .value(QStringLiteral("scale"))
                             .toDouble(),
                    0.5);
            }
        }

        const std::optional<Project> back = projectFromAsset(path.toStdString(), &error);
        QVERIFY2(back, error.c_str());
        QCOMPARE(back->materials.size(), materials.size());
        for (std::size_t i = 0; i < materials.size(); ++i) {
            const Material& a = materials[i];
            const Material& b = back->materials[i];
            QCOMPARE(b.name, a.name);
            QCOMPARE(b.alphaMode, a.alphaMode);
            if (a.alphaMode == AlphaMode::Mask)
                QCOMPARE(b.alphaCutoff, a.alphaCutoff);
            QCOMPARE(b.doubleSided, a.doubleSided);
            QCOMPARE(b.unlit, a.unlit);
            QVERIFY(std::abs(b.ior - a.ior) < 1e-9);
            QVERIFY(std::abs(b.emissiveStrength - a.emissiveStrength) < 1e-9);
            // The coat's factors as they were, or 1 where a baked texture holds factor x texture
            // (compared texel by texel below); no coat on an unlit material or one whose coat is off.
            const bool coated = !a.unlit && a.hasClearcoat();
            const bool baked = coated
                && (a.map(MapSlot::Clearcoat).hasTexture()
                    || a.map(MapSlot::ClearcoatRoughness).hasTexture());
            QVERIFY(std::abs(b.clearcoat() - (baked ? 1.0 : coated ? a.clearcoat() : 0.0)) < 1e-9);
            QVERIFY(std::abs(b.clearcoatRoughness()
                        - (baked         ? 1.0
                                : coated ? a.clearcoatRoughness()
                                         : 0.0))
                < 1e-9);
            // The specular layer: a baked texture's strength factor is 1, its colour factor the
            // tint's largest component (3), which the texture was divided by.
            const bool specularBaked = !a.unlit
                && (a.map(MapSlot::Specular).hasTexture() || a.map(MapSlot::SpecularColor).hasTexture());
            QVERIFY(std::abs(b.specular() - (specularBaked ? 1.0 : a.specular())) < 1e-9);
            QVERIFY(glm::length(b.specularColor() - (specularBaked ? glm::dvec3(3.0) : a.specularColor()))
                < 1e-9);
            // The anisotropy's strength and rotation stay parameters, baked texture or not.
            QVERIFY(std::abs(b.anisotropy() - (a.unlit ? 0.0 : a.anisotropy())) < 1e-9);
            QVERIFY(std::abs(b.anisotropyRotationDegrees - (a.unlit ? 0.0 : a.anisotropyRotationDegrees)) < 1e-9);
            // The film's factor, index and range stay parameters, baked texture or not.
            if (!a.unlit && a.hasIridescence()) {
                QCOMPARE(b.iridescence(), a.iridescence());
                QCOMPARE(b.iridescenceIor, a.iridescenceIor);
                QCOMPARE(b.iridescenceThicknessMinimum, a.iridescenceThicknessMinimum);
                QCOMPARE(b.iridescenceThicknessMaximum(), a.iridescenceThicknessMaximum());
            }
            // The sheen likewise.
            const bool sheened = !a.unlit && a.hasSheen();
            const bool sheenBaked = sheened
                && (a.map(MapSlot::SheenColor).hasTexture() || a.map(MapSlot::SheenRoughness).hasTexture());
            QVERIFY(glm::length(b.sheenColor()
                        - (sheenBaked     ? glm::dvec3(1.0)
                                : sheened ? a.sheenColor()
                                          : glm::dvec3(0.0)))
                < 1e-9);
            QVERIFY(std::abs(b.sheenRoughness()
                        - (sheenBaked     ? 1.0
                                : sheened ? a.sheenRoughness()
                                          : 0.0))
                < 1e-9);
            for (const MapSlot slot : kAllMapSlots) {
                // A lobe that is off (or a lobe on an unlit material) writes none of its maps.
                const bool exported = a.usesSlot(slot) && (lobeOf(slot) == MaterialLobe::Core || !a.unlit);
                QCOMPARE(b.map(slot).hasTexture(), a.map(slot).hasTexture() && exported);
                if (!exported)
                    continue;
                if (!a.map(slot).hasTexture())
                    continue;
                // The sampler and the UV set come back (set 1 only where the mesh has one).
                QVERIFY2(b.map(slot).sampler == a.map(slot).sampler, toString(slot));
                QCOMPARE(b.map(slot).texCoord, mesh.hasTexCoord1 ? a.map(slot).texCoord : 0);
            }
            if (mesh.hasTexCoord1) {
                // TEXCOORD_1 itself: each vertex's second set as it went out.
                const std::optional<GltfAsset> asset = importGltf(path.toStdString(), &error);
                QVERIFY2(asset, error.c_str());
                QVERIFY(asset->mesh.hasTexCoord1);
                for (const Vertex& v : asset->mesh.vertices)
                    QVERIFY2(glm::length(v.uv1 - (0.5f * v.uv + glm::vec2(0.25f))) < 1e-5f,
                        qPrintable(QStringLiteral("uv (%1, %2), uv1 (%3, %4)")
                                       .arg(v.uv.x)
                                       .arg(v.uv.y)
                                       .arg(v.uv1.x)
                                       .arg(v.uv1.y)));
            }

            // The inputs at every texel centre of the 16x8 maps.
            const Loaded mapsA = loadMaps(a);
            const Loaded mapsB = loadMaps(b);
            double worstScalar = 0.0, worstColor = 0.0, worstNormal = 0.0;
            for (int y = 0; y < 8; ++y) {
                for (int x = 0; x < 16; ++x) {
                    const glm::dvec2 uv((x + 0.5) / 16.0, (y + 0.5) / 8.0);
                    const MaterialInfo ia = materialInputs(a, mapsA.images, uv);
                    const MaterialInfo ib = materialInputs(b, mapsB.images, uv);
                    worstScalar = std::max({worstScalar, std::abs(ia.metallic - ib.metallic),
                        std::abs(ia.perceptualRoughness - ib.perceptualRoughness),
                        std::abs(ia.occlusion - ib.occlusion), std::abs(ia.alpha - ib.alpha)});
                    if (!a.unlit)
                        worstScalar = std::max({worstScalar, std::abs(ia.clearcoat - ib.clearcoat),
                            std::abs(ia.clearcoatRoughness - ib.clearcoatRoughness),
                            std::abs(ia.sheenRoughness - ib.sheenRoughness),
                            std::abs(ia.specular - ib.specular), std::abs(ia.anisotropy - ib.anisotropy),
                            std::abs(ia.iridescence - ib.iridescence),
                            // the thickness as its texture holds it: a fraction of the range
                            std::abs(ia.iridescenceThickness - ib.iridescenceThickness)
                                / std::max(std::abs(a.iridescenceThicknessMaximum() - a.iridescenceThicknessMinimum),
                                    1.0)});
                    // The anisotropy direction, a unit vector stored as d x 0.5 + 0.5 in 8 bits.
                    if (!a.unlit)
                        worstNormal = std::max(
                            worstNormal, glm::length(ia.anisotropyTangentDirection - ib.anisotropyTangentDirection));
                    // The specular colour as the file holds it: over the tint's largest component.
                    const double tintScale
                        = std::max({1.0, a.specularColor().r, a.specularColor().g, a.specularColor().b});
                    if (!a.unlit)
                        for (int c = 0; c < 3; ++c)
                            worstColor = std::max({worstColor,
                                std::abs(tonemap::linearToSrgb(ia.sheenColor[c])
                                    - tonemap::linearToSrgb(ib.sheenColor[c])),
                                std::abs(tonemap::linearToSrgb(ia.specularColor[c] / tintScale)
                                    - tonemap::linearToSrgb(ib.specularColor[c] / tintScale))});
                    for (int c = 0; c < 3; ++c)
                        worstColor = std::max({worstColor,
                            std::abs(tonemap::linearToSrgb(ia.baseColor[c])
                                - tonemap::linearToSrgb(ib.baseColor[c])),
                            std::abs(tonemap::linearToSrgb(ia.emissive[c] / a.emissiveStrength)
                                - tonemap::linearToSrgb(ib.emissive[c] / b.emissiveStrength))});
                    for (const MapSlot slot : {MapSlot::Normal, MapSlot::ClearcoatNormal}) {
                        if (!a.map(slot).hasTexture() || !a.usesSlot(slot)
                            || (a.unlit && slot != MapSlot::Normal))
                            continue;
                        const glm::dvec3 ng(0.0, 0.0, 1.0);
                        const glm::dvec4 tangent(1.0, 0.0, 0.0, 1.0);
                        const auto normal = [&](const Material& m, const Loaded& maps) {
                            const MaterialMap& map = m.map(slot);
                            return shadingNormal(ng, tangent,
                                sampleTexture(
                                    *maps.images[std::size_t(slot)], map.colorSpace, map.uv.apply(uv)),
                                map.factor.x, map.flipGreen);
                        };
                        worstNormal = std::max(worstNormal, glm::length(normal(a, mapsA) - normal(b, mapsB)));
                    }
                }
            }
            const bool resampled = feature == QStringLiteral("shared transform");
            // A shared transform keeps the maps as they are: the bilinear reads between texels of
            // two 8-bit quantised copies differ by up to a step.
            const double step = resampled ? 1.0 / 255.0 : 0.5 / 255.0;
            QVERIFY2(worstScalar <= step + 1e-6,
                qPrintable(QStringLiteral("scalar %1/255").arg(worstScalar * 255.0)));
            QVERIFY2(worstColor <= step + 1e-6,
                qPrintable(QStringLiteral("colour %1/255").arg(worstColor * 255.0)));
            QVERIFY2(worstNormal <= 2.0 / 255.0,
                qPrintable(QStringLiteral("normal %1/255").arg(worstNormal * 255.0)));
        }
        // The mesh: every triangle, each part with its material.
        std::optional<Mesh> meshBack = loadViewMesh(path.toStdString(), &error);
        QVERIFY2(meshBack, error.c_str());
        QCOMPARE(meshBack->triangleCount(), mesh.triangleCount());
        QCOMPARE(back->materialOfPart(0), 0);
        if (materials.size() == 2)
            QCOMPARE(back->materialOfPart(1), 1);
    }

    void refusals()
    {
        QTemporaryDir dir;
        const Mesh mesh = makeSphere(8, 4);
        Material plain;
        std::string error;
        const QString path = dir.filePath(QStringLiteral("a.gltf"));
        QVERIFY(writeGltfAsset(path.toStdString(), mesh, {}, {plain}, {}, false, nullptr, &error));
        QVERIFY(!writeGltfAsset(path.toStdString(), mesh, {}, {plain}, {}, false, nullptr, &error));
        QCOMPARE(QString::fromStdString(error),
            dir.filePath(QStringLiteral("a.bin")) + QStringLiteral(": exists"));
        QVERIFY2(
            writeGltfAsset(path.toStdString(), mesh, {}, {plain}, {}, true, nullptr, &error), error.c_str());
        GltfExportOptions deep;
        deep.textures.bitDepth = 32;
        QVERIFY(!writeGltfAsset(dir.filePath(QStringLiteral("b.glb")).toStdString(), mesh, {}, {plain}, deep,
            false, nullptr, &error));
        QCOMPARE(error, std::string("glTF textures are PNG: 8 or 16 bits, not 32"));
        QVERIFY(!writeGltfAsset(dir.filePath(QStringLiteral("c.glb")).toStdString(), Mesh {}, {}, {plain}, {},
            false, nullptr, &error));
        Material missing;
        missing.name = "Lost";
        missing.map(MapSlot::Roughness).path = dir.filePath(QStringLiteral("gone.png")).toStdString();
        QVERIFY(!writeGltfAsset(dir.filePath(QStringLiteral("d.gltf")).toStdString(), mesh, {}, {missing}, {},
            false, nullptr, &error));
        QVERIFY2(QString::fromStdString(error).startsWith(QStringLiteral("material 'Lost', roughness: "))
                && QString::fromStdString(error).contains(QStringLiteral("gone.png")),
            error.c_str());
        QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("d.gltf"))));
    }
};

QTEST_GUILESS_MAIN(GltfExportTest)
#include "GltfExportTest.moc"
