// glTF vertex data beyond position, normal, tangent and UV (issue 29): COLOR_0 in each type
// glTF allows and one it does not, and morph targets blended at their default weights. Small
// files the test writes itself (support/GltfWriter).

#include "core/GltfImport.h"

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
};

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
