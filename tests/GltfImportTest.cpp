// glTF assets in (core/gltf/GltfImport.h): small files the test writes itself (support/GltfWriter),
// one row per feature of the material model and the geometry, in each buffer storage (external
// .bin, data URI, .glb), and a table of broken files that must each give a clear message.

#include "core/gltf/GltfImport.h"
#include "core/image/Image.h"
#include "core/mesh/MeshImport.h"

#include "GltfWriter.h"
#include "TestSupport.h"

#include <QFile>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <cmath>
#include <cstring>
#include <numbers>

#include <sys/stat.h>

using namespace facet;
using facet::test::GltfWriter;
using facet::test::jsonNumbers;
using facet::test::textureInfo;
using Storage = GltfWriter::BufferStorage;

Q_DECLARE_METATYPE(GltfWriter::BufferStorage)

namespace {



// A 4 x 4 RGBA texture whose channels hold distinct constant values: R 0.2, G 0.4, B 0.6, A 0.8.
QByteArray packedPng()
{
    return facet::test::encodePng(4, 4, 4, std::vector<glm::vec4>(16, glm::vec4(0.2f, 0.4f, 0.6f, 0.8f)));
}

bool near(double a, double b, double tolerance = 1e-6)
{
    return std::abs(a - b) <= tolerance;
}

// The asset's JSON text with `insert` placed right after its opening brace (a .gltf's whole
// text, a .glb's JSON chunk, padded and the lengths rewritten).
bool insertIntoJson(const QString& file, const QByteArray& insert)
{
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly))
        return false;
    QByteArray bytes = f.readAll();
    f.close();
    if (bytes.startsWith("glTF")) {
        const auto u32 = [&bytes](int at) {
            std::uint32_t v = 0;
            std::memcpy(&v, bytes.constData() + at, 4);
            return v;
        };
        const qsizetype jsonLength = qsizetype(u32(12));
        QByteArray json = bytes.mid(20, jsonLength);
        json.insert(json.indexOf('{') + 1, insert);
        while (json.size() % 4 != 0)
            json.append(' ');
        const QByteArray rest = bytes.mid(20 + jsonLength);
        QByteArray out = bytes.left(12);
        const auto put = [&out](std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
        put(std::uint32_t(json.size()));
        put(0x4E4F534A);
        out.append(json);
        out.append(rest);
        const std::uint32_t total = std::uint32_t(out.size());
        std::memcpy(out.data() + 8, &total, 4);
        bytes = out;
    } else {
        bytes.insert(bytes.indexOf('{') + 1, insert);
    }
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return false;
    return f.write(bytes) == bytes.size();
}

} // namespace

class GltfImportTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }

private Q_SLOTS:
    void materialFactorsAndMaps_data();
    void materialFactorsAndMaps();
    void embeddedImagesDecode_data();
    void embeddedImagesDecode();
    void textureTransformMatchesTheSampleRenderer();
    void severalMaterialsKeepTheirParts();
    void geometryConventions();
    void nodeTransformsAndModes();
    void brokenFilesGiveClearMessages_data();
    void brokenFilesGiveClearMessages();
    void deepNodeGraphDoesNotOverflow();
    void deeplyNestedJsonIsRefused_data();
    void deeplyNestedJsonIsRefused();
    void meshImportReadsGltfThroughThisReader();
    void materialsOnlyListsTheSameParts();
    void corruptedFilesNeverCrash();
};

void GltfImportTest::materialFactorsAndMaps_data()
{
    QTest::addColumn<Storage>("storage");
    QTest::newRow("external .bin") << Storage::ExternalFile;
    QTest::newRow("data URI") << Storage::DataUri;
    QTest::newRow(".glb") << Storage::Glb;
}

