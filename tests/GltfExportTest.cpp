// core/gltf/GltfExport: materials on a mesh written as a glTF 2.0 asset (.gltf with its .bin and
// textures, and .glb), one row per feature: constants only; every map (packed ORM, DirectX normal
// at strength 2, emissive with strength, alpha); a UV transform the maps share (kept as
// KHR_texture_transform) and transforms that differ (baked); IOR; MASK and BLEND; single-sided;
// two materials of one name. Each file passes the Khronos glTF-Validator with no error and no
// warning, and imports back (core/project/AssetProject projectFromAsset) with the same parameters and the
// same material inputs at every texel (0.5/255 for data and sRGB colour, 2/255 for the normal).

#include <cmath>
#include <cstring>
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

// The JSON of a .gltf, or of a .glb's JSON chunk.
QJsonObject assetJson(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QByteArray bytes = file.readAll();
    if (bytes.startsWith("glTF") && bytes.size() >= 20) {
        std::uint32_t length = 0;
        std::memcpy(&length, bytes.constData() + 12, 4);
        bytes = bytes.mid(20, qsizetype(length));
    }
    return QJsonDocument::fromJson(bytes).object();
}

// A skinned, animated asset with a node hierarchy, morph targets, an instanced mesh, extras, an
// embedded image and a material extension Facet does not write:
//   1 Body (mesh 0 "Strip", skin 0); 0 Root (extras) -> 2 Hip -> 3 Knee, 4 TileA and 5 TileB (both
//   mesh 1 "Tile", a quad with a morph target at weight 0.25).
// "Strip" has two primitives (materials 0 and 1) sharing its attributes; the animation turns the
// knee and drives TileA's morph weight. Its parts, as importGltf makes them: Body's two
// primitives, TileA's, TileB's.
void writeRiggedAsset(const QString& path, test::GltfWriter::BufferStorage storage)
{
    test::GltfWriter w;
    QJsonObject& json = w.json();
    const auto appendTo = [&json](const char* key, const QJsonValue& value) {
        QJsonArray array = json.value(QLatin1String(key)).toArray();
        array.append(value);
        json.insert(QLatin1String(key), array);
        return int(array.size() - 1);
    };
    // Accessors over views of their own; vertex data's views say so (target 34962).
    const auto data = [&](const void* bytes, std::size_t size, int componentType, int count, const char* type,
                          QJsonObject extra = {}, int target = 0) {
        extra.insert(QStringLiteral("bufferView"),
            w.addBufferView(QByteArray(static_cast<const char*>(bytes), qsizetype(size)), target));
        extra.insert(QStringLiteral("componentType"), componentType);
        extra.insert(QStringLiteral("count"), count);
        extra.insert(QStringLiteral("type"), QLatin1String(type));
        return appendTo("accessors", extra);
    };
    // The image first: the views after it are renumbered when it goes.
    const int image = w.addImageEmbedded(
        test::encodePng(2, 2, 4, std::vector<glm::vec4>(4, glm::vec4(0.8f, 0.2f, 0.1f, 1.0f))),
        QStringLiteral("image/png"));
    const std::vector<glm::vec3> positions {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 2, 0}, {1, 2, 0}};
    const std::vector<glm::vec3> normals(6, glm::vec3(0, 0, 1));
    std::vector<glm::vec2> uvs;
    for (const glm::vec3& p : positions)
        uvs.emplace_back(p.x, 1.0f - 0.5f * p.y);
    const int strip = w.addMesh(positions, normals, uvs, {0, 1, 3, 0, 3, 2}, 0, QStringLiteral("Strip"));
    const std::uint16_t joints[6][4]
        = {{0, 0, 0, 0}, {0, 0, 0, 0}, {0, 1, 0, 0}, {0, 1, 0, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}};
    const float weights[6][4]
        = {{1, 0, 0, 0}, {1, 0, 0, 0}, {0.5f, 0.5f, 0, 0}, {0.5f, 0.5f, 0, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}};
    const int jointsAccessor = data(joints, sizeof(joints), 5123, 6, "VEC4", {}, 34962);
    const int weightsAccessor = data(weights, sizeof(weights), 5126, 6, "VEC4", {}, 34962);
    QJsonObject meshJson = json.value(QStringLiteral("meshes")).toArray().at(strip).toObject();
    QJsonObject lower = meshJson.value(QStringLiteral("primitives")).toArray().at(0).toObject();
    QJsonObject attributes = lower.value(QStringLiteral("attributes")).toObject();
    attributes.insert(QStringLiteral("JOINTS_0"), jointsAccessor);
    attributes.insert(QStringLiteral("WEIGHTS_0"), weightsAccessor);
    lower.insert(QStringLiteral("attributes"), attributes);
    QJsonObject upper = lower;
    upper.insert(QStringLiteral("indices"), w.addIndexAccessor({2, 3, 5, 2, 5, 4}));
    upper.insert(QStringLiteral("material"), 1);
    meshJson.insert(QStringLiteral("primitives"), QJsonArray {lower, upper});
    meshJson.insert(QStringLiteral("extras"), QJsonObject {{QStringLiteral("lod"), 0}});
    QJsonArray meshes = json.value(QStringLiteral("meshes")).toArray();
    meshes.replace(strip, meshJson);
    json.insert(QStringLiteral("meshes"), meshes);

    const int tile = w.addQuad(1, 0.0f, QStringLiteral("Tile"));
    const int displacement
        = w.addFloatAccessor({0, 0, 0.5f, 0, 0, 0.5f, 0, 0, 0.5f, 0, 0, 0.5f}, 3, /*withMinMax=*/true);
    w.setPrimitive(tile, QStringLiteral("targets"),
        QJsonArray {QJsonObject {{QStringLiteral("POSITION"), displacement}}});
    meshes = json.value(QStringLiteral("meshes")).toArray();
    QJsonObject tileJson = meshes.at(tile).toObject();
    tileJson.insert(QStringLiteral("weights"), test::jsonNumbers({0.25}));
    meshes.replace(tile, tileJson);
    json.insert(QStringLiteral("meshes"), meshes);

    float inverseBind[2][16] = {};
    for (int j = 0; j < 2; ++j) {
        for (int d = 0; d < 4; ++d)
            inverseBind[j][d * 5] = 1.0f;
        inverseBind[j][13] = -1.0f - float(j); // translation y: the joints at 1 and 2
    }
    const int ibm = data(inverseBind, sizeof(inverseBind), 5126, 2, "MAT4");
    const float times[] = {0.0f, 1.0f};
    const int input = data(times, sizeof(times), 5126, 2, "SCALAR",
        QJsonObject {{QStringLiteral("min"), test::jsonNumbers({0.0})},
            {QStringLiteral("max"), test::jsonNumbers({1.0})}});
    const float rotations[] = {0, 0, 0, 1, 0, 0, 0.38268343f, 0.92387953f};
    const int rotation = data(rotations, sizeof(rotations), 5126, 2, "VEC4");
    const float morphWeights[] = {0.25f, 1.0f};
    const int morph = data(morphWeights, sizeof(morphWeights), 5126, 2, "SCALAR");

    const int texture = w.addTexture(image);
    w.addMaterial(QJsonObject {{QStringLiteral("name"), QStringLiteral("Skin")},
        {QStringLiteral("pbrMetallicRoughness"),
            QJsonObject {{QStringLiteral("baseColorTexture"), test::textureInfo(texture)}}},
        {QStringLiteral("extensions"),
            QJsonObject {{QStringLiteral("KHR_materials_clearcoat"),
                QJsonObject {{QStringLiteral("clearcoatFactor"), 1.0}}}}}});
    w.addMaterial(QJsonObject {{QStringLiteral("name"), QStringLiteral("Cloth")}});
    json.insert(QStringLiteral("extensionsUsed"), QJsonArray {QStringLiteral("KHR_materials_clearcoat")});

    const auto node = [](const char* name, QJsonObject fields = {}) {
        fields.insert(QStringLiteral("name"), QLatin1String(name));
        return fields;
    };
    json.insert(QStringLiteral("nodes"),
        QJsonArray {node("Root",
                        {{QStringLiteral("children"), QJsonArray {2, 4, 5}},
                            {QStringLiteral("extras"), QJsonObject {{QStringLiteral("id"), 7}}}}),
            node("Body", {{QStringLiteral("mesh"), strip}, {QStringLiteral("skin"), 0}}),
            node("Hip",
                {{QStringLiteral("translation"), test::jsonNumbers({0, 1, 0})},
                    {QStringLiteral("children"), QJsonArray {3}}}),
            node("Knee",
                {{QStringLiteral("translation"), test::jsonNumbers({0, 1, 0})},
                    {QStringLiteral("rotation"), test::jsonNumbers({0, 0, 0, 1})}}),
            node("TileA",
                {{QStringLiteral("mesh"), tile},
                    {QStringLiteral("translation"), test::jsonNumbers({2, 0, 0})}}),
            node("TileB",
                {{QStringLiteral("mesh"), tile},
                    {QStringLiteral("translation"), test::jsonNumbers({4, 0, 0})}})});
    json.insert(QStringLiteral("scene"), 0);
    // The skinned node is a root (the validator's NODE_SKINNED_MESH_NON_ROOT), and the first.
    json.insert(
        QStringLiteral("scenes"), QJsonArray {QJsonObject {{QStringLiteral("nodes"), QJsonArray {1, 0}}}});
    json.insert(QStringLiteral("skins"),
        QJsonArray {QJsonObject {{QStringLiteral("joints"), QJsonArray {2, 3}},
            {QStringLiteral("inverseBindMatrices"), ibm}, {QStringLiteral("skeleton"), 2}}});
    const auto channel = [](int sampler, int target, const char* property) {
        return QJsonObject {{QStringLiteral("sampler"), sampler},
            {QStringLiteral("target"),
                QJsonObject {
                    {QStringLiteral("node"), target}, {QStringLiteral("path"), QLatin1String(property)}}}};
    };
    json.insert(QStringLiteral("animations"),
        QJsonArray {QJsonObject {{QStringLiteral("name"), QStringLiteral("Bend")},
            {QStringLiteral("channels"), QJsonArray {channel(0, 3, "rotation"), channel(1, 4, "weights")}},
            {QStringLiteral("samplers"),
                QJsonArray {
                    QJsonObject {{QStringLiteral("input"), input}, {QStringLiteral("output"), rotation}},
                    QJsonObject {{QStringLiteral("input"), input}, {QStringLiteral("output"), morph}}}}}});
    json.insert(QStringLiteral("extras"), QJsonObject {{QStringLiteral("note"), QStringLiteral("kept")}});
    QString error;
    QVERIFY2(w.write(path, storage, &error), qPrintable(error));
}

