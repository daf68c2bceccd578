// glTF vertex data beyond position, normal, tangent and UV (issue 29): COLOR_0 in each type
// glTF allows and one it does not, morph targets blended at their default weights, TEXCOORD_1
// and the maps that read it, and each texture's sampler. Small files the test writes itself
// (support/GltfWriter).

#include "core/gltf/GltfImport.h"

#include "GltfWriter.h"
#include "TestSupport.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

using namespace facet;
using facet::test::GltfWriter;
using Storage = GltfWriter::BufferStorage;

namespace {

bool near(double a, double b, double tolerance = 1e-6)
{
    return std::abs(a - b) <= tolerance;
}

} // namespace

class GltfVertexDataTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }

private Q_SLOTS:
    void vertexColorsAreRead_data();
    void vertexColorsAreRead();
    void morphTargetsAtTheirDefaultWeights_data();
    void morphTargetsAtTheirDefaultWeights();
    void secondUvSetIsRead_data();
    void secondUvSetIsRead();
    void samplersAreRead_data();
    void samplersAreRead();
};

void GltfVertexDataTest::secondUvSetIsRead_data()
{
    QTest::addColumn<bool>("withSet1"); // the quad has TEXCOORD_1
    QTest::addColumn<int>("occlusionTexCoord"); // occlusionTexture.texCoord
    QTest::addColumn<int>("transformTexCoord"); // KHR_texture_transform's texCoord, -1: none
    QTest::addColumn<int>("expected"); // the occlusion map's set
    QTest::addColumn<QString>("note"); // in the import's warning; empty: none about sets
    QTest::newRow("set 0") << true << 0 << -1 << 0 << QString();
    QTest::newRow("set 1") << true << 1 << -1 << 1 << QString();
    QTest::newRow("set 1 by the texture transform") << true << 0 << 1 << 1 << QString();
    QTest::newRow("set 1 on a mesh without it")
        << false << 1 << -1 << 1 << QStringLiteral("occlusion reads TEXCOORD_1, which no primitive has");
    QTest::newRow("set 2") << true << 2 << -1 << 0 << QStringLiteral("reads texture coordinate set 2");
}