// Every field of the material model, read from one material that sets all of them.
void GltfImportTest::materialFactorsAndMaps()
{
    QFETCH(Storage, storage);
    GltfWriter w;
    const int packed = w.addTexture(w.addImageEmbedded(packedPng(), QStringLiteral("image/png")));
    const int color = w.addTexture(w.addImageUri(QStringLiteral("base%20colour.png")));
    QJsonObject pbr;
    pbr[QLatin1String("baseColorFactor")] = jsonNumbers({0.5, 0.25, 0.125, 0.75});
    pbr[QLatin1String("baseColorTexture")] = textureInfo(color);
    pbr[QLatin1String("metallicFactor")] = 0.3;
    pbr[QLatin1String("roughnessFactor")] = 0.7;
    pbr[QLatin1String("metallicRoughnessTexture")] = textureInfo(packed);
    QJsonObject material;
    material[QLatin1String("name")] = QLatin1String("Everything");
    material[QLatin1String("pbrMetallicRoughness")] = pbr;
    QJsonObject normal = textureInfo(packed);
    normal[QLatin1String("scale")] = 1.5;
    material[QLatin1String("normalTexture")] = normal;
    QJsonObject occlusion = textureInfo(packed);
    occlusion[QLatin1String("strength")] = 0.6;
    material[QLatin1String("occlusionTexture")] = occlusion;
    QJsonObject transform;
    transform[QLatin1String("offset")] = jsonNumbers({0.25, 0.5});
    transform[QLatin1String("rotation")] = 0.3;
    transform[QLatin1String("scale")] = jsonNumbers({2.0, 3.0});
    QJsonObject transformExtension;
    transformExtension[QLatin1String("KHR_texture_transform")] = transform;
    material[QLatin1String("emissiveTexture")] = textureInfo(color, transformExtension);
    material[QLatin1String("emissiveFactor")] = jsonNumbers({1.0, 0.5, 0.0});
    material[QLatin1String("alphaMode")] = QLatin1String("MASK");
    material[QLatin1String("alphaCutoff")] = 0.35;
    material[QLatin1String("doubleSided")] = true;
    QJsonObject strength;
    strength[QLatin1String("emissiveStrength")] = 4.0;
    QJsonObject ior;
    ior[QLatin1String("ior")] = 1.33;
    QJsonObject extensions;
    extensions[QLatin1String("KHR_materials_emissive_strength")] = strength;
    extensions[QLatin1String("KHR_materials_ior")] = ior;
    material[QLatin1String("extensions")] = extensions;
    w.addNode(w.addQuad(w.addMaterial(material)));
    w.json()[QLatin1String("extensionsUsed")]
        = QJsonArray {QStringLiteral("KHR_texture_transform"), QStringLiteral("KHR_materials_emissive_strength"),
                      QStringLiteral("KHR_materials_ior")};

    const QString file = path(storage == Storage::Glb ? QStringLiteral("all.glb") : QStringLiteral("all.gltf"));
    QString writeError;
    QVERIFY2(w.write(file, storage, &writeError), qPrintable(writeError));
    std::string error, warning;
    const auto asset = importGltf(file.toStdString(), &error, &warning);
    QVERIFY2(asset, error.c_str());
    QCOMPARE(asset->materials.size(), std::size_t(1));
    const Material& m = asset->materials[0];
    std::string problem;
    QVERIFY2(m.validate(&problem), problem.c_str());
    QCOMPARE(m.name, std::string("Everything"));
    QCOMPARE(m.baseColorFactor(), glm::dvec4(0.5, 0.25, 0.125, 0.75));
    QVERIFY(near(m.metallic(), 0.3) && near(m.roughness(), 0.7));
    QVERIFY(near(m.normalStrength(), 1.5) && near(m.occlusionStrength(), 0.6));
    QCOMPARE(glm::dvec3(m.map(MapSlot::Emissive).factor), glm::dvec3(1.0, 0.5, 0.0));
    QVERIFY(near(m.emissiveStrength, 4.0) && near(m.ior, 1.33));
    QCOMPARE(m.alphaMode, AlphaMode::Mask);
    QVERIFY(near(m.alphaCutoff, 0.35));
    QVERIFY(m.doubleSided);

    // Maps: the packed texture feeds metallic (B), roughness (G), occlusion (R) and the normal;
    // the external image is resolved (percent-decoded) against the asset's folder.
    const std::string embedded = gltfImageReference(file.toStdString(), 0);
    const std::string external = path(QStringLiteral("base colour.png")).toStdString();
    QCOMPARE(m.map(MapSlot::BaseColor).path, external);
    QCOMPARE(m.map(MapSlot::BaseColor).colorSpace, ColorEncoding::SRGB);
    QCOMPARE(m.map(MapSlot::Metallic).path, embedded);
    QCOMPARE(m.map(MapSlot::Metallic).channel, MapChannel::B);
    QCOMPARE(m.map(MapSlot::Roughness).path, embedded);
    QCOMPARE(m.map(MapSlot::Roughness).channel, MapChannel::G);
    QCOMPARE(m.map(MapSlot::Occlusion).channel, MapChannel::R);
    QCOMPARE(m.map(MapSlot::Normal).path, embedded);
    QCOMPARE(m.map(MapSlot::Emissive).path, external);
    QCOMPARE(m.map(MapSlot::Emissive).colorSpace, ColorEncoding::SRGB);
    QCOMPARE(m.map(MapSlot::Emissive).uv, gltfTextureTransform({0.25, 0.5}, 0.3, {2.0, 3.0}));
    QVERIFY(m.map(MapSlot::BaseColor).uv.isIdentity());
    // The external image does not exist: the import says so (the map keeps its path for relinking).
    QVERIFY2(QString::fromStdString(warning).contains(QStringLiteral("image 'base colour.png' is missing")), warning.c_str());
}

void GltfImportTest::embeddedImagesDecode_data()
{
    QTest::addColumn<Storage>("storage");
    QTest::newRow("bufferView in .glb") << Storage::Glb;
    QTest::newRow("bufferView in a data-URI buffer") << Storage::DataUri;
}

