// core/gltf/GltfExport writing back the asset it came from (issue 29): a skinned, animated asset
// with a node hierarchy, morph targets, an instanced mesh, extras, an embedded image and a material
// extension Facet does not write, and the AnimatedMorphCube sample, each to .gltf and .glb: the
// scenes, nodes, skins, animations, morph targets and accessors come back as they were, only the
// materials and textures are Facet's, and every file passes the Khronos glTF-Validator. (The
// materials' own round trip, feature by feature: GltfExportTest.)

#include <cmath>
#include <cstring>

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
#include "core/mesh/MeshPrimitives.h"
#include "core/project/AssetProject.h"
#include "core/project/ProjectAssets.h"

using namespace facet;

namespace {

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

class GltfAssetExportTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
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
};

QTEST_GUILESS_MAIN(GltfAssetExportTest)
#include "GltfAssetExportTest.moc"