// Issue 29: a textureInfo with texCoord 1 read UV 0. Both sets are read, flipped to Facet's
// bottom-left origin, and each map keeps its set (glTF 2.0 section 3.9.2, KHR_texture_transform).
void GltfVertexDataTest::secondUvSetIsRead()
{
    QFETCH(bool, withSet1);
    QFETCH(int, occlusionTexCoord);
    QFETCH(int, transformTexCoord);
    QFETCH(int, expected);
    QFETCH(QString, note);
    GltfWriter w;
    const int image = w.addImageEmbedded(
        test::encodePng(2, 2, 3, std::vector<glm::vec4>(4, glm::vec4(0.5f))), QStringLiteral("image/png"));
    const int texture = w.addTexture(image);
    QJsonObject occlusion = test::textureInfo(texture,
        transformTexCoord < 0 ? QJsonObject {}
                              : QJsonObject {{QStringLiteral("KHR_texture_transform"),
                                  QJsonObject {{QStringLiteral("texCoord"), transformTexCoord}}}});
    occlusion[QLatin1String("texCoord")] = occlusionTexCoord;
    const int material = w.addMaterial(QJsonObject {{QStringLiteral("occlusionTexture"), occlusion},
        {QStringLiteral("pbrMetallicRoughness"),
            QJsonObject {{QStringLiteral("baseColorTexture"), test::textureInfo(texture)}}}});
    const int mesh = w.addQuad(material);
    // Set 1: the corners' UVs scaled by a quarter and moved, unlike set 0's (0, 0) to (1, 1).
    const std::vector<float> set1 = {0.1f, 0.2f, 0.35f, 0.2f, 0.35f, 0.45f, 0.1f, 0.45f};
    if (withSet1)
        w.setAttribute(mesh, QStringLiteral("TEXCOORD_1"), w.addFloatAccessor(set1, 2));
    w.addNode(mesh);
    const QString file = path(QStringLiteral("uv-sets-%1.glb")
                                  .arg(QString(QLatin1String(QTest::currentDataTag())).replace(u' ', u'-')));
    QVERIFY(w.write(file, Storage::Glb));
    std::string error, warning;
    const auto asset = importGltf(file.toStdString(), &error, &warning);
    QVERIFY2(asset, error.c_str());
    QCOMPARE(asset->materials.size(), std::size_t(1));
    QCOMPARE(asset->materials[0].map(MapSlot::Occlusion).texCoord, expected);
    QCOMPARE(asset->materials[0].map(MapSlot::BaseColor).texCoord, 0);
    if (note.isEmpty())
        QVERIFY2(!QString::fromStdString(warning).contains(QLatin1String("TEXCOORD")), warning.c_str());
    else
        QVERIFY2(QString::fromStdString(warning).contains(note), warning.c_str());
    QCOMPARE(asset->mesh.hasTexCoord1, withSet1);
    std::string problem;
    QVERIFY2(asset->mesh.validate(&problem), problem.c_str());
    for (std::size_t i = 0; i < asset->mesh.vertices.size(); ++i) {
        const Vertex& v = asset->mesh.vertices[i];
        if (!withSet1) {
            QCOMPARE(v.uv1, v.uv); // a copy: a map on set 1 reads set 0
            continue;
        }
        // Each vertex's set 1 is the file's corner that its set 0 names, with v flipped.
        // (The quad's corners have glTF UVs (0, 1), (1, 1), (1, 0), (0, 0): Facet's (0, 0) to (0, 1).)
        const int corner = v.uv == glm::vec2(0, 0) ? 0
            : v.uv == glm::vec2(1, 0)              ? 1
            : v.uv == glm::vec2(1, 1)              ? 2
                                                   : 3;
        const glm::vec2 file1(set1[std::size_t(corner) * 2], set1[std::size_t(corner) * 2 + 1]);
        QVERIFY2(
            glm::all(glm::lessThan(glm::abs(v.uv1 - glm::vec2(file1.x, 1.0f - file1.y)), glm::vec2(1e-6f))),
            qPrintable(QStringLiteral("vertex %1: uv1 (%2, %3)").arg(i).arg(v.uv1.x).arg(v.uv1.y)));
    }
}

void GltfVertexDataTest::samplersAreRead_data()
{
    QTest::addColumn<QJsonObject>("sampler"); // empty: the texture names none
    QTest::addColumn<int>("wrapS");
    QTest::addColumn<int>("wrapT");
    QTest::addColumn<int>("magFilter");
    QTest::addColumn<int>("minFilter");
    const auto s = [](int mag, int min, int wrapS, int wrapT) {
        QJsonObject o;
        if (mag >= 0)
            o[QLatin1String("magFilter")] = mag;
        if (min >= 0)
            o[QLatin1String("minFilter")] = min;
        if (wrapS >= 0)
            o[QLatin1String("wrapS")] = wrapS;
        if (wrapT >= 0)
            o[QLatin1String("wrapT")] = wrapT;
        return o;
    };
    const int repeat = int(TextureWrap::Repeat), clamp = int(TextureWrap::ClampToEdge),
              mirror = int(TextureWrap::MirroredRepeat);
    const int automatic = int(TextureFilter::Auto), nearest = int(TextureFilter::Nearest),
              linear = int(TextureFilter::Linear);
    QTest::newRow("no sampler") << QJsonObject {} << repeat << repeat << automatic << automatic;
    QTest::newRow("empty sampler") << s(-1, -1, -1, -1) << repeat << repeat << automatic << automatic;
    QTest::newRow("clamp both") << s(-1, -1, 33071, 33071) << clamp << clamp << automatic << automatic;
    QTest::newRow("mirror S, clamp T")
        << s(-1, -1, 33648, 33071) << mirror << clamp << automatic << automatic;
    QTest::newRow("nearest, no mips") << s(9728, 9728, -1, -1) << repeat << repeat << nearest << nearest;
    QTest::newRow("linear, nearest-mipmap-linear") << s(9729, 9986, 10497, 10497) << repeat << repeat
                                                   << linear << int(TextureFilter::NearestMipmapLinear);
}