// Image::load reads an embedded image through its reference, with the file's pixel values.
void GltfImportTest::embeddedImagesDecode()
{
    QFETCH(Storage, storage);
    GltfWriter w;
    QJsonObject pbr;
    pbr[QLatin1String("baseColorTexture")] = textureInfo(w.addTexture(w.addImageEmbedded(packedPng(), QStringLiteral("image/png"))));
    QJsonObject material;
    material[QLatin1String("pbrMetallicRoughness")] = pbr;
    w.addNode(w.addQuad(w.addMaterial(material)));
    const QString file = path(storage == Storage::Glb ? QStringLiteral("img.glb") : QStringLiteral("img.gltf"));
    QVERIFY(w.write(file, storage));
    std::string error;
    const auto asset = importGltf(file.toStdString(), &error);
    QVERIFY2(asset, error.c_str());
    const std::string reference = asset->materials[0].map(MapSlot::BaseColor).path;
    QCOMPARE(fileOfImagePath(reference), file.toStdString());
    const auto image = Image::load(reference, &error);
    QVERIFY2(image, error.c_str());
    QCOMPARE(image->width(), 4);
    QCOMPARE(image->sourceChannels(), 4);
    const glm::vec4 texel = image->at(1, 2);
    QVERIFY(near(texel.r, 51 / 255.0) && near(texel.g, 102 / 255.0) && near(texel.b, 153 / 255.0)
            && near(texel.a, 204 / 255.0));
    // A reference to an image the asset does not have names the asset and the index.
    const auto missing = Image::load(gltfImageReference(file.toStdString(), 7), &error);
    QVERIFY(!missing);
    QVERIFY2(QString::fromStdString(error).contains(QStringLiteral("#images/7"))
                 && QString::fromStdString(error).contains(QStringLiteral("has 1 images")),
             error.c_str());
}