// Every accessor's elements as floats, per accessor: the data an asset's skins, animations, morph
// targets and meshes read.
std::vector<std::vector<float>> accessorValues(const QString& path)
{
    tinygltf::Model model;
    std::string problem;
    std::vector<std::vector<float>> values;
    if (!gltfmodel::loadModel(path.toStdString(), std::size_t(1) << 30, model, &problem, nullptr))
        return values;
    for (std::size_t a = 0; a < model.accessors.size(); ++a) {
        const int components = tinygltf::GetNumComponentsInType(std::uint32_t(model.accessors[a].type));
        const auto view = gltfmodel::accessorView(model, int(a), components, "accessor", &problem);
        std::vector<float>& out = values.emplace_back();
        for (std::size_t i = 0; view && i < view->count; ++i)
            for (int c = 0; c < components; ++c)
                out.push_back(gltfmodel::component(*view, i, c));
    }
    return values;
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

    void roundTrip_data()
    {
        QTest::addColumn<QString>("feature");
        QTest::addColumn<bool>("binary");
        for (const char* feature : {"constants", "every map", "shared transform", "different transforms",
                 "ior", "clearcoat", "clearcoat, smooth", "unlit, clearcoat", "clearcoat maps",
                 "clearcoat maps, coat off", "sheen", "sheen maps", "sheen maps, sheen off", "unlit, sheen",
                 "clearcoat and sheen maps", "specular", "specular maps", "mask", "blend", "single-sided",
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
                            std::abs(ia.specular - ib.specular)});
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

    // An asset exported from its own file keeps what Facet does not edit (issue 29): the same
    // scenes, nodes (names, transforms, hierarchy, skins, extras), skins, animations, morph targets
    // and weights, every accessor's data, validator-clean; only the materials and textures are
    // Facet's. A mesh two nodes show with different materials is copied for the second; the
    // source's embedded image and its material extension go with its materials.
    void keepsTheAsset_data()
    {
        QTest::addColumn<QString>("source");
        QTest::addColumn<bool>("binary");
        for (const char* source : {"rigged .gltf", "rigged .glb", "AnimatedMorphCube"})
            for (const bool binary : {false, true})
                QTest::newRow(qPrintable(QStringLiteral("%1 -> %2")
                                             .arg(QLatin1String(source),
                                                 binary ? QStringLiteral(".glb") : QStringLiteral(".gltf"))))
                    << QString::fromLatin1(source) << binary;
    }

    void keepsTheAsset()
    {
        QFETCH(QString, source);
        QFETCH(bool, binary);
        QTemporaryDir dir;
        const bool rigged = source.startsWith(QStringLiteral("rigged"));
        QString sourcePath;
        if (rigged) {
            sourcePath = dir.filePath(source.endsWith(QStringLiteral(".glb")) ? QStringLiteral("rig.glb")
                                                                              : QStringLiteral("rig.gltf"));
            writeRiggedAsset(sourcePath,
                source.endsWith(QStringLiteral(".glb")) ? test::GltfWriter::BufferStorage::Glb
                                                        : test::GltfWriter::BufferStorage::DataUri);
            if (QTest::currentTestFailed())
                return;
        } else {
            sourcePath = test::sourceDir()
                + QStringLiteral("/tests/data/gltf/AnimatedMorphCube/AnimatedMorphCube.gltf");
        }
        FACET_REQUIRE_VALID_GLTF(sourcePath);
        std::string error;
        const std::optional<GltfAsset> before = importGltf(sourcePath.toStdString(), &error);
        QVERIFY2(before, error.c_str());

        Material red, blue;
        red.name = "Red";
        red.setBaseColor(glm::dvec3(0.8, 0.1, 0.1));
        blue.name = "Blue";
        blue.setBaseColor(glm::dvec3(0.1, 0.2, 0.8));
        blue.ior = 1.4;
        const std::vector<Material> materials {red, blue};
        // Body's primitives swapped; TileA and TileB (one mesh in the file) given different ones.
        const std::vector<int> parts = rigged ? std::vector<int> {1, 0, 0, 1} : std::vector<int> {1};
        QCOMPARE(before->mesh.subMeshes.size(), parts.size());

        const QString path
            = dir.filePath(binary ? QStringLiteral("out/kept.glb") : QStringLiteral("out/kept.gltf"));
        GltfExportOptions options;
        options.binary = binary;
        options.source = viewMeshGltfFile(sourcePath.toStdString());
        QCOMPARE(QString::fromStdString(options.source), sourcePath);
        Mesh fitted = before->mesh;
        fitted.normalizeToUnitSphere(); // what the view holds: the export writes the file's units anyway
        QVERIFY2(
            writeGltfAsset(path.toStdString(), fitted, parts, materials, options, false, nullptr, &error),
            error.c_str());
        FACET_REQUIRE_VALID_GLTF(path);

        const QJsonObject in = assetJson(sourcePath);
        const QJsonObject out = assetJson(path);
        for (const char* key : {"scene", "scenes", "skins", "animations", "extras"})
            QVERIFY2(out.value(QLatin1String(key)) == in.value(QLatin1String(key)), key);
        QCOMPARE(out.value(QStringLiteral("accessors")).toArray().size(),
            in.value(QStringLiteral("accessors")).toArray().size());
        // Every accessor reads the same numbers.
        const std::vector<std::vector<float>> valuesIn = accessorValues(sourcePath);
        const std::vector<std::vector<float>> valuesOut = accessorValues(path);
        QVERIFY(!valuesIn.empty());
        QCOMPARE(valuesOut.size(), valuesIn.size());
        for (std::size_t a = 0; a < valuesIn.size(); ++a)
            QVERIFY2(valuesOut[a] == valuesIn[a], qPrintable(QStringLiteral("accessor %1").arg(a)));

        // Nodes as they were, but TileB on the copy of the shared mesh; meshes as they were, but
        // their materials.
        QJsonArray expectedNodes = in.value(QStringLiteral("nodes")).toArray();
        const QJsonArray inMeshes = in.value(QStringLiteral("meshes")).toArray();
        const QJsonArray outMeshes = out.value(QStringLiteral("meshes")).toArray();
        const auto withoutMaterials = [](QJsonObject mesh) {
            QJsonArray primitives = mesh.value(QStringLiteral("primitives")).toArray();
            for (qsizetype p = 0; p < primitives.size(); ++p) {
                QJsonObject primitive = primitives.at(p).toObject();
                primitive.remove(QStringLiteral("material"));
                primitives.replace(p, primitive);
            }
            mesh.insert(QStringLiteral("primitives"), primitives);
            return mesh;
        };
        const auto materialsOf = [](const QJsonObject& mesh) {
            std::vector<int> result;
            for (const QJsonValue& primitive : mesh.value(QStringLiteral("primitives")).toArray())
                result.push_back(primitive.toObject().value(QStringLiteral("material")).toInt(-1));
            return result;
        };
        if (rigged) {
            QJsonObject tileB = expectedNodes.at(5).toObject();
            tileB.insert(QStringLiteral("mesh"), 2);
            expectedNodes.replace(5, tileB);
            QCOMPARE(outMeshes.size(), 3);
            QCOMPARE(
                withoutMaterials(outMeshes.at(2).toObject()), withoutMaterials(inMeshes.at(1).toObject()));
            QCOMPARE(materialsOf(outMeshes.at(0).toObject()), (std::vector<int> {1, 0}));
            QCOMPARE(materialsOf(outMeshes.at(1).toObject()), (std::vector<int> {0}));
            QCOMPARE(materialsOf(outMeshes.at(2).toObject()), (std::vector<int> {1}));
            // The embedded image's view is gone with the source's materials, and so is its extension.
            QVERIFY(!out.value(QStringLiteral("extensionsUsed"))
                         .toArray()
                         .contains(QStringLiteral("KHR_materials_clearcoat")));
            QCOMPARE(out.value(QStringLiteral("bufferViews")).toArray().size(),
                in.value(QStringLiteral("bufferViews")).toArray().size() - 1);
        } else {
            QCOMPARE(outMeshes.size(), inMeshes.size());
            QCOMPARE(materialsOf(outMeshes.at(0).toObject()), (std::vector<int> {1}));
        }
        QCOMPARE(out.value(QStringLiteral("nodes")).toArray(), expectedNodes);
        for (qsizetype m = 0; m < inMeshes.size(); ++m)
            QCOMPARE(
                withoutMaterials(outMeshes.at(m).toObject()), withoutMaterials(inMeshes.at(m).toObject()));
        const QJsonArray outMaterials = out.value(QStringLiteral("materials")).toArray();
        QCOMPARE(outMaterials.size(), 2);
        QCOMPARE(
            outMaterials.at(0).toObject().value(QStringLiteral("name")).toString(), QStringLiteral("Red"));
        QCOMPARE(
            outMaterials.at(1).toObject().value(QStringLiteral("name")).toString(), QStringLiteral("Blue"));
        QVERIFY(out.value(QStringLiteral("extensionsUsed"))
                    .toArray()
                    .contains(QStringLiteral("KHR_materials_ior")));

        // Read back: the same geometry where every node puts it, each part with its material.
        const std::optional<GltfAsset> after = importGltf(path.toStdString(), &error);
        QVERIFY2(after, error.c_str());
        QCOMPARE(after->mesh.vertices.size(), before->mesh.vertices.size());
        for (std::size_t v = 0; v < before->mesh.vertices.size(); ++v)
            QVERIFY(
                glm::length(after->mesh.vertices[v].position - before->mesh.vertices[v].position) < 1e-6f);
        QCOMPARE(after->mesh.subMeshes.size(), parts.size());
        for (std::size_t p = 0; p < parts.size(); ++p)
            QCOMPARE(after->mesh.subMeshes[p].materialIndex, parts[p]);
        QCOMPARE(after->materials[1].name, std::string("Blue"));
        QVERIFY(std::abs(after->materials[1].ior - 1.4) < 1e-9);
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