// Issue 29: samplers were ignored (always repeat). Each map keeps its texture's wraps and filters
// (glTF 2.0 section 3.8.4); the packed metallic-roughness texture gives both slots the same.
void GltfVertexDataTest::samplersAreRead()
{
    QFETCH(QJsonObject, sampler);
    QFETCH(int, wrapS);
    QFETCH(int, wrapT);
    QFETCH(int, magFilter);
    QFETCH(int, minFilter);
    GltfWriter w;
    int samplerIndex = -1;
    if (!sampler.isEmpty() || QLatin1String(QTest::currentDataTag()) == QLatin1String("empty sampler")) {
        QJsonArray samplers;
        samplers.append(sampler);
        w.json()[QLatin1String("samplers")] = samplers;
        samplerIndex = 0;
    }
    const int image = w.addImageEmbedded(
        test::encodePng(2, 2, 3, std::vector<glm::vec4>(4, glm::vec4(0.5f))), QStringLiteral("image/png"));
    const int withSampler = w.addTexture(image, samplerIndex);
    const int without = w.addTexture(image);
    const int material = w.addMaterial(QJsonObject {{QStringLiteral("pbrMetallicRoughness"),
        QJsonObject {{QStringLiteral("metallicRoughnessTexture"), test::textureInfo(withSampler)},
            {QStringLiteral("baseColorTexture"), test::textureInfo(without)}}}});
    w.addNode(w.addQuad(material));
    const QString file = path(QStringLiteral("sampler-%1.glb")
                                  .arg(QString(QLatin1String(QTest::currentDataTag())).replace(u' ', u'-')));
    QVERIFY(w.write(file, Storage::Glb));
    std::string error;
    const auto asset = importGltf(file.toStdString(), &error);
    QVERIFY2(asset, error.c_str());
    const TextureSampler expected {
        TextureWrap(wrapS), TextureWrap(wrapT), TextureFilter(magFilter), TextureFilter(minFilter)};
    const Material& m = asset->materials[0];
    QVERIFY(m.map(MapSlot::Metallic).sampler == expected);
    QVERIFY(m.map(MapSlot::Roughness).sampler == expected);
    QVERIFY(m.map(MapSlot::BaseColor).sampler.isDefault()); // its texture names no sampler
}

void GltfVertexDataTest::vertexColorsAreRead_data()
{
    QTest::addColumn<QString>("type"); // VEC3 or VEC4
    QTest::addColumn<int>("componentType");
    QTest::addColumn<bool>("normalized");
    QTest::addColumn<QString>("refusal"); // empty: read
    const int kFloat = 5126, kUnsignedByte = 5121, kUnsignedShort = 5123;
    QTest::newRow("none") << QString() << 0 << false << QString();
    QTest::newRow("VEC3 FLOAT") << QStringLiteral("VEC3") << kFloat << false << QString();
    QTest::newRow("VEC4 FLOAT") << QStringLiteral("VEC4") << kFloat << false << QString();
    QTest::newRow("VEC4 normalized UNSIGNED_BYTE")
        << QStringLiteral("VEC4") << kUnsignedByte << true << QString();
    QTest::newRow("VEC3 normalized UNSIGNED_SHORT")
        << QStringLiteral("VEC3") << kUnsignedShort << true << QString();
    QTest::newRow("VEC4 UNSIGNED_BYTE, not normalized")
        << QStringLiteral("VEC4") << kUnsignedByte << false
        << QStringLiteral("COLOR_0: UNSIGNED_BYTE components are not allowed");
}