// gltfTextureTransform reads the same texel as glTF's own rule: glTF samples the image at
// uv' = T R(-rotation) S uv with (0, 0) the top-left corner; Facet samples at its own uv' =
// T' R' S' uv_f with uv_f = (u, 1 - v) and (0, 0) the bottom-left corner. Both must name the same
// image point. KHR_texture_transform as the Khronos glTF Sample Viewer applies it (source/gltf/material.js:
// rotation [c, -s, 0, s, c, 0, 0, 0, 1] given to gl-matrix, which takes columns), in glTF's UV
// space, against Facet's transform of the same texels in its own (issue 29: the rotation ran the
// other way, as the extension README's GLSL reads).
void GltfImportTest::textureTransformMatchesTheSampleRenderer()
{
    const auto gltfMatrix = [](glm::dvec2 offset, double rotation, glm::dvec2 scale) {
        const glm::dmat3 t(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
        const glm::dmat3 r(
            std::cos(rotation), -std::sin(rotation), 0, std::sin(rotation), std::cos(rotation), 0, 0, 0, 1);
        const glm::dmat3 s(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
        return t * r * s;
    };
    struct Case {
        glm::dvec2 offset;
        double rotation;
        glm::dvec2 scale;
    };
    const Case cases[] = {{{0, 0}, 0, {1, 1}}, {{0.5, 0}, 0, {1, 1}}, {{0, 0.5}, 0, {1, 1}}, {{0, 0}, 0.392699, {1, 1}},
                          {{0, 0}, 0, {1.5, 1.5}}, {{0, 1}, std::numbers::pi / 2, {0.5, 0.5}}, {{0.2, -0.3}, -1.1, {2, 0.7}}};
    for (const Case& c : cases) {
        const UvTransform facetUv = gltfTextureTransform(c.offset, c.rotation, c.scale);
        for (const glm::dvec2 uv : {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(0.3, 0.8), glm::dvec2(0.9, 0.1)}) {
            const glm::dvec3 g = gltfMatrix(c.offset, c.rotation, c.scale) * glm::dvec3(uv, 1.0);
            const glm::dvec2 imagePointGltf(g.x, g.y); // x right, y down from the top-left
            const glm::dvec2 f = facetUv.apply({uv.x, 1.0 - uv.y});
            const glm::dvec2 imagePointFacet(f.x, 1.0 - f.y); // back to top-left origin
            QVERIFY2(glm::length(imagePointGltf - imagePointFacet) < 1e-12,
                     qPrintable(QStringLiteral("offset (%1, %2) rotation %3 scale (%4, %5)")
                                    .arg(c.offset.x)
                                    .arg(c.offset.y)
                                    .arg(c.rotation)
                                    .arg(c.scale.x)
                                    .arg(c.scale.y)));
        }
    }
}

// Two materials on two primitives, and a primitive without one (glTF's default material).
void GltfImportTest::severalMaterialsKeepTheirParts()
{
    GltfWriter w;
    QJsonObject red, blue;
    QJsonObject redPbr, bluePbr;
    redPbr[QLatin1String("baseColorFactor")] = jsonNumbers({1, 0, 0, 1});
    bluePbr[QLatin1String("baseColorFactor")] = jsonNumbers({0, 0, 1, 1});
    red[QLatin1String("name")] = QLatin1String("Red");
    red[QLatin1String("pbrMetallicRoughness")] = redPbr;
    blue[QLatin1String("name")] = QLatin1String("Blue");
    blue[QLatin1String("pbrMetallicRoughness")] = bluePbr;
    const int redIndex = w.addMaterial(red);
    const int blueIndex = w.addMaterial(blue);
    w.addNode(w.addQuad(blueIndex, 0.0f, QStringLiteral("front")));
    w.addNode(w.addQuad(redIndex, -1.0f, QStringLiteral("back")));
    w.addNode(w.addQuad(-1, -2.0f, QStringLiteral("plain")));
    const QString file = path(QStringLiteral("three.glb"));
    QVERIFY(w.write(file, Storage::Glb));
    std::string error;
    const auto asset = importGltf(file.toStdString(), &error);
    QVERIFY2(asset, error.c_str());
    QCOMPARE(asset->materials.size(), std::size_t(3));
    QCOMPARE(asset->materials[0].name, std::string("Red"));
    QCOMPARE(asset->materials[1].name, std::string("Blue"));
    QCOMPARE(asset->materials[2].name, std::string("Default"));
    QCOMPARE(asset->materials[2].metallic(), 1.0);
    QCOMPARE(asset->materials[2].roughness(), 1.0);
    QVERIFY(!asset->materials[2].doubleSided);
    QCOMPARE(asset->mesh.subMeshes.size(), std::size_t(3));
    QCOMPARE(asset->mesh.subMeshes[0].name, std::string("front"));
    QCOMPARE(asset->mesh.subMeshes[0].materialIndex, blueIndex);
    QCOMPARE(asset->mesh.subMeshes[1].materialIndex, redIndex);
    QCOMPARE(asset->mesh.subMeshes[2].materialIndex, 2);
    std::string problem;
    QVERIFY2(asset->mesh.validate(&problem), problem.c_str());
}

// UVs flip to Facet's bottom-left origin, normals and generated tangents follow glTF's frame.
void GltfImportTest::geometryConventions()
{
    GltfWriter w;
    w.addNode(w.addQuad(-1));
    const QString file = path(QStringLiteral("quad.gltf"));
    QVERIFY(w.write(file, Storage::ExternalFile));
    std::string error;
    const auto asset = importGltf(file.toStdString(), &error);
    QVERIFY2(asset, error.c_str());
    const Mesh& mesh = asset->mesh;
    QCOMPARE(mesh.vertices.size(), std::size_t(4));
    QCOMPARE(mesh.triangleCount(), std::size_t(2));
    // Vertex 0 at (-1, -1) has glTF uv (0, 1): the image's bottom-left, Facet's (0, 0).
    QCOMPARE(mesh.vertices[0].uv, glm::vec2(0.0f, 0.0f));
    QCOMPARE(mesh.vertices[2].uv, glm::vec2(1.0f, 1.0f));
    QVERIFY(mesh.hasTangents);
    // u grows along +X, v (Facet) along +Y: the tangent is +X with handedness +1.
    for (const Vertex& v : mesh.vertices) {
        QVERIFY(glm::length(glm::vec3(v.tangent) - glm::vec3(1, 0, 0)) < 1e-5f);
        QCOMPARE(v.tangent.w, 1.0f);
        QVERIFY(glm::length(v.normal - glm::vec3(0, 0, 1)) < 1e-6f);
    }
}

void GltfImportTest::nodeTransformsAndModes()
{
    // A parent translated by (10, 0, 0) and a child mirrored in X: positions move, the winding
    // reverses so the faces still point outward (positive signed area along the normal).
    GltfWriter w;
    const int quad = w.addQuad(-1);
    QJsonObject child;
    child[QLatin1String("mesh")] = quad;
    child[QLatin1String("scale")] = jsonNumbers({-1, 1, 1});
    QJsonObject parent;
    parent[QLatin1String("translation")] = jsonNumbers({10, 0, 0});
    parent[QLatin1String("children")] = QJsonArray {1};
    w.json()[QLatin1String("nodes")] = QJsonArray {parent, child};
    QJsonObject scene;
    scene[QLatin1String("nodes")] = QJsonArray {0};
    w.json()[QLatin1String("scenes")] = QJsonArray {scene};
    const QString file = path(QStringLiteral("mirrored.glb"));
    QVERIFY(w.write(file, Storage::Glb));
    std::string error;
    const auto asset = importGltf(file.toStdString(), &error);
    QVERIFY2(asset, error.c_str());
    const Mesh& mesh = asset->mesh;
    QVERIFY(std::abs(mesh.bounds.center().x - 10.0f) < 1e-5f);
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::vec3 a = mesh.vertices[mesh.indices[t]].position;
        const glm::vec3 b = mesh.vertices[mesh.indices[t + 1]].position;
        const glm::vec3 c = mesh.vertices[mesh.indices[t + 2]].position;
        QVERIFY(glm::dot(glm::cross(b - a, c - a), mesh.vertices[mesh.indices[t]].normal) > 0.0f);
    }

    // A triangle strip of 4 vertices is 2 triangles; a fan of 5 is 3; points are dropped.
    for (const auto& [mode, count, triangles] : {std::tuple {5, 4, 2}, std::tuple {6, 5, 3}, std::tuple {0, 3, 0}}) {
        GltfWriter s;
        std::vector<glm::vec3> positions;
        std::vector<std::uint32_t> indices;
        for (int i = 0; i < count; ++i) {
            const double a = 2.0 * std::numbers::pi * i / count;
            positions.emplace_back(float(std::cos(a)), float(std::sin(a)), 0.0f);
            indices.push_back(std::uint32_t(i));
        }
        const int meshIndex
            = s.addMesh(positions, std::vector<glm::vec3>(positions.size(), glm::vec3(0, 0, 1)), {}, indices, -1);
        QJsonObject m = s.json()[QLatin1String("meshes")].toArray()[meshIndex].toObject();
        QJsonObject primitive = m[QLatin1String("primitives")].toArray()[0].toObject();
        primitive[QLatin1String("mode")] = mode;
        m[QLatin1String("primitives")] = QJsonArray {primitive};
        s.json()[QLatin1String("meshes")] = QJsonArray {m};
        s.addNode(meshIndex);
        if (mode == 0) // points alone: nothing to show
            s.addNode(s.addQuad(-1));
        const QString f = path(QStringLiteral("mode%1.gltf").arg(mode));
        QVERIFY(s.write(f, Storage::DataUri));
        std::string warning;
        const auto strip = importGltf(f.toStdString(), &error, &warning);
        QVERIFY2(strip, error.c_str());
        if (mode == 0) {
            QVERIFY2(QString::fromStdString(warning).contains(QStringLiteral("points or lines dropped")), warning.c_str());
            QCOMPARE(strip->mesh.subMeshes.size(), std::size_t(1)); // the quad only
        } else {
            QCOMPARE(strip->mesh.triangleCount(), std::size_t(triangles));
        }
    }
}

void GltfImportTest::brokenFilesGiveClearMessages_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("message");
    QTest::newRow("missing file") << QStringLiteral("missing") << QStringLiteral("file does not exist");
    QTest::newRow("not glTF") << QStringLiteral("notjson") << QStringLiteral("not a readable glTF file");
    QTest::newRow(".glb cut in half") << QStringLiteral("cut") << QStringLiteral("cut short: its header says");
    QTest::newRow("accessor past its buffer") << QStringLiteral("accessor") << QStringLiteral("reach past the end");
    QTest::newRow("accessor of the wrong type") << QStringLiteral("type") << QStringLiteral("expected 3 components");
    QTest::newRow("index out of range") << QStringLiteral("index") << QStringLiteral("index 99 is out of range");
    QTest::newRow("material out of range") << QStringLiteral("material") << QStringLiteral("names material 5");
    QTest::newRow("node cycle") << QStringLiteral("cycle") << QStringLiteral("reached twice");
    QTest::newRow("required extension") << QStringLiteral("meshopt") << QStringLiteral("EXT_meshopt_compression");
    QTest::newRow("buffer is a device") << QStringLiteral("device") << QStringLiteral("not a regular file");
    QTest::newRow("no triangles") << QStringLiteral("empty") << QStringLiteral("contains no triangles");
    // Issue 29: read as if valid before.
    QTest::newRow("POSITION as UNSIGNED_BYTE without KHR_mesh_quantization")
        << QStringLiteral("position-ubyte")
        << QStringLiteral("POSITION: UNSIGNED_BYTE components need the KHR_mesh_quantization");
    QTest::newRow("NORMAL as UNSIGNED_SHORT") << QStringLiteral(
        "normal-ushort") << QStringLiteral("NORMAL: UNSIGNED_SHORT components are not allowed");
    QTest::newRow("negative accessor byteOffset")
        << QStringLiteral("negative-offset") << QStringLiteral("accessors[0].byteOffset: -12 is negative");
    QTest::newRow("negative bufferView byteLength")
        << QStringLiteral("negative-length") << QStringLiteral("bufferViews[1].byteLength: -4 is negative");
}

