// Meshes: the procedural primitives (valid, watertight, outward, the right volume, tangent
// frames that agree with their UVs), normalisation, transforms, tangent and UV generation, and
// Assimp import of the CC0 sample meshes, of small files written here with known answers, and
// of broken files, each of which must give a message naming the file and never crash.

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <tuple>

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <glm/geometric.hpp>

#include "TestSupport.h"
#include "core/Mesh.h"
#include "core/MeshImport.h"
#include "core/MeshPrimitives.h"
#include "core/Tangents.h"

using namespace facet;

namespace {

constexpr double kPi = std::numbers::pi;

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

bool writeFile(const QString& path, const QByteArray& data)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(data) == data.size();
}

QByteArray readFile(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// Signed volume by the divergence theorem: sum over triangles of p0 . (p1 x p2) / 6. Positive
// for a closed mesh wound counter-clockwise from outside.
double signedVolume(const Mesh& mesh)
{
    double volume = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 p0 = mesh.vertices[mesh.indices[t]].position;
        const glm::dvec3 p1 = mesh.vertices[mesh.indices[t + 1]].position;
        const glm::dvec3 p2 = mesh.vertices[mesh.indices[t + 2]].position;
        volume += glm::dot(p0, glm::cross(p1, p2)) / 6.0;
    }
    return volume;
}

// Watertight and consistently wound: after welding vertices at the same position (seams and
// poles are split on purpose), every directed edge occurs exactly once and its reverse exactly
// once, i.e. every edge is shared by exactly two triangles that traverse it in opposite
// directions. Positions are welded on a 1e-5 grid: the primitives' seams coincide bit for bit,
// this only absorbs rounding in the tests' own transforms.
bool isClosed(const Mesh& mesh, QString* why)
{
    std::map<std::tuple<long long, long long, long long>, uint32_t> ids;
    std::vector<uint32_t> welded(mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const glm::vec3 p = mesh.vertices[i].position;
        const auto key = std::make_tuple(std::llround(double(p.x) * 1e5), std::llround(double(p.y) * 1e5),
            std::llround(double(p.z) * 1e5));
        welded[i] = ids.emplace(key, uint32_t(ids.size())).first->second;
    }
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = welded[mesh.indices[t + k]], b = welded[mesh.indices[t + (k + 1) % 3]];
            if (a == b) {
                *why = QStringLiteral("triangle %1 is degenerate after welding").arg(t / 3);
                return false;
            }
            ++directed[{a, b}];
        }
    for (const auto& [edge, count] : directed) {
        const auto reverse = directed.find({edge.second, edge.first});
        if (count != 1 || reverse == directed.end() || reverse->second != 1) {
            *why = QStringLiteral("edge %1-%2 used %3 time(s), its reverse %4 time(s)")
                       .arg(edge.first)
                       .arg(edge.second)
                       .arg(count)
                       .arg(reverse == directed.end() ? 0 : reverse->second);
            return false;
        }
    }
    return true;
}

// How well the vertex tangent frames agree with the triangles' UV directions: for every corner
// of every triangle with UV area, whether tangent.xyz points along the triangle's dP/du and the
// bitangent cross(n, t) * w along its dP/dv (positive dot products), and whether the vertex
// normal is on the outward side of the face (it agrees with the winding).
struct FrameAgreement {
    std::size_t corners = 0;
    std::size_t tangentAgrees = 0;
    std::size_t bitangentAgrees = 0;
    std::size_t normalAgrees = 0;
    double tangentFraction() const { return corners ? double(tangentAgrees) / double(corners) : 0.0; }
    double bitangentFraction() const { return corners ? double(bitangentAgrees) / double(corners) : 0.0; }
    double normalFraction() const { return corners ? double(normalAgrees) / double(corners) : 0.0; }
};

FrameAgreement frameAgreement(const Mesh& mesh)
{
    FrameAgreement result;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const Vertex* v[3] = {&mesh.vertices[mesh.indices[t]], &mesh.vertices[mesh.indices[t + 1]],
            &mesh.vertices[mesh.indices[t + 2]]};
        const glm::dvec3 e1 = glm::dvec3(v[1]->position) - glm::dvec3(v[0]->position);
        const glm::dvec3 e2 = glm::dvec3(v[2]->position) - glm::dvec3(v[0]->position);
        const glm::dvec2 d1 = glm::dvec2(v[1]->uv) - glm::dvec2(v[0]->uv);
        const glm::dvec2 d2 = glm::dvec2(v[2]->uv) - glm::dvec2(v[0]->uv);
        const double det = d1.x * d2.y - d2.x * d1.y;
        const glm::dvec3 face = glm::cross(e1, e2);
        if (std::abs(det) < 1e-12 || glm::length(face) < 1e-12)
            continue;
        const glm::dvec3 dPdu = (e1 * d2.y - e2 * d1.y) / det;
        const glm::dvec3 dPdv = (e2 * d1.x - e1 * d2.x) / det;
        for (const Vertex* corner : v) {
            const glm::dvec3 n = corner->normal;
            const glm::dvec3 tangent = glm::dvec3(corner->tangent);
            const glm::dvec3 bitangent = glm::cross(n, tangent) * double(corner->tangent.w);
            ++result.corners;
            result.tangentAgrees += glm::dot(tangent, dPdu) > 0.0 ? 1 : 0;
            result.bitangentAgrees += glm::dot(bitangent, dPdv) > 0.0 ? 1 : 0;
            result.normalAgrees += glm::dot(n, face) > 0.0 ? 1 : 0;
        }
    }
    return result;
}

bool isClosedPrimitive(std::string_view name)
{
    return name != "plane";
}

// A mesh from a list of triangles (positions and UVs), flat normals, for the tangent tests.
Mesh triangles(const std::vector<glm::vec3>& positions, const std::vector<glm::vec2>& uvs)
{
    Mesh mesh;
    mesh.name = "triangles";
    for (std::size_t i = 0; i < positions.size(); ++i) {
        Vertex v;
        v.position = positions[i];
        v.uv = uvs[i];
        mesh.vertices.push_back(v);
        mesh.indices.push_back(uint32_t(i));
    }
    for (std::size_t t = 0; t + 2 < positions.size(); t += 3) {
        const glm::vec3 n
            = glm::normalize(glm::cross(positions[t + 1] - positions[t], positions[t + 2] - positions[t]));
        for (int k = 0; k < 3; ++k)
            mesh.vertices[t + k].normal = n;
    }
    mesh.subMeshes = {SubMesh {"all", 0, uint32_t(mesh.indices.size()), 0, true}};
    mesh.hasUvs = true;
    mesh.updateBounds();
    return mesh;
}

double angleDegrees(const glm::vec3& a, const glm::vec3& b)
{
    const double c = glm::dot(glm::dvec3(glm::normalize(a)), glm::dvec3(glm::normalize(b)));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / kPi;
}