// Issue 29: COLOR_0 was dropped without a word (BoxVertexColors: 23 dE00 from Filament). glTF 2.0
// section 3.7.2.1: RGB or RGBA, float or normalized unsigned byte / short; it multiplies the base
// colour. The four corners get (0.2, 0.4, 0.6, 0.8) scaled by 1, 0.75, 0.5, 0.25.
void GltfVertexDataTest::vertexColorsAreRead()
{
    QFETCH(QString, type);
    QFETCH(int, componentType);
    QFETCH(bool, normalized);
    QFETCH(QString, refusal);
    GltfWriter w;
    const int mesh = w.addQuad(-1);
    const int components = type == QLatin1String("VEC4") ? 4 : 3;
    std::vector<glm::vec4> expected(4, glm::vec4(1.0f));
    if (!type.isEmpty()) {
        std::vector<float> values;
        for (int corner = 0; corner < 4; ++corner) {
            const float scale = 1.0f - 0.25f * float(corner);
            const glm::vec4 c = glm::vec4(0.2f, 0.4f, 0.6f, 0.8f) * scale;
            for (int k = 0; k < components; ++k)
                values.push_back(c[k]);
            expected[std::size_t(corner)] = components == 4 ? c : glm::vec4(glm::vec3(c), 1.0f);
        }
        int accessor = -1;
        if (componentType == 5126) {
            accessor = w.addFloatAccessor(values, components);
        } else {
            const int size = componentType == 5121 ? 1 : 2;
            const double maximum = size == 1 ? 255.0 : 65535.0;
            QByteArray bytes;
            for (std::size_t i = 0; i < values.size(); ++i) {
                const auto q = std::uint32_t(std::lround(values[i] * maximum));
                bytes.append(reinterpret_cast<const char*>(&q), size);
                values[i] = float(double(q) / maximum); // what the file now says
            }
            while (bytes.size() % 4 != 0)
                bytes.append('\0');
            for (int corner = 0; corner < 4; ++corner)
                for (int k = 0; k < components; ++k)
                    expected[std::size_t(corner)][k] = values[std::size_t(corner * components + k)];
            QJsonArray accessors = w.json()[QLatin1String("accessors")].toArray();
            accessors.append(QJsonObject {{QStringLiteral("bufferView"), w.addBufferView(bytes)},
                {QStringLiteral("componentType"), componentType}, {QStringLiteral("normalized"), normalized},
                {QStringLiteral("count"), 4}, {QStringLiteral("type"), type}});
            w.json()[QLatin1String("accessors")] = accessors;
            accessor = int(accessors.size() - 1);
        }
        w.setAttribute(mesh, QStringLiteral("COLOR_0"), accessor);
    }
    w.addNode(mesh);
    const QString file = path(QStringLiteral("colours-%1.glb")
                                  .arg(QString(QLatin1String(QTest::currentDataTag())).replace(u' ', u'-')));
    QVERIFY(w.write(file, Storage::Glb));
    std::string error;
    const auto asset = importGltf(file.toStdString(), &error);
    if (!refusal.isEmpty()) {
        QVERIFY(!asset);
        QVERIFY2(QString::fromStdString(error).contains(refusal), error.c_str());
        return;
    }
    QVERIFY2(asset, error.c_str());
    QCOMPARE(asset->mesh.hasVertexColors, !type.isEmpty());
    QCOMPARE(asset->mesh.vertices.size(), std::size_t(4));
    for (std::size_t i = 0; i < 4; ++i) {
        const glm::vec4 c = vertexColor(asset->mesh.vertices[i]);
        // 16-bit storage: within half a step of 1/65535.
        QVERIFY2(glm::all(glm::lessThanEqual(glm::abs(c - expected[i]), glm::vec4(1e-5f))),
            qPrintable(QStringLiteral("vertex %1: %2 %3 %4 %5").arg(i).arg(c.r).arg(c.g).arg(c.b).arg(c.a)));
    }
}