void GltfImportTest::brokenFilesGiveClearMessages()
{
    QFETCH(QString, name);
    QFETCH(QString, message);
    GltfWriter w;
    const int mesh = w.addQuad(-1);
    w.addNode(mesh);
    QString file = path(name + QStringLiteral(".gltf"));
    const auto editPrimitive = [&w](const char* key, int value) {
        QJsonObject m = w.json()[QLatin1String("meshes")].toArray()[0].toObject();
        QJsonObject p = m[QLatin1String("primitives")].toArray()[0].toObject();
        p[QLatin1String(key)] = value;
        m[QLatin1String("primitives")] = QJsonArray {p};
        w.json()[QLatin1String("meshes")] = QJsonArray {m};
    };
    Storage storage = Storage::DataUri;
    if (name == QLatin1String("notjson")) {
        QFile f(file);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("this is not glTF\n");
    } else if (name == QLatin1String("cut")) {
        file = path(QStringLiteral("cut.glb"));
        QVERIFY(w.write(file, Storage::Glb));
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadWrite));
        QVERIFY(f.resize(f.size() / 2));
    } else if (name == QLatin1String("accessor")) {
        QJsonArray accessors = w.json()[QLatin1String("accessors")].toArray();
        QJsonObject a = accessors[0].toObject();
        a[QLatin1String("count")] = 1000;
        accessors[0] = a;
        w.json()[QLatin1String("accessors")] = accessors;
    } else if (name == QLatin1String("type")) {
        QJsonArray accessors = w.json()[QLatin1String("accessors")].toArray();
        QJsonObject a = accessors[0].toObject();
        a[QLatin1String("type")] = QLatin1String("VEC2");
        accessors[0] = a;
        w.json()[QLatin1String("accessors")] = accessors;
    } else if (name == QLatin1String("index")) {
        GltfWriter bad;
        bad.addNode(bad.addMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {}, {}, {0, 1, 99}, -1));
        w = bad;
    } else if (name == QLatin1String("material")) {
        editPrimitive("material", 5);
    } else if (name == QLatin1String("cycle")) {
        QJsonObject a, b;
        a[QLatin1String("mesh")] = 0;
        a[QLatin1String("children")] = QJsonArray {1};
        b[QLatin1String("children")] = QJsonArray {0};
        w.json()[QLatin1String("nodes")] = QJsonArray {a, b};
    } else if (name == QLatin1String("meshopt")) {
        w.json()[QLatin1String("extensionsRequired")] = QJsonArray {QStringLiteral("EXT_meshopt_compression")};
        w.json()[QLatin1String("extensionsUsed")] = QJsonArray {QStringLiteral("EXT_meshopt_compression")};
    } else if (name == QLatin1String("position-ubyte") || name == QLatin1String("normal-ushort")
        || name == QLatin1String("negative-offset")) {
        QJsonArray accessors = w.json()[QLatin1String("accessors")].toArray();
        const int index = name == QLatin1String("normal-ushort") ? 1 : 0; // addQuad: POSITION, NORMAL, ...
        QJsonObject a = accessors[index].toObject();
        if (name == QLatin1String("negative-offset")) {
            a[QLatin1String("byteOffset")] = -12;
        } else {
            a[QLatin1String("componentType")] = name == QLatin1String("normal-ushort") ? 5123 : 5121;
            a.remove(QLatin1String("min"));
            a.remove(QLatin1String("max"));
        }
        accessors[index] = a;
        w.json()[QLatin1String("accessors")] = accessors;
    } else if (name == QLatin1String("negative-length")) {
        QJsonArray views = w.json()[QLatin1String("bufferViews")].toArray();
        QJsonObject v = views[1].toObject();
        v[QLatin1String("byteLength")] = -4;
        views[1] = v;
        w.json()[QLatin1String("bufferViews")] = views;
    } else if (name == QLatin1String("device")) {
        storage = Storage::ExternalFile;
    } else if (name == QLatin1String("empty")) {
        GltfWriter bad;
        bad.addNode(-1);
        w = bad;
    }
    if (name != QLatin1String("missing") && name != QLatin1String("notjson") && name != QLatin1String("cut"))
        QVERIFY(w.write(file, storage));
    if (name == QLatin1String("device")) {
        // Point the buffer at a FIFO next to the asset: it must be refused, not waited on forever.
        QVERIFY(::mkfifo(path(QStringLiteral("pipe.bin")).toLocal8Bit().constData(), 0600) == 0);
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QJsonObject json = QJsonDocument::fromJson(f.readAll()).object();
        f.close();
        QJsonArray buffers = json[QLatin1String("buffers")].toArray();
        QJsonObject buffer = buffers[0].toObject();
        buffer[QLatin1String("uri")] = QLatin1String("pipe.bin");
        buffers[0] = buffer;
        json[QLatin1String("buffers")] = buffers;
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(QJsonDocument(json).toJson());
    }
    std::string error;
    const auto asset = importGltf(file.toStdString(), &error);
    QVERIFY2(!asset, "a broken file was accepted");
    const QString text = QString::fromStdString(error);
    QVERIFY2(text.startsWith(QStringLiteral("importGltf: ") + file + QStringLiteral(": ")), error.c_str());
    QVERIFY2(text.contains(message), error.c_str());
}

