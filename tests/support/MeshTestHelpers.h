#pragma once
// Helpers shared by the mesh tests (MeshTest, MeshImportTest): geometric checks of meshes and
// small files written with known answers.

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
#include "core/mesh/Mesh.h"
#include "core/mesh/MeshImport.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/mesh/Tangents.h"

namespace facet::test::mesh {

using namespace facet;

inline constexpr double kPi = std::numbers::pi;

inline bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

inline bool writeFile(const QString& path, const QByteArray& data)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(data) == data.size();
}

inline QByteArray readFile(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// Signed volume by the divergence theorem: sum over triangles of p0 . (p1 x p2) / 6. Positive
// for a closed mesh wound counter-clockwise from outside.
inline double signedVolume(const Mesh& mesh)
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
inline bool isClosed(const Mesh& mesh, QString* why)
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

inline FrameAgreement frameAgreement(const Mesh& mesh)
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

inline bool isClosedPrimitive(std::string_view name)
{
    return name != "plane";
}

// A mesh from a list of triangles (positions and UVs), flat normals, for the tangent tests.
inline Mesh triangles(const std::vector<glm::vec3>& positions, const std::vector<glm::vec2>& uvs)
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

inline double angleDegrees(const glm::vec3& a, const glm::vec3& b)
{
    const double c = glm::dot(glm::dvec3(glm::normalize(a)), glm::dvec3(glm::normalize(b)));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / kPi;
}

// glTF 2.0 (.gltf, JSON with the buffer embedded as a base64 data URI) holding one triangle
// in the XY plane facing +Z, UVs (0,0) (1,0) (0,1) in glTF's top-left convention, and the given
// node hierarchy. `withNormals` false leaves the NORMAL attribute out; `withTangents` adds a
// TANGENT attribute, (0.6, 0.8, 0), (0.8, 0.6, 0), (0, 1, 0) with w = -1. (Not one tangent for
// all three: Assimp's FindInvalidData drops a tangent array whose elements are all equal.)
inline QByteArray gltfTriangle(
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
inline void checkImportFails(const QString& path, const char* expectedPart)
{
    std::string error, warning = "stale";
    const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
    QVERIFY2(!mesh, qPrintable(path));
    QVERIFY2(contains(error, "importMesh: " + path.toStdString() + ": "), error.c_str());
    QVERIFY2(contains(error, expectedPart), error.c_str());
    QVERIFY(warning.empty());
}

} // namespace facet::test::mesh