void GltfVertexDataTest::morphTargetsAtTheirDefaultWeights_data()
{
    QTest::addColumn<QVector<double>>("meshWeights");
    QTest::addColumn<QVector<double>>("nodeWeights");
    QTest::addColumn<double>("z"); // every vertex's z afterwards
    QTest::addColumn<double>("normalX"); // every normal's x afterwards (before normalising: 0 + w1)
    // Target 0 moves every vertex by +1 in z; target 1 tilts the normals by +1 in x.
    QTest::newRow("no weights: the base shape") << QVector<double> {} << QVector<double> {} << 0.0 << 0.0;
    QTest::newRow("mesh weights") << QVector<double> {0.5, 0.0} << QVector<double> {} << 0.5 << 0.0;
    QTest::newRow("both targets") << QVector<double> {0.25, 1.0} << QVector<double> {} << 0.25 << 1.0;
    QTest::newRow("node weights win")
        << QVector<double> {0.5, 0.0} << QVector<double> {1.0, 0.0} << 1.0 << 0.0;
    QTest::newRow("negative weight") << QVector<double> {-2.0, 0.0} << QVector<double> {} << -2.0 << 0.0;
}

// Issue 29: a mesh's default morph-target weights were not applied (AnimatedMorphCube showed
// its base shape). glTF 2.0 section 3.7.2.2: position/normal = base + sum of weight x target, with
// the node's weights, else the mesh's.
void GltfVertexDataTest::morphTargetsAtTheirDefaultWeights()
{
    QFETCH(QVector<double>, meshWeights);
    QFETCH(QVector<double>, nodeWeights);
    QFETCH(double, z);
    QFETCH(double, normalX);
    GltfWriter w;
    const int mesh = w.addQuad(-1);
    std::vector<float> up(4 * 3, 0.0f);
    for (int i = 0; i < 4; ++i)
        up[std::size_t(i) * 3 + 2] = 1.0f;
    const int liftUp = w.addFloatAccessor(up, 3, true);
    std::vector<float> tilt(4 * 3, 0.0f);
    for (int i = 0; i < 4; ++i)
        tilt[std::size_t(i) * 3] = 1.0f;
    const int tiltX = w.addFloatAccessor(tilt, 3);
    QJsonObject m = w.json()[QLatin1String("meshes")].toArray()[mesh].toObject();
    QJsonObject p = m[QLatin1String("primitives")].toArray()[0].toObject();
    p[QLatin1String("targets")] = QJsonArray {
        QJsonObject {{QStringLiteral("POSITION"), liftUp}}, QJsonObject {{QStringLiteral("NORMAL"), tiltX}}};
    m[QLatin1String("primitives")] = QJsonArray {p};
    QJsonArray weights;
    for (double value : meshWeights)
        weights.append(value);
    if (!weights.isEmpty())
        m[QLatin1String("weights")] = weights;
    w.json()[QLatin1String("meshes")] = QJsonArray {m};
    const int node = w.addNode(mesh);
    if (!nodeWeights.isEmpty()) {
        QJsonArray nodes = w.json()[QLatin1String("nodes")].toArray();
        QJsonObject n = nodes[node].toObject();
        QJsonArray values;
        for (double value : nodeWeights)
            values.append(value);
        n[QLatin1String("weights")] = values;
        nodes[node] = n;
        w.json()[QLatin1String("nodes")] = nodes;
    }
    const QString file = path(
        QStringLiteral("morph-%1.gltf").arg(QLatin1String(QTest::currentDataTag())).replace(u' ', u'-'));
    QVERIFY(w.write(file, Storage::DataUri));
    std::string error;
    const auto asset = importGltf(file.toStdString(), &error);
    QVERIFY2(asset, error.c_str());
    QCOMPARE(asset->mesh.vertices.size(), std::size_t(4));
    const glm::vec3 expectedNormal = glm::normalize(glm::vec3(float(normalX), 0.0f, 1.0f));
    for (const Vertex& v : asset->mesh.vertices) {
        QVERIFY2(near(v.position.z, z, 1e-6), qPrintable(QString::number(v.position.z)));
        QVERIFY2(glm::length(v.normal - expectedNormal) < 1e-6f, qPrintable(QString::number(v.normal.x)));
    }
}

QTEST_GUILESS_MAIN(GltfVertexDataTest)
#include "GltfVertexDataTest.moc"