// 25 000 nested nodes (issue 12's crafted file overflowed Assimp's recursive reader).
void GltfImportTest::deepNodeGraphDoesNotOverflow()
{
    GltfWriter w;
    const int quad = w.addQuad(-1);
    QJsonArray nodes;
    constexpr int kDepth = 25000;
    for (int i = 0; i < kDepth; ++i) {
        QJsonObject node;
        if (i + 1 < kDepth)
            node[QLatin1String("children")] = QJsonArray {i + 1};
        else
            node[QLatin1String("mesh")] = quad;
        nodes.append(node);
    }
    w.json()[QLatin1String("nodes")] = nodes;
    QJsonObject scene;
    scene[QLatin1String("nodes")] = QJsonArray {0};
    w.json()[QLatin1String("scenes")] = QJsonArray {scene};
    const QString file = path(QStringLiteral("deep.gltf"));
    QVERIFY(w.write(file, Storage::DataUri));
    std::string error;
    const auto asset = importGltf(file.toStdString(), &error);
    QVERIFY2(asset, error.c_str());
    QCOMPARE(asset->mesh.triangleCount(), std::size_t(2));
}

// Issue 29: a 40 KB glTF whose extras (or extensions, or any object) nest 20 000 arrays deep
// overflowed the stack in tinygltf's recursive copy of the JSON (10 000 did not). The nesting is
// bounded before any parser sees the text: refused with the position, through every way a glTF is
// read (importGltf, importMesh for --mesh and a project's mesh, readGltfImage for a texture
// reference into the asset); 200 levels still load.
void GltfImportTest::deeplyNestedJsonIsRefused_data()
{
    QTest::addColumn<QString>("suffix");
    QTest::addColumn<QByteArray>("key"); // a key of the top-level object
    QTest::addColumn<QByteArray>("level"); // repeated `depth` times ...
    QTest::addColumn<QByteArray>("leaf"); // ... around this ...
    QTest::addColumn<QByteArray>("close"); // ... and closed as many times
    QTest::addColumn<int>("depth");
    QTest::addColumn<bool>("loads");
    for (const char* suffix : {"gltf", "glb"}) {
        const QString s = QLatin1String(suffix);
        QTest::newRow(qPrintable(s + QStringLiteral(": extras, 20 000 arrays")))
            << s << QByteArray("extras") << QByteArray("[") << QByteArray() << QByteArray("]") << 20000
            << false;
        QTest::newRow(qPrintable(s + QStringLiteral(": extensions, 20 000 objects")))
            << s << QByteArray("extensions") << QByteArray("{\"a\":") << QByteArray("0") << QByteArray("}")
            << 20000 << false;
        // The key's value sits at depth 1 (inside the top-level object): 256 more make 257.
        QTest::newRow(qPrintable(s + QStringLiteral(": extras, one level past the bound")))
            << s << QByteArray("extras") << QByteArray("[") << QByteArray() << QByteArray("]") << 256
            << false;
        QTest::newRow(qPrintable(s + QStringLiteral(": extras, at the bound")))
            << s << QByteArray("extras") << QByteArray("[") << QByteArray() << QByteArray("]") << 255 << true;
    }
}