// glTF 2.0 (.gltf, JSON with the buffer embedded as a base64 data URI) holding one triangle
// in the XY plane facing +Z, UVs (0,0) (1,0) (0,1) in glTF's top-left convention, and the given
// node hierarchy. `withNormals` false leaves the NORMAL attribute out; `withTangents` adds a
// TANGENT attribute, (0.6, 0.8, 0), (0.8, 0.6, 0), (0, 1, 0) with w = -1. (Not one tangent for
// all three: Assimp's FindInvalidData drops a tangent array whose elements are all equal.)
QByteArray gltfTriangle(
    const QJsonArray& nodes, const QJsonArray& sceneNodes, bool withNormals, bool withTangents = false)
{
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const float normals[9] = {0, 0, 1, 0, 0, 1, 0, 0, 1};
    const float uvs[6] = {0, 0, 1, 0, 0, 1};
    const uint16_t indices[4] = {0, 1, 2, 0}; // padded to 4-byte alignment
    const float tangents[12] = {0.6f, 0.8f, 0, -1, 0.8f, 0.6f, 0, -1, 0, 1, 0, -1};
    QByteArray buffer;
    buffer.append(reinterpret_cast<const char*>(positions), sizeof positions);
    buffer.append(reinterpret_cast<const char*>(normals), sizeof normals);
    buffer.append(reinterpret_cast<const char*>(uvs), sizeof uvs);
    buffer.append(reinterpret_cast<const char*>(indices), sizeof indices);
    buffer.append(reinterpret_cast<const char*>(tangents), sizeof tangents);
    const auto view = [](int offset, int length, int target) {
        return QJsonObject {{QStringLiteral("buffer"), 0}, {QStringLiteral("byteOffset"), offset},
            {QStringLiteral("byteLength"), length}, {QStringLiteral("target"), target}};
    };
    const auto accessor = [](int bufferView, int componentType, int count, const char* type) {
        return QJsonObject {{QStringLiteral("bufferView"), bufferView},
            {QStringLiteral("componentType"), componentType}, {QStringLiteral("count"), count},
            {QStringLiteral("type"), QLatin1String(type)}};
    };
    QJsonObject positionAccessor = accessor(0, 5126, 3, "VEC3");
    positionAccessor[QStringLiteral("min")] = QJsonArray {0, 0, 0};
    positionAccessor[QStringLiteral("max")] = QJsonArray {1, 1, 0};
    QJsonObject attributes {{QStringLiteral("POSITION"), 0}, {QStringLiteral("TEXCOORD_0"), 2}};
    if (withNormals)
        attributes[QStringLiteral("NORMAL")] = 1;
    if (withTangents)
        attributes[QStringLiteral("TANGENT")] = 4;
    const QJsonObject gltf {
        {QStringLiteral("asset"), QJsonObject {{QStringLiteral("version"), QStringLiteral("2.0")}}},
        {QStringLiteral("scene"), 0},
        {QStringLiteral("scenes"), QJsonArray {QJsonObject {{QStringLiteral("nodes"), sceneNodes}}}},
        {QStringLiteral("nodes"), nodes},
        {QStringLiteral("meshes"),
            QJsonArray {QJsonObject {{QStringLiteral("name"), QStringLiteral("tri")},
                {QStringLiteral("primitives"),
                    QJsonArray {QJsonObject {{QStringLiteral("attributes"), attributes},
                        {QStringLiteral("indices"), 3}, {QStringLiteral("mode"), 4}}}}}}},
        {QStringLiteral("buffers"),
            QJsonArray {QJsonObject {{QStringLiteral("byteLength"), int(buffer.size())},
                {QStringLiteral("uri"),
                    QString::fromLatin1("data:application/octet-stream;base64," + buffer.toBase64())}}}},
        {QStringLiteral("bufferViews"),
            QJsonArray {view(0, 36, 34962), view(36, 36, 34962), view(72, 24, 34962), view(96, 6, 34963),
                view(104, 48, 34962)}},
        {QStringLiteral("accessors"),
            QJsonArray {positionAccessor, accessor(1, 5126, 3, "VEC3"), accessor(2, 5126, 3, "VEC2"),
                accessor(3, 5123, 3, "SCALAR"), accessor(4, 5126, 3, "VEC4")}},
    };
    return QJsonDocument(gltf).toJson();
}

// Asserts inside a helper: QVERIFY returns from the helper only, so callers check QTest::currentTestFailed().
void checkImportFails(const QString& path, const char* expectedPart)
{
    std::string error, warning = "stale";
    const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
    QVERIFY2(!mesh, qPrintable(path));
    QVERIFY2(contains(error, "importMesh: " + path.toStdString() + ": "), error.c_str());
    QVERIFY2(contains(error, expectedPart), error.c_str());
    QVERIFY(warning.empty());
}

} // namespace

class MeshTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // ---- Primitives ---------------------------------------------------------------------
    void primitives_data()
    {
        QTest::addColumn<QString>("name");
        for (std::string_view name : primitiveNames())
            QTest::newRow(std::string(name).c_str())
                << QString::fromLatin1(name.data(), qsizetype(name.size()));
    }
    void primitives()
    {
        QFETCH(QString, name);
        const std::optional<Mesh> mesh = makePrimitive(name.toStdString());
        QVERIFY(mesh);
        std::string problem;
        QVERIFY2(mesh->validate(&problem), problem.c_str());
        QCOMPARE(mesh->name, name.toStdString());
        QVERIFY(mesh->hasUvs && mesh->hasTangents && !mesh->uvsGenerated);
        QCOMPARE(mesh->subMeshes.size(), std::size_t(1));
        QCOMPARE(mesh->subMeshes[0].firstIndex, 0u);
        QCOMPARE(std::size_t(mesh->subMeshes[0].indexCount), mesh->indices.size());
        QVERIFY(mesh->triangleCount() > 0);
        // No primitive has a mirrored UV chart.
        for (const Vertex& v : mesh->vertices)
            QCOMPARE(v.tangent.w, 1.0f);
        // Every corner's frame agrees with its triangle: tangent along dP/du, bitangent along
        // dP/dv, normal on the outward side. Analytic frames on these shapes agree everywhere.
        const FrameAgreement frame = frameAgreement(*mesh);
        QVERIFY(frame.corners >= 3 * mesh->triangleCount() - 3); // at most one UV-degenerate triangle
        QCOMPARE(frame.tangentAgrees, frame.corners);
        QCOMPARE(frame.bitangentAgrees, frame.corners);
        QCOMPARE(frame.normalAgrees, frame.corners);
        if (isClosedPrimitive(name.toStdString())) {
            QString why;
            QVERIFY2(isClosed(*mesh, &why), qPrintable(why));
            QVERIFY(signedVolume(*mesh) > 0.0);
        }
        // Framing puts the bounding sphere at the origin with radius 1.
        Mesh framed = *mesh;
        framed.normalizeToUnitSphere();
        QVERIFY2(framed.validate(&problem), problem.c_str());
        QVERIFY(std::abs(framed.boundingSphereRadius() - 1.0f) < 1e-5f);
        QVERIFY(glm::length(framed.bounds.center()) < 1e-5f);
        for (const Vertex& v : framed.vertices)
            QVERIFY(glm::length(v.position) <= 1.0f + 1e-5f);
    }

    void primitiveVolumes()
    {
        // Inscribed polyhedra fall short of the smooth shape by O(1/segments^2): with 64
        // segments about 0.3% for the sphere; the brief's bound is 1%.
        const double sphere = signedVolume(makeSphere());
        QVERIFY2(std::abs(sphere / (4.0 / 3.0 * kPi) - 1.0) < 0.01, qPrintable(QString::number(sphere)));
        QVERIFY(sphere < 4.0 / 3.0 * kPi); // inscribed: never larger
        QVERIFY(std::abs(signedVolume(makeCube()) - 8.0) < 1e-5);
        QVERIFY(std::abs(signedVolume(makeCylinder()) / (2.0 * kPi) - 1.0) < 0.01);
        const double torus = 2.0 * kPi * kPi * 0.7 * 0.3 * 0.3; // 2 pi^2 R r^2
        QVERIFY(std::abs(signedVolume(makeTorus()) / torus - 1.0) < 0.01);
        // The shader ball: a bit less than its ball (the band's recess) plus the base and neck.
        const double ball = 4.0 / 3.0 * kPi * 0.8 * 0.8 * 0.8;
        const double shaderBall = signedVolume(makeShaderBall());
        QVERIFY2(
            shaderBall > 0.85 * ball && shaderBall < 1.15 * ball, qPrintable(QString::number(shaderBall)));
    }

    void sphereLayout()
    {
        const Mesh sphere = makeSphere();
        QCOMPARE(sphere.vertices.size(), std::size_t(2 * 64 + 31 * 65));
        QCOMPARE(sphere.triangleCount(), std::size_t(2 * 64 + 2 * 64 * 30));
        for (const Vertex& v : sphere.vertices) {
            QVERIFY(std::abs(glm::length(v.position) - 1.0f) < 1e-6f);
            QVERIFY(glm::length(v.normal - v.position) < 1e-6f); // analytic normals
            // u = 0.5 - atan2(z, x) / (2 pi) (the seam column repeats u = 0 as u = 1), v = asin(y) / pi + 0.5
            const bool pole = std::abs(v.position.y) > 1.0f - 1e-6f;
            if (!pole) {
                const double u = 0.5 - std::atan2(double(v.position.z), double(v.position.x)) / (2.0 * kPi);
                const double du = std::abs(u - double(v.uv.x));
                QVERIFY2(du < 1e-5 || std::abs(du - 1.0) < 1e-5, qPrintable(QString::number(du)));
            }
            QVERIFY(std::abs(std::asin(double(v.position.y)) / kPi + 0.5 - double(v.uv.y)) < 1e-5);
        }
        // Seen from the reference camera on +Z, u grows to the right (+X) and v up: not mirrored.
        const auto front = std::min_element(
            sphere.vertices.begin(), sphere.vertices.end(), [](const Vertex& a, const Vertex& b) {
                return glm::length(a.position - glm::vec3(0, 0, 1))
                    < glm::length(b.position - glm::vec3(0, 0, 1));
            });
        QVERIFY(glm::length(front->position - glm::vec3(0, 0, 1)) < 1e-6f);
        QVERIFY(glm::length(glm::vec3(front->tangent) - glm::vec3(1, 0, 0)) < 1e-6f);
        QCOMPARE(front->uv.x, 0.25f);
    }

    void primitiveArguments()
    {
        QVERIFY(!makePrimitive("teapot"));
        QVERIFY(!makePrimitive(""));
        QVERIFY(!makePrimitive("Sphere"));
        QCOMPARE(primitiveNames().size(), std::size_t(6));
        // Out-of-range tessellation is clamped, never a crash or a broken mesh.
        for (const Mesh& mesh : {makeSphere(0, -5), makeSphere(3, 2), makeCylinder(-1), makeTorus(1, 1),
                 makeShaderBall(2), makePlane(0), makeSphere(100000, 3)}) {
            std::string problem;
            QVERIFY2(mesh.validate(&problem), problem.c_str());
            if (mesh.name != "plane") {
                QString why;
                QVERIFY2(isClosed(mesh, &why),
                    qPrintable(QString::fromStdString(mesh.name) + QLatin1String(": ") + why));
            }
        }
        QCOMPARE(makeSphere(100000, 3).vertices.size(), makeSphere(4096, 3).vertices.size());
        QCOMPARE(makePlane(4).triangleCount(), std::size_t(32));
        QCOMPARE(makeCube().vertices.size(), std::size_t(24));
    }

    // ---- Mesh ---------------------------------------------------------------------------
    void normalizeToUnitSphere()
    {
        Mesh mesh = makeTorus();
        QVERIFY(mesh.transform(glm::mat4 {{3, 0, 0, 0}, {0, 0.5f, 0, 0}, {0, 0, 2, 0}, {10, -4, 7, 1}}));
        const Mesh before = mesh;
        const glm::mat4 applied = mesh.normalizeToUnitSphere();
        QVERIFY(std::abs(mesh.boundingSphereRadius() - 1.0f) < 1e-5f);
        QVERIFY(glm::length(mesh.bounds.center()) < 1e-5f);
        // The returned transform is what was applied.
        for (std::size_t i = 0; i < mesh.vertices.size(); i += 97) {
            const glm::vec3 expected = glm::vec3(applied * glm::vec4(before.vertices[i].position, 1.0f));
            QVERIFY(glm::length(expected - mesh.vertices[i].position) < 1e-5f);
            QCOMPARE(mesh.vertices[i].normal, before.vertices[i].normal);
        }
        // Idempotent.
        const glm::mat4 again = mesh.normalizeToUnitSphere();
        for (int c = 0; c < 4; ++c)
            QVERIFY(glm::length(again[c] - glm::mat4(1.0f)[c]) < 1e-5f);
        // Degenerate meshes: empty is left alone, a single point is only centred.
        Mesh empty;
        QCOMPARE(empty.normalizeToUnitSphere(), glm::mat4(1.0f));
        Mesh point;
        point.vertices.resize(2);
        point.vertices[0].position = point.vertices[1].position = {1, 2, 3};
        const glm::mat4 centred = point.normalizeToUnitSphere();
        QCOMPARE(point.vertices[0].position, glm::vec3(0.0f));
        QCOMPARE(glm::vec3(centred[3]), glm::vec3(-1, -2, -3));
    }

    void transform()
    {
        // Non-uniform scale: normals must stay perpendicular to the surface (inverse transpose).
        Mesh sphere = makeSphere(32, 16);
        QVERIFY(sphere.transform(glm::mat4 {{2, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0.5f, 0}, {0, 0, 0, 1}}));
        std::string problem;
        QVERIFY2(sphere.validate(&problem), problem.c_str());
        FrameAgreement frame = frameAgreement(sphere);
        QCOMPARE(frame.normalAgrees, frame.corners);
        QCOMPARE(frame.tangentAgrees, frame.corners);
        QCOMPARE(frame.bitangentAgrees, frame.corners);
        // Ellipsoid normal at (x, y, z) is along (x/a^2, y/b^2, z/c^2).
        for (const Vertex& v : sphere.vertices) {
            const glm::vec3 expected = glm::normalize(v.position / glm::vec3(4.0f, 1.0f, 0.25f));
            QVERIFY(glm::length(v.normal - expected) < 1e-5f);
        }
        // A mirror keeps the mesh outward (winding reversed) and flips the handedness.
        Mesh mirrored = makeCube();
        QVERIFY(mirrored.transform(glm::mat4 {{-1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}));
        QVERIFY2(mirrored.validate(&problem), problem.c_str());
        QVERIFY(std::abs(signedVolume(mirrored) - 8.0) < 1e-5);
        frame = frameAgreement(mirrored);
        QCOMPARE(frame.normalAgrees, frame.corners);
        QCOMPARE(frame.tangentAgrees, frame.corners);
        QCOMPARE(frame.bitangentAgrees, frame.corners);
        for (const Vertex& v : mirrored.vertices)
            QCOMPARE(v.tangent.w, -1.0f);
        // Singular and non-finite matrices are refused and leave the mesh alone.
        Mesh cube = makeCube();
        QVERIFY(
            !cube.transform(glm::mat4 {{1, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}, &problem));
        QVERIFY2(contains(problem, "Mesh::transform: 'cube'"), problem.c_str());
        QVERIFY(!cube.transform(glm::mat4(std::nanf(""))));
        QVERIFY(cube == makeCube());
    }

    void validateCatchesBrokenMeshes()
    {
        const Mesh good = makeCube();
        const auto expectProblem = [&](Mesh broken, const char* part) {
            std::string problem;
            QVERIFY(!broken.validate(&problem));
            QVERIFY2(contains(problem, "Mesh::validate: 'cube': "), problem.c_str());
            QVERIFY2(contains(problem, part), problem.c_str());
        };
        Mesh m = good;
        m.indices[5] = 24;
        expectProblem(m, "out of range");
        m = good;
        m.indices.pop_back();
        expectProblem(m, "not a multiple of 3");
        m = good;
        m.vertices[3].position.x = std::nanf("");
        expectProblem(m, "vertex 3: position is not finite");
        m = good;
        m.vertices[4].normal *= 1.1f;
        expectProblem(m, "vertex 4: normal");
        m = good;
        m.vertices[5].tangent = glm::vec4(
            glm::normalize(glm::vec3(m.vertices[5].normal) + glm::vec3(m.vertices[5].tangent)), 1.0f);
        expectProblem(m, "not perpendicular");
        m = good;
        m.vertices[6].tangent.w = 0.5f;
        expectProblem(m, "handedness");
        m = good;
        m.subMeshes[0].indexCount += 3;
        expectProblem(m, "sub-mesh 0");
        m = good;
        m.vertices[7].position *= 2.0f; // bounds not updated
        expectProblem(m, "outside the bounds");
        m = good;
        m.vertices[8].uv.y = INFINITY;
        expectProblem(m, "UV is not finite");
        // Tangents are only checked when the mesh says it has them.
        m = good;
        m.vertices[6].tangent.w = 0.5f;
        m.hasTangents = false;
        QVERIFY(m.validate());
    }

    // ---- Tangents -----------------------------------------------------------------------
    void tangentsFromUvs()
    {
        // A quad in the XY plane facing +Z, UVs in three layouts: straight (u = +X, v = +Y),
        // turned a quarter (u = +Y, v = -X), mirrored (u = -X, v = +Y).
        const std::vector<glm::vec3> quad
            = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}};
        const struct {
            std::vector<glm::vec2> uvs;
            glm::vec3 tangent;
            float w;
        } cases[] = {
            {{{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}}, {1, 0, 0}, 1.0f},
            {{{0, 1}, {0, 0}, {1, 0}, {0, 1}, {1, 0}, {1, 1}}, {0, 1, 0}, 1.0f},
            {{{1, 0}, {0, 0}, {0, 1}, {1, 0}, {0, 1}, {1, 1}}, {-1, 0, 0}, -1.0f},
        };
        for (const auto& c : cases) {
            Mesh mesh = triangles(quad, c.uvs);
            TangentStats stats;
            std::string problem;
            QVERIFY2(generateTangents(mesh, &problem, &stats), problem.c_str());
            QVERIFY(mesh.hasTangents);
            QCOMPARE(stats.degenerateTriangles, std::size_t(0));
            QCOMPARE(stats.fallbackVertices, std::size_t(0));
            for (const Vertex& v : mesh.vertices) {
                QVERIFY(glm::length(glm::vec3(v.tangent) - c.tangent) < 1e-6f);
                QCOMPARE(v.tangent.w, c.w);
            }
            QVERIFY2(mesh.validate(&problem), problem.c_str());
        }
        // At a shared vertex each triangle votes with its dP/du DIRECTION weighted by its corner
        // angle, not with dP/du's length (as MikkTSpace): triangle (O, A, B) has dP/du = +X and
        // a 90 degree corner at O; triangle (O, B, C) has dP/du = (100, -200, 0) from its
        // squeezed UVs and a 45 degree corner. O's tangent is their angle-weighted mean direction.
        {
            Mesh fan;
            fan.name = "fan";
            const glm::vec3 positions[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 1, 0}};
            const glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {0, 1}, {-0.01f, -1.0f}};
            for (int i = 0; i < 4; ++i) {
                Vertex v;
                v.position = positions[i];
                v.normal = {0, 0, 1};
                v.uv = uvs[i];
                fan.vertices.push_back(v);
            }
            fan.indices = {0, 1, 2, 0, 2, 3};
            fan.hasUvs = true;
            QVERIFY(generateTangents(fan));
            const glm::vec3 expected = glm::normalize(
                float(kPi / 2) * glm::vec3(1, 0, 0) + float(kPi / 4) * glm::normalize(glm::vec3(1, -2, 0)));
            QVERIFY2(angleDegrees(glm::vec3(fan.vertices[0].tangent), expected) < 0.01,
                qPrintable(QString::number(angleDegrees(glm::vec3(fan.vertices[0].tangent), expected))));
            QCOMPARE(fan.vertices[0].tangent.w, 1.0f);
        }
        // No UV area: an arbitrary unit tangent perpendicular to the normal (Duff et al.).
        Mesh flat = triangles({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}});
        TangentStats stats;
        QVERIFY(generateTangents(flat, nullptr, &stats));
        QCOMPARE(stats.degenerateTriangles, std::size_t(1));
        QCOMPARE(stats.fallbackVertices, std::size_t(3));
        std::string problem;
        QVERIFY2(flat.validate(&problem), problem.c_str());
        // Without UVs it refuses, naming the mesh.
        Mesh noUvs = makeCube();
        noUvs.hasUvs = false;
        QVERIFY(!generateTangents(noUvs, &problem));
        QVERIFY2(
            contains(problem, "generateTangents: 'cube': ") && contains(problem, "no UVs"), problem.c_str());
        Mesh badIndex = makeCube();
        badIndex.indices[0] = 1000;
        QVERIFY(!generateTangents(badIndex, &problem));
        QVERIFY2(contains(problem, "out of range"), problem.c_str());
    }

    void perpendicularTangentIsOrthonormal()
    {
        // Every direction, including the poles and the n.z = 0 circle where the basis switches.
        for (int i = 0; i <= 40; ++i)
            for (int j = 0; j < 80; ++j) {
                const double theta = kPi * i / 40.0, phi = 2.0 * kPi * j / 80.0;
                const glm::vec3 n(
                    std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
                const glm::vec3 t = perpendicularTangent(n);
                QVERIFY(std::abs(glm::length(t) - 1.0f) < 1e-5f);
                QVERIFY(std::abs(glm::dot(t, n)) < 1e-5f);
            }
    }

    void generatedTangentsMatchAnalytic()
    {
        // The generator, run on primitives whose exact tangents are known, must reproduce them.
        // Where a vertex has triangles on both sides the chord directions average back to the
        // exact tangent; on the u = 0/1 seam it has them on one side only and is off by half a
        // segment (360 / 64 / 2 = 2.8 degrees on the sphere): hence worst < 3, mean < 0.5.
        for (const Mesh& reference : {makeSphere(), makeShaderBall(), makeTorus(), makeCube()}) {
            Mesh mesh = reference;
            for (Vertex& v : mesh.vertices)
                v.tangent = {0, 0, 0, 0};
            TangentStats stats;
            QVERIFY(generateTangents(mesh, nullptr, &stats));
            QCOMPARE(stats.fallbackVertices, std::size_t(0));
            double worst = 0.0, sum = 0.0;
            for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
                const double angle = angleDegrees(
                    glm::vec3(mesh.vertices[i].tangent), glm::vec3(reference.vertices[i].tangent));
                worst = std::max(worst, angle);
                sum += angle;
                QCOMPARE(mesh.vertices[i].tangent.w, reference.vertices[i].tangent.w);
            }
            const double mean = sum / double(mesh.vertices.size());
            qInfo("%s: generated vs analytic tangents: worst %.3g, mean %.3g degrees", reference.name.c_str(),
                worst, mean);
            QVERIFY2(worst < 3.0 && mean < 0.5, reference.name.c_str());
        }
    }

    // ---- UV fallback --------------------------------------------------------------------
    void boxProjection()
    {
        // The sphere without UVs: box projection puts each triangle in one chart, splits the
        // vertices between charts, and gives w = +1 tangents that agree with the UVs.
        Mesh mesh = makeSphere();
        mesh.hasUvs = mesh.hasTangents = false;
        const std::size_t before = mesh.vertices.size();
        std::string problem;
        QVERIFY2(ensureTangentFrame(mesh, UvProjection::Box, &problem), problem.c_str());
        QVERIFY(mesh.hasUvs && mesh.uvsGenerated && mesh.hasTangents);
        QVERIFY(mesh.vertices.size() > before);
        QVERIFY2(mesh.validate(&problem), problem.c_str());
        const auto& faces = boxProjectionFaces();
        for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
            // Which chart the face normal picks; every corner's UV is that chart's projection.
            const glm::vec3 p0 = mesh.vertices[mesh.indices[t]].position;
            const glm::vec3 n = glm::cross(mesh.vertices[mesh.indices[t + 1]].position - p0,
                mesh.vertices[mesh.indices[t + 2]].position - p0);
            const auto chart
                = std::max_element(faces.begin(), faces.end(), [&](const BoxFace& a, const BoxFace& b) {
                      return glm::dot(a.normal, n) < glm::dot(b.normal, n);
                  });
            for (int k = 0; k < 3; ++k) {
                const Vertex& v = mesh.vertices[mesh.indices[t + k]];
                const glm::vec2 expected(0.5f + 0.5f * glm::dot(v.position, chart->tangent),
                    0.5f + 0.5f * glm::dot(v.position, chart->bitangent));
                QVERIFY(glm::length(v.uv - expected) < 1e-5f);
            }
        }
        for (const Vertex& v : mesh.vertices)
            QCOMPARE(v.tangent.w, 1.0f);
        const FrameAgreement frame = frameAgreement(mesh);
        QCOMPARE(frame.bitangentAgrees, frame.corners);
        QVERIFY2(frame.tangentFraction() > 0.999, qPrintable(QString::number(frame.tangentFraction())));
        // Splitting keeps the surface closed.
        QString why;
        QVERIFY2(isClosed(mesh, &why), qPrintable(why));
    }

    void sphericalProjection()
    {
        // On the sphere itself the spherical fallback reproduces the primitive's own UVs
        // (up to the seam's u + 1 and the poles' mid-segment u) and no triangle spans the seam.
        const Mesh reference = makeSphere();
        Mesh mesh = reference;
        mesh.hasUvs = mesh.hasTangents = false;
        for (Vertex& v : mesh.vertices)
            v.uv = {-7, -7};
        std::string problem;
        QVERIFY2(generateUvs(mesh, UvProjection::Spherical, &problem), problem.c_str());
        QVERIFY(mesh.uvsGenerated && !mesh.hasTangents);
        QVERIFY2(generateTangents(mesh, &problem), problem.c_str());
        QVERIFY2(mesh.validate(&problem), problem.c_str());
        for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
            float lo = 10, hi = -10;
            for (int k = 0; k < 3; ++k) {
                const Vertex& v = mesh.vertices[mesh.indices[t + k]];
                lo = std::min(lo, v.uv.x);
                hi = std::max(hi, v.uv.x);
                QVERIFY(std::abs(std::asin(v.position.y) / float(kPi) + 0.5f - v.uv.y) < 1e-5f);
            }
            QVERIFY2(hi - lo < 1.5f / 64.0f,
                qPrintable(QStringLiteral("triangle %1 spans u %2..%3").arg(t / 3).arg(lo).arg(hi)));
        }
        for (std::size_t i = 0; i < reference.vertices.size(); ++i) {
            const float du = std::abs(mesh.vertices[i].uv.x - reference.vertices[i].uv.x);
            QVERIFY(du < 1e-5f || std::abs(du - 1.0f) < 1e-5f);
        }
        const FrameAgreement frame = frameAgreement(mesh);
        QCOMPARE(frame.tangentAgrees, frame.corners);
        QCOMPARE(frame.bitangentAgrees, frame.corners);
        QString why;
        QVERIFY2(isClosed(mesh, &why), qPrintable(why));
        QCOMPARE(uvProjectionFromName(uvProjectionName(UvProjection::Spherical)), UvProjection::Spherical);
        QCOMPARE(uvProjectionFromName(uvProjectionName(UvProjection::Box)), UvProjection::Box);
        QVERIFY(!uvProjectionFromName("planar"));
    }

    // ---- Import -------------------------------------------------------------------------
    void importSampleMeshes_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("fileVertices");
        QTest::addColumn<int>("triangles");
        QTest::addColumn<QVector<float>>("boundsMinMax");
        // Counts and bounds from the files' glTF accessors (POSITION min/max, index count / 3).
        QTest::newRow("suzi") << QStringLiteral("suzi") << 7503 << 14842
                              << QVector<float> {-0.92973012f, -0.66979480f, -0.54478627f, 0.92973012f,
                                     0.66825354f, 0.57615846f};
        QTest::newRow("bunny") << QStringLiteral("bunny") << 2826 << 5648
                               << QVector<float> {-0.91377079f, -0.89104164f, -0.69637245f, 0.91721433f,
                                      0.93988293f, 0.69886428f};
    }
    void importSampleMeshes()
    {
        QFETCH(QString, name);
        QFETCH(int, fileVertices);
        QFETCH(int, triangles);
        QFETCH(QVector<float>, boundsMinMax);
        const QString path = facet::test::modelPath(name);
        FACET_REQUIRE_ASSET(path, qPrintable(name + QStringLiteral(".glb")));
        std::string error, warning;
        QElapsedTimer timer;
        timer.start();
        const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
        const qint64 ms = timer.elapsed();
        QVERIFY2(mesh, error.c_str());
        qInfo("%s: %d file vertices -> %zu after UV seams, %zu triangles, imported in %lld ms",
            qPrintable(name), fileVertices, mesh->vertices.size(), mesh->triangleCount(), ms);
        QCOMPARE(mesh->triangleCount(), std::size_t(triangles));
        // The fallback splits vertices along chart seams: more than the file's, not absurdly many.
        QVERIFY(mesh->vertices.size() > std::size_t(fileVertices));
        QVERIFY(mesh->vertices.size() < std::size_t(2 * fileVertices));
        QVERIFY(mesh->hasUvs && mesh->uvsGenerated && mesh->hasTangents);
        QVERIFY2(contains(warning, "importMesh: " + path.toStdString() + ": ") && contains(warning, "no UVs"),
            warning.c_str());
        std::string problem;
        QVERIFY2(mesh->validate(&problem), problem.c_str());
        QCOMPARE(mesh->name, name.toStdString());
        QCOMPARE(mesh->subMeshes.size(), std::size_t(1));
        // Not normalised on import: the bounds are the file's.
        for (int k = 0; k < 3; ++k) {
            QVERIFY(std::abs(mesh->bounds.min[k] - boundsMinMax[k]) < 1e-4f);
            QVERIFY(std::abs(mesh->bounds.max[k] - boundsMinMax[3 + k]) < 1e-4f);
        }
        // Outward normals (the file's) and box-projected tangent frames that follow the UVs.
        // Every corner agrees on both files today; 0.1% leaves room for a sliver triangle whose
        // smooth vertex normal leans past its face normal, while a flipped sign or a wrong
        // chart fails by far.
        const FrameAgreement frame = frameAgreement(*mesh);
        qInfo("%s: frame agreement: tangent %.5f, bitangent %.5f, normal %.5f over %zu corners",
            qPrintable(name), frame.tangentFraction(), frame.bitangentFraction(), frame.normalFraction(),
            frame.corners);
        QVERIFY(frame.tangentFraction() > 0.999);
        QVERIFY(frame.bitangentFraction() > 0.999);
        QVERIFY(frame.normalFraction() > 0.999);
        for (const Vertex& v : mesh->vertices)
            QCOMPARE(v.tangent.w, 1.0f); // no box chart is mirrored
        // Framing for the viewer is the caller's step, and works on it.
        Mesh framed = *mesh;
        framed.normalizeToUnitSphere();
        QVERIFY(std::abs(framed.boundingSphereRadius() - 1.0f) < 1e-5f);

        // The spherical fallback also yields a valid frame.
        MeshImportOptions options;
        options.uvFallback = UvProjection::Spherical;
        const std::optional<Mesh> spherical = importMesh(path.toStdString(), &error, &warning, options);
        QVERIFY2(spherical, error.c_str());
        QVERIFY2(spherical->validate(&problem), problem.c_str());
        QVERIFY(contains(warning, "spherical projection"));
    }

    void importFileWithUvs()
    {
        // pmndrs.glb has UVs: they are kept, nothing is generated.
        const QString path = facet::test::modelPath(QStringLiteral("pmndrs"));
        FACET_REQUIRE_ASSET(path, "pmndrs.glb");
        std::string error, warning;
        const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
        QVERIFY2(mesh, error.c_str());
        QVERIFY(mesh->hasUvs && !mesh->uvsGenerated && mesh->hasTangents);
        QCOMPARE(mesh->triangleCount(), std::size_t(1552));
        std::string problem;
        QVERIFY2(mesh->validate(&problem), problem.c_str());
        QVERIFY2(!contains(warning, "UVs"), warning.c_str());
    }

    void importObjTangents()
    {
        // Three quads facing +Z as separate OBJ objects, UVs straight, turned and mirrored
        // (OBJ's UV origin is bottom-left, as ours): the tangents must follow.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("quads.obj"));
        QVERIFY(writeFile(path,
            "# three unit quads facing +Z\n"
            "vn 0 0 1\n"
            "o straight\n"
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
            "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
            "f 1/1/1 2/2/1 3/3/1 4/4/1\n"
            "o turned\n"
            "v 2 0 0\nv 3 0 0\nv 3 1 0\nv 2 1 0\n"
            "vt 0 1\nvt 0 0\nvt 1 0\nvt 1 1\n"
            "f 5/5/1 6/6/1 7/7/1 8/8/1\n"
            "o mirrored\n"
            "v 4 0 0\nv 5 0 0\nv 5 1 0\nv 4 1 0\n"
            "vt 1 0\nvt 0 0\nvt 0 1\nvt 1 1\n"
            "f 9/9/1 10/10/1 11/11/1 12/12/1\n"));
        std::string error, warning;
        const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
        QVERIFY2(mesh, error.c_str());
        QVERIFY(mesh->hasUvs && !mesh->uvsGenerated && mesh->hasTangents);
        QCOMPARE(mesh->triangleCount(), std::size_t(6));
        QCOMPARE(mesh->subMeshes.size(), std::size_t(3));
        const std::map<std::string, std::pair<glm::vec3, float>> expected = {{"straight", {{1, 0, 0}, 1.0f}},
            {"turned", {{0, 1, 0}, 1.0f}}, {"mirrored", {{-1, 0, 0}, -1.0f}}};
        for (const SubMesh& sub : mesh->subMeshes) {
            QVERIFY2(expected.count(sub.name), sub.name.c_str());
            const auto& [tangent, w] = expected.at(sub.name);
            QCOMPARE(sub.indexCount, 6u);
            for (uint32_t i = sub.firstIndex; i < sub.firstIndex + sub.indexCount; ++i) {
                const Vertex& v = mesh->vertices[mesh->indices[i]];
                QVERIFY2(glm::length(glm::vec3(v.tangent) - tangent) < 1e-5f, sub.name.c_str());
                QCOMPARE(v.tangent.w, w);
                QVERIFY(glm::length(v.normal - glm::vec3(0, 0, 1)) < 1e-6f);
            }
        }
    }

    void importPartlyWithoutUvs()
    {
        // Two objects, one with UVs and one without: the first keeps its UVs, only the second
        // gets generated ones.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("partial.obj"));
        QVERIFY(writeFile(path,
            "o textured\nv 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0.1 0.2\nvt 0.3 0.2\nvt 0.3 0.4\nf 1/1 2/2 3/3\n"
            "o bare\nv 3 0 0\nv 4 0 0\nv 4 1 0\nf 4 5 6\n"));
        std::string error, warning;
        const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
        QVERIFY2(mesh, error.c_str());
        QCOMPARE(mesh->subMeshes.size(), std::size_t(2));
        QVERIFY(mesh->hasUvs && mesh->uvsGenerated && mesh->hasTangents);
        QVERIFY2(contains(warning, "1 part(s) without UVs: generated by box projection"), warning.c_str());
        const SubMesh& textured
            = mesh->subMeshes[0].name == "textured" ? mesh->subMeshes[0] : mesh->subMeshes[1];
        const SubMesh& bare = mesh->subMeshes[0].name == "textured" ? mesh->subMeshes[1] : mesh->subMeshes[0];
        QCOMPARE(textured.name, std::string("textured"));
        QCOMPARE(bare.name, std::string("bare"));
        const glm::vec2 fileUvs[3] = {{0.1f, 0.2f}, {0.3f, 0.2f}, {0.3f, 0.4f}};
        for (int k = 0; k < 3; ++k)
            QVERIFY(
                glm::length(mesh->vertices[mesh->indices[textured.firstIndex + uint32_t(k)]].uv - fileUvs[k])
                < 1e-6f);
        // The bare triangle faces +Z: the +Z chart, u along +X, v along +Y.
        const Vertex& a = mesh->vertices[mesh->indices[bare.firstIndex]];
        const Vertex& b = mesh->vertices[mesh->indices[bare.firstIndex + 1]];
        QVERIFY(b.uv.x > a.uv.x && std::abs(b.uv.y - a.uv.y) < 1e-6f);
        const FrameAgreement frame = frameAgreement(*mesh);
        QCOMPARE(frame.tangentAgrees, frame.corners);
        std::string problem;
        QVERIFY2(mesh->validate(&problem), problem.c_str());
    }

    void importAppliesNodeTransforms()
    {
        // One triangle, instanced by two nodes: a child (translated by (0, 0, 1)) of a parent
        // translated by (10, 20, 30) and scaled by 2, and a node mirrored in X and turned 90
        // degrees about Z. Positions, normals, winding and UVs must come out transformed.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("nodes.gltf"));
        const QJsonArray nodes {
            QJsonObject {{QStringLiteral("name"), QStringLiteral("parent")},
                {QStringLiteral("translation"), QJsonArray {10, 20, 30}},
                {QStringLiteral("scale"), QJsonArray {2, 2, 2}},
                {QStringLiteral("children"), QJsonArray {1}}},
            QJsonObject {{QStringLiteral("name"), QStringLiteral("child")}, {QStringLiteral("mesh"), 0},
                {QStringLiteral("translation"), QJsonArray {0, 0, 1}}},
            // Column-major: x -> (0, -1, 0) after the mirror, y -> (-1, 0, 0): det = -1.
            QJsonObject {{QStringLiteral("name"), QStringLiteral("mirror")}, {QStringLiteral("mesh"), 0},
                {QStringLiteral("matrix"), QJsonArray {0, -1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}},
            // A shear z' = z + x, moved to z = -5: it tilts the triangle's plane, and only the
            // inverse transpose turns the normal with it (the matrix itself leaves +Z alone).
            QJsonObject {{QStringLiteral("name"), QStringLiteral("shear")}, {QStringLiteral("mesh"), 0},
                {QStringLiteral("matrix"), QJsonArray {1, 0, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -5, 1}}},
        };
        QVERIFY(writeFile(path, gltfTriangle(nodes, QJsonArray {0, 2, 3}, true)));
        std::string error, warning;
        const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
        QVERIFY2(mesh, error.c_str());
        std::string problem;
        QVERIFY2(mesh->validate(&problem), problem.c_str());
        QCOMPARE(mesh->subMeshes.size(), std::size_t(3));
        QCOMPARE(mesh->triangleCount(), std::size_t(3));
        QVERIFY(mesh->hasUvs && !mesh->uvsGenerated && mesh->hasTangents);
        QCOMPARE(mesh->subMeshes[0].name, std::string("tri"));

        const auto corner = [&](std::size_t s, int k) -> const Vertex& {
            return mesh->vertices[mesh->indices[mesh->subMeshes[s].firstIndex + uint32_t(k)]];
        };
        // Instance 1: world = T(10,20,30) S(2) T(0,0,1) p = 2p + (10, 20, 32).
        const glm::vec3 expected1[3] = {{10, 20, 32}, {12, 20, 32}, {10, 22, 32}};
        for (int k = 0; k < 3; ++k) {
            QVERIFY2(
                glm::length(corner(0, k).position - expected1[k]) < 1e-5f, qPrintable(QString::number(k)));
            QVERIFY(glm::length(corner(0, k).normal - glm::vec3(0, 0, 1)) < 1e-6f);
        }
        // glTF's UV origin is top-left; ours (OpenGL) bottom-left: v' = 1 - v.
        QVERIFY(glm::length(corner(0, 0).uv - glm::vec2(0, 1)) < 1e-6f);
        QVERIFY(glm::length(corner(0, 1).uv - glm::vec2(1, 1)) < 1e-6f);
        QVERIFY(glm::length(corner(0, 2).uv - glm::vec2(0, 0)) < 1e-6f);
        // u grows along +X; glTF's v grows along +Y, so ours along -Y: a mirrored chart (w = -1).
        QVERIFY(glm::length(glm::vec3(corner(0, 0).tangent) - glm::vec3(1, 0, 0)) < 1e-5f);
        QCOMPARE(corner(0, 0).tangent.w, -1.0f);

        // Instance 2: p -> (-y, -x, z). The winding is reversed, so the face still agrees with
        // the transformed normal, which stays +Z (the inverse transpose of this matrix).
        const glm::vec3 positions2[3] = {{0, 0, 0}, {0, -1, 0}, {-1, 0, 0}};
        for (int k = 0; k < 3; ++k) {
            const auto found = std::find_if(mesh->vertices.begin(), mesh->vertices.end(),
                [&](const Vertex& v) { return glm::length(v.position - positions2[k]) < 1e-6f; });
            QVERIFY2(found != mesh->vertices.end(), qPrintable(QString::number(k)));
            QVERIFY(glm::length(found->normal - glm::vec3(0, 0, 1)) < 1e-6f);
        }
        // Instance 3: (x, y, z) -> (x, y, z + x - 5); normal along (-1, 0, 1).
        const glm::vec3 positions3[3] = {{0, 0, -5}, {1, 0, -4}, {0, 1, -5}};
        for (int k = 0; k < 3; ++k) {
            QVERIFY(glm::length(corner(2, k).position - positions3[k]) < 1e-6f);
            QVERIFY(glm::length(corner(2, k).normal - glm::normalize(glm::vec3(-1, 0, 1))) < 1e-6f);
        }
        const FrameAgreement frame = frameAgreement(*mesh);
        QCOMPARE(frame.corners, std::size_t(9));
        QCOMPARE(frame.normalAgrees, frame.corners);
        QCOMPARE(frame.tangentAgrees, frame.corners);
        QCOMPARE(frame.bitangentAgrees, frame.corners);
    }

    void importKeepsFileTangents()
    {
        // The file's TANGENTs (deliberately not what generateTangents() would make from the UVs,
        // (1, 0, 0, -1) everywhere) are kept, turned by the node's rotation: 90 degrees about +Z,
        // (x, y) -> (-y, x).
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("tangents.gltf"));
        const QJsonArray nodes {QJsonObject {{QStringLiteral("mesh"), 0},
            {QStringLiteral("rotation"), QJsonArray {0, 0, std::sqrt(0.5), std::sqrt(0.5)}}}};
        QVERIFY(writeFile(path, gltfTriangle(nodes, QJsonArray {0}, true, true)));
        std::string error, warning;
        const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
        QVERIFY2(mesh, error.c_str());
        QVERIFY(mesh->hasTangents && !mesh->uvsGenerated);
        const glm::vec3 expected[3] = {{-0.8f, 0.6f, 0.0f}, {-0.6f, 0.8f, 0.0f}, {-1.0f, 0.0f, 0.0f}};
        QCOMPARE(mesh->indices.size(), std::size_t(3));
        for (int k = 0; k < 3; ++k) {
            const Vertex& v = mesh->vertices[mesh->indices[std::size_t(k)]];
            QVERIFY2(glm::length(glm::vec3(v.tangent) - expected[k]) < 1e-5f,
                qPrintable(QStringLiteral("%1 %2 %3").arg(v.tangent.x).arg(v.tangent.y).arg(v.tangent.z)));
            QCOMPARE(v.tangent.w, -1.0f);
        }
        std::string problem;
        QVERIFY2(mesh->validate(&problem), problem.c_str());
    }

    void importGeneratesMissingNormals()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("no-normals.gltf"));
        const QJsonArray nodes {QJsonObject {{QStringLiteral("mesh"), 0}}};
        QVERIFY(writeFile(path, gltfTriangle(nodes, QJsonArray {0}, false)));
        std::string error, warning;
        const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
        QVERIFY2(mesh, error.c_str());
        QVERIFY2(contains(warning, "no normals"), warning.c_str());
        for (const Vertex& v : mesh->vertices)
            QVERIFY(glm::length(v.normal - glm::vec3(0, 0, 1)) < 1e-6f);
        std::string problem;
        QVERIFY2(mesh->validate(&problem), problem.c_str());
    }

    void importDropsPointsAndLines()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("mixed.obj"));
        QVERIFY(writeFile(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\nl 1 4\np 4\n"));
        std::string error, warning;
        const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
        QVERIFY2(mesh, error.c_str());
        QCOMPARE(mesh->triangleCount(), std::size_t(1));
        QVERIFY2(contains(warning, "2 part(s) made of points or lines dropped"), warning.c_str());
        // Only points and lines: nothing to show.
        const QString onlyLines = dir.filePath(QStringLiteral("lines.obj"));
        QVERIFY(writeFile(onlyLines, "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3\n"));
        checkImportFails(onlyLines, "no triangles");
    }

    void importLimits()
    {
        const QString path = facet::test::modelPath(QStringLiteral("suzi"));
        FACET_REQUIRE_ASSET(path, "suzi.glb");
        MeshImportOptions options;
        options.maxVertices = 1000;
        std::string error;
        QVERIFY(!importMesh(path.toStdString(), &error, nullptr, options));
        QVERIFY2(contains(error, "importMesh: " + path.toStdString() + ": 7503 vertices")
                && contains(error, "1000"),
            error.c_str());
        options = {};
        options.maxTriangles = 100;
        QVERIFY(!importMesh(path.toStdString(), &error, nullptr, options));
        QVERIFY2(contains(error, "14842 triangles"), error.c_str());
    }

    void importBadFiles()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        checkImportFails(dir.filePath(QStringLiteral("nothing-here.glb")), "does not exist");
        checkImportFails(dir.path(), "is a directory");
        std::string error;
        QVERIFY(!importMesh("", &error, nullptr));
        QVERIFY2(contains(error, "importMesh: : no file name"), error.c_str());

        const QString empty = dir.filePath(QStringLiteral("empty.obj"));
        QVERIFY(writeFile(empty, {}));
        checkImportFails(empty, "file is empty");

        const QString garbage = dir.filePath(QStringLiteral("garbage.obj"));
        QVERIFY(writeFile(
            garbage, "This is not a mesh.\nJust some text pretending to be an OBJ file.\n\x01\x02\x03\n"));
        checkImportFails(garbage, "no meshes");

        const QString notAMesh = dir.filePath(QStringLiteral("picture.png"));
        QVERIFY(writeFile(notAMesh, QByteArray("\x89PNG\r\n\x1a\n", 8) + QByteArray(64, '\0')));
        checkImportFails(notAMesh, "Assimp cannot read it");

        const QString ply = dir.filePath(QStringLiteral("bad-indices.ply"));
        QVERIFY(writeFile(ply,
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
            "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
            "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"));
        checkImportFails(ply, "out of range");
        // Assimp 5.2 hangs on a PLY header without "end_header": cut short, or the keyword damaged.
        const QByteArray plyText = readFile(ply);
        const QString cutPly = dir.filePath(QStringLiteral("cut.ply"));
        QVERIFY(writeFile(cutPly, plyText.left(plyText.indexOf("end_header") + 5)));
        checkImportFails(cutPly, "no \"end_header\" line");
        QVERIFY(writeFile(cutPly, plyText.left(plyText.indexOf("end_header") + 10))); // no newline
        checkImportFails(cutPly, "no \"end_header\" line");
        const QString damagedPly = dir.filePath(QStringLiteral("damaged.ply"));
        QVERIFY(writeFile(damagedPly,
            QByteArray(plyText).replace("end_header",
                "end_\xb8"
                "eader")));
        checkImportFails(damagedPly, "no \"end_header\" line");
        // A face list cut short leaves a face with no indices, which Assimp 5.2 validates but
        // then asserts on (an abort in Debian's build).
        const QString emptyFace = dir.filePath(QStringLiteral("empty-face.ply"));
        QVERIFY(writeFile(emptyFace, plyText.left(plyText.lastIndexOf("3 0 1 7")) + "0"));
        checkImportFails(emptyFace, "face 0 of mesh 0 has no vertices");
        const QString notPly = dir.filePath(QStringLiteral("not-really.ply"));
        QVERIFY(writeFile(notPly, "solid nothing\nendsolid nothing\n"));
        checkImportFails(notPly, "not a PLY file");

        const QString sample = facet::test::modelPath(QStringLiteral("suzi"));
        if (!sample.isEmpty()) {
            // The real file cut in half, and cut at a few other places (header, JSON, binary).
            const QByteArray whole = readFile(sample);
            QVERIFY(whole.size() > 1000);
            for (qsizetype cut :
                {whole.size() / 2, qsizetype(12), qsizetype(20), qsizetype(100), whole.size() - 1}) {
                const QString truncated = dir.filePath(QStringLiteral("truncated-%1.glb").arg(cut));
                QVERIFY(writeFile(truncated, whole.left(cut)));
                checkImportFails(truncated, "");
                if (QTest::currentTestFailed())
                    return;
            }
            // Flipped bytes in the compressed payload: fails or succeeds, never crashes; a mesh
            // that comes back is valid.
            QByteArray corrupt = whole;
            for (qsizetype i = corrupt.size() / 3; i < corrupt.size(); i += 997)
                corrupt[i] = char(corrupt[i] ^ 0x5a);
            const QString corrupted = dir.filePath(QStringLiteral("corrupted.glb"));
            QVERIFY(writeFile(corrupted, corrupt));
            std::string warning;
            if (const std::optional<Mesh> mesh = importMesh(corrupted.toStdString(), &error, &warning)) {
                std::string problem;
                QVERIFY2(mesh->validate(&problem), problem.c_str());
            } else {
                QVERIFY2(contains(error, corrupted.toStdString()), error.c_str());
            }
        }

        // A file we may not read (only meaningful when not running as root).
        const QString locked = dir.filePath(QStringLiteral("locked.obj"));
        QVERIFY(writeFile(locked, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
        QFile::setPermissions(locked, QFileDevice::Permissions());
        QFile probe(locked);
        if (!probe.open(QIODevice::ReadOnly))
            checkImportFails(locked, "cannot be read");
    }

    void importableMeshPatternsListsCommonFormats()
    {
        const std::string patterns = importableMeshPatterns();
        for (const char* pattern : {"*.obj", "*.gltf", "*.glb", "*.fbx", "*.ply", "*.dae", "*.stl"})
            QVERIFY2(contains(patterns, pattern), pattern);
    }
};

QTEST_GUILESS_MAIN(MeshTest)
#include "MeshTest.moc"