void GltfImportTest::deeplyNestedJsonIsRefused()
{
    QFETCH(QString, suffix);
    QFETCH(QByteArray, key);
    QFETCH(QByteArray, level);
    QFETCH(QByteArray, leaf);
    QFETCH(QByteArray, close);
    QFETCH(int, depth);
    QFETCH(bool, loads);
    GltfWriter w;
    QJsonObject values;
    values[QLatin1String("baseColorTexture")]
        = textureInfo(w.addTexture(w.addImageEmbedded(packedPng(), QStringLiteral("image/png"))));
    QJsonObject material;
    material[QLatin1String("pbrMetallicRoughness")] = values;
    w.addNode(w.addQuad(w.addMaterial(material)));
    const QString file = path(QStringLiteral("nested-%1.%2").arg(depth).arg(suffix));
    QVERIFY(w.write(file, suffix == QLatin1String("glb") ? Storage::Glb : Storage::DataUri));
    QVERIFY(insertIntoJson(
        file, "\"" + key + "\":" + level.repeated(depth) + leaf + close.repeated(depth) + ","));

    std::string error;
    const auto asset = importGltf(file.toStdString(), &error);
    std::string meshError;
    const auto mesh = importMesh(file.toStdString(), &meshError);
    std::string imageError;
    const auto image = readGltfImage(GltfImageReference {file.toStdString(), 0}, nullptr, &imageError);
    if (loads) {
        QVERIFY2(asset, error.c_str());
        QVERIFY2(mesh, meshError.c_str());
        QVERIFY2(image, imageError.c_str());
        return;
    }
    QVERIFY2(!asset && !mesh && !image, "a file nested too deep was read");
    for (const std::string& message : {error, meshError, imageError}) {
        const QString text = QString::fromStdString(message);
        QVERIFY2(text.contains(file) && text.contains(QStringLiteral("nest deeper than 256 levels"))
                && text.contains(QStringLiteral("line 1, column ")),
            message.c_str());
    }
}

// importMesh() hands .gltf/.glb to this reader (the viewer's mesh path), never to Assimp.
void GltfImportTest::meshImportReadsGltfThroughThisReader()
{
    GltfWriter w;
    w.addNode(w.addQuad(-1));
    QJsonObject a, b;
    a[QLatin1String("mesh")] = 0;
    a[QLatin1String("children")] = QJsonArray {1};
    b[QLatin1String("children")] = QJsonArray {0};
    w.json()[QLatin1String("nodes")] = QJsonArray {a, b};
    const QString file = path(QStringLiteral("cycle-mesh.glb"));
    QVERIFY(w.write(file, Storage::Glb));
    std::string error;
    QVERIFY(!importMesh(file.toStdString(), &error));
    QVERIFY2(QString::fromStdString(error).startsWith(QStringLiteral("importMesh: ") + file)
                 && QString::fromStdString(error).contains(QStringLiteral("reached twice")),
             error.c_str());
}

// The quick read a project uses (materialsOnly) lists exactly the parts the full import makes:
// the same names and material indices, in the same order, also with a Draco sample mesh.
void GltfImportTest::materialsOnlyListsTheSameParts()
{
    GltfWriter w;
    QJsonObject red;
    red[QLatin1String("pbrMetallicRoughness")] = QJsonObject {{QStringLiteral("baseColorFactor"), jsonNumbers({1, 0, 0, 1})}};
    const int material = w.addMaterial(red);
    w.addNode(w.addQuad(material, 0.0f, QStringLiteral("front")));
    w.addNode(w.addQuad(-1, -1.0f, QStringLiteral("back")));
    w.addNode(w.addSphere(material));
    const QString file = path(QStringLiteral("parts.glb"));
    QVERIFY(w.write(file, Storage::Glb));
    QStringList files {file};
    if (const QString sample = facet::test::modelPath(QStringLiteral("pmndrs")); !sample.isEmpty())
        files.append(sample); // Draco-compressed, one textured material
    for (const QString& f : files) {
        std::string error;
        const auto full = importGltf(f.toStdString(), &error);
        QVERIFY2(full, error.c_str());
        GltfImportOptions options;
        options.materialsOnly = true;
        const auto quick = importGltf(f.toStdString(), &error, nullptr, options);
        QVERIFY2(quick, error.c_str());
        QVERIFY(quick->mesh.vertices.empty());
        QCOMPARE(quick->materials, full->materials);
        QCOMPARE(quick->mesh.subMeshes.size(), full->mesh.subMeshes.size());
        for (std::size_t i = 0; i < full->mesh.subMeshes.size(); ++i) {
            QCOMPARE(quick->mesh.subMeshes[i].name, full->mesh.subMeshes[i].name);
            QCOMPARE(quick->mesh.subMeshes[i].materialIndex, full->mesh.subMeshes[i].materialIndex);
        }
    }
}

// Deterministic mutation: bytes of valid assets (a .glb of Facet's writer with a packed texture,
// the same as .gltf JSON, and the Draco-compressed CC0 sample) overwritten at random places,
// truncated or extended. Every outcome is an asset that validates or a message naming the file;
// nothing crashes, hangs or throws (run under the asan preset too).
void GltfImportTest::corruptedFilesNeverCrash()
{
    GltfWriter w;
    QJsonObject values;
    values[QLatin1String("baseColorTexture")] = textureInfo(w.addTexture(w.addImageEmbedded(packedPng(), QStringLiteral("image/png"))));
    QJsonObject material;
    material[QLatin1String("pbrMetallicRoughness")] = values;
    const int m = w.addMaterial(material);
    w.addNode(w.addQuad(m));
    w.addNode(w.addSphere(m, 12, 6));
    const QString glb = path(QStringLiteral("seed.glb"));
    const QString gltf = path(QStringLiteral("seed.gltf"));
    QVERIFY(w.write(glb, Storage::Glb));
    QVERIFY(w.write(gltf, Storage::DataUri));
    QStringList seeds {glb, gltf};
    if (const QString sample = facet::test::modelPath(QStringLiteral("pmndrs")); !sample.isEmpty())
        seeds.append(sample);

    std::uint64_t state = 0x9E3779B97F4A7C15ULL;
    const auto next = [&state] { // xorshift64*
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        return state * 0x2545F4914F6CDD1DULL;
    };
    int accepted = 0, refused = 0;
    for (const QString& seed : seeds) {
        QFile in(seed);
        QVERIFY(in.open(QIODevice::ReadOnly));
        const QByteArray original = in.readAll();
        for (int round = 0; round < 150; ++round) {
            QByteArray bytes = original;
            const int kind = int(next() % 4);
            if (kind == 0) { // a few bytes overwritten
                for (int i = 0, n = 1 + int(next() % 8); i < n; ++i)
                    bytes[qsizetype(next() % std::uint64_t(bytes.size()))] = char(next());
            } else if (kind == 1) { // cut short
                bytes.truncate(qsizetype(next() % std::uint64_t(bytes.size())));
            } else if (kind == 2) { // a run of one byte value (zeros, 0xff, digits in JSON)
                const qsizetype at = qsizetype(next() % std::uint64_t(bytes.size()));
                static constexpr char kValues[] = {'\0', '\x7f', '9', '-', '['};
                const char value = kValues[next() % 5];
                for (qsizetype i = at; i < std::min(bytes.size(), at + qsizetype(1 + next() % 64)); ++i)
                    bytes[i] = value;
            } else { // garbage appended
                for (int i = 0, n = 1 + int(next() % 256); i < n; ++i)
                    bytes.append(char(next()));
            }
            const QString file = path(QStringLiteral("mutant%1").arg(QFileInfo(seed).suffix().prepend(u'.')));
            QFile out(file);
            QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
            out.write(bytes);
            out.close();
            std::string error;
            const auto asset = importGltf(file.toStdString(), &error);
            if (asset) {
                ++accepted;
                std::string problem;
                QVERIFY2(asset->mesh.validate(&problem), problem.c_str());
                for (const Material& each : asset->materials)
                    QVERIFY2(each.validate(&problem), problem.c_str());
            } else {
                ++refused;
                QVERIFY2(QString::fromStdString(error).startsWith(QStringLiteral("importGltf: ") + file + QStringLiteral(": ")),
                         error.c_str());
            }
        }
    }
    qInfo("%d mutants accepted (valid), %d refused with a message", accepted, refused);
    QVERIFY(refused > 0);
}

QTEST_GUILESS_MAIN(GltfImportTest)
#include "GltfImportTest.moc"
