#include "core/mesh/Tangents.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "core/mesh/Mesh.h"
#include "core/support/Failure.h"

namespace facet {

namespace {

bool indicesInRange(const Mesh& mesh)
{
    return std::all_of(
        mesh.indices.begin(), mesh.indices.end(), [&](uint32_t i) { return i < mesh.vertices.size(); });
}

// The component of v perpendicular to the unit vector n, normalised; zero when v has none.
glm::vec3 perpendicularPart(const glm::vec3& v, const glm::vec3& n)
{
    const glm::vec3 p = v - n * glm::dot(n, v);
    const float length = glm::length(p);
    return length > 0.0f && std::isfinite(length) ? p / length : glm::vec3(0.0f);
}

// Interior angle at `corner` of the triangle (corner, a, b); 0 for a degenerate corner.
float cornerAngle(const glm::vec3& corner, const glm::vec3& a, const glm::vec3& b)
{
    const glm::vec3 e1 = a - corner;
    const glm::vec3 e2 = b - corner;
    const float l1 = glm::length(e1);
    const float l2 = glm::length(e2);
    if (!(l1 > 0.0f) || !(l2 > 0.0f))
        return 0.0f;
    return std::acos(std::clamp(glm::dot(e1, e2) / (l1 * l2), -1.0f, 1.0f));
}

// Which triangles generateUvs() works on: [first, end) ranges of the index buffer.
std::vector<std::pair<std::size_t, std::size_t>> triangleRanges(
    const Mesh& mesh, const std::vector<std::size_t>& onlySubMeshes)
{
    std::vector<std::pair<std::size_t, std::size_t>> ranges;
    if (onlySubMeshes.empty()) {
        ranges.emplace_back(0, mesh.indices.size() - mesh.indices.size() % 3);
        return ranges;
    }
    for (std::size_t s : onlySubMeshes) {
        if (s >= mesh.subMeshes.size())
            continue;
        const SubMesh& sub = mesh.subMeshes[s];
        const std::size_t first = std::min<std::size_t>(sub.firstIndex, mesh.indices.size());
        const std::size_t end
            = std::min<std::size_t>(std::size_t(sub.firstIndex) + sub.indexCount, mesh.indices.size());
        ranges.emplace_back(first, first + (end - first) / 3 * 3);
    }
    return ranges;
}

// Gives each (vertex, chart) pair its own vertex: the first chart that claims a vertex keeps it,
// later charts get copies. Charts are small integers; most vertices are claimed by one chart, so
// the common case is an array lookup and only the duplicates go through a hash map.
class VertexSplitter {
public:
    explicit VertexSplitter(Mesh& mesh)
        : m_mesh(mesh)
        , m_firstChart(mesh.vertices.size(), kUnclaimed)
    {
    }

    uint32_t claim(uint32_t vertex, uint64_t chart, const glm::vec2& uv)
    {
        if (m_firstChart[vertex] == kUnclaimed) {
            m_firstChart[vertex] = chart;
            m_mesh.vertices[vertex].uv = uv;
            return vertex;
        }
        if (m_firstChart[vertex] == chart)
            return vertex;
        const auto key = std::make_pair(vertex, chart);
        const auto found = m_copies.find(key);
        if (found != m_copies.end())
            return found->second;
        Vertex copy = m_mesh.vertices[vertex];
        copy.uv = uv;
        const auto index = uint32_t(m_mesh.vertices.size());
        m_mesh.vertices.push_back(copy);
        m_copies.emplace(key, index);
        return index;
    }

private:
    static constexpr uint64_t kUnclaimed = ~uint64_t(0);
    struct PairHash {
        std::size_t operator()(const std::pair<uint32_t, uint64_t>& p) const
        {
            return std::hash<uint64_t>()((uint64_t(p.first) * 0x9E3779B97F4A7C15ull) ^ p.second);
        }
    };
    Mesh& m_mesh;
    std::vector<uint64_t> m_firstChart;
    std::unordered_map<std::pair<uint32_t, uint64_t>, uint32_t, PairHash> m_copies;
};

// The sphere primitive's longitude/latitude mapping (MeshPrimitives.cpp, docs/meshes.md).
glm::vec2 sphericalUv(const glm::vec3& d)
{
    constexpr float pi = std::numbers::pi_v<float>;
    return {0.5f - std::atan2(d.z, d.x) / (2.0f * pi), std::asin(std::clamp(d.y, -1.0f, 1.0f)) / pi + 0.5f};
}

void boxProject(Mesh& mesh, const std::vector<std::pair<std::size_t, std::size_t>>& ranges,
    const glm::vec3& centre, float scale)
{
    const auto& faces = boxProjectionFaces();
    VertexSplitter splitter(mesh);
    for (const auto& [first, end] : ranges)
        for (std::size_t t = first; t < end; t += 3) {
            uint32_t* corner = &mesh.indices[t];
            const glm::vec3 p0 = mesh.vertices[corner[0]].position;
            const glm::vec3 p1 = mesh.vertices[corner[1]].position;
            const glm::vec3 p2 = mesh.vertices[corner[2]].position;
            glm::vec3 n = glm::cross(p1 - p0, p2 - p0);
            // A zero-area triangle has no face normal: its vertex normals say where it faces.
            if (!(glm::dot(n, n) > 0.0f))
                n = mesh.vertices[corner[0]].normal + mesh.vertices[corner[1]].normal
                    + mesh.vertices[corner[2]].normal;
            const glm::vec3 a = glm::abs(n);
            const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
            const int face = 2 * axis + (n[axis] < 0.0f ? 1 : 0);
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 q = (mesh.vertices[corner[k]].position - centre) * scale;
                const glm::vec2 uv(0.5f + 0.5f * glm::dot(q, faces[face].tangent),
                    0.5f + 0.5f * glm::dot(q, faces[face].bitangent));
                corner[k] = splitter.claim(corner[k], uint64_t(face), uv);
            }
        }
}

void sphereProject(
    Mesh& mesh, const std::vector<std::pair<std::size_t, std::size_t>>& ranges, const glm::vec3& centre)
{
    // Charts: 0 the plain mapping, 1 the copy with u + 1 on the far side of the seam, 2 + t a
    // pole vertex's copy for triangle t (its u is the mean of the other two corners', as the
    // sphere primitive places its pole vertices mid-segment).
    constexpr float kPole = 1.0f - 1e-6f;
    VertexSplitter splitter(mesh);
    for (const auto& [first, end] : ranges)
        for (std::size_t t = first; t < end; t += 3) {
            uint32_t* corner = &mesh.indices[t];
            glm::vec2 uv[3];
            bool pole[3];
            for (int k = 0; k < 3; ++k) {
                const Vertex& v = mesh.vertices[corner[k]];
                glm::vec3 d = v.position - centre;
                const float length = glm::length(d);
                // A vertex at the centre has no direction: its normal stands in.
                d = length > 0.0f ? d / length : v.normal;
                uv[k] = sphericalUv(d);
                pole[k] = std::abs(d.y) > kPole;
            }
            // The seam: a triangle whose u values span more than half the circle wraps around
            // u = 0/1; its corners on the low side move up by one.
            float lo = 2.0f, hi = -1.0f;
            for (int k = 0; k < 3; ++k)
                if (!pole[k]) {
                    lo = std::min(lo, uv[k].x);
                    hi = std::max(hi, uv[k].x);
                }
            const bool wraps = hi - lo > 0.5f;
            uint64_t chart[3] = {0, 0, 0};
            for (int k = 0; k < 3; ++k)
                if (wraps && !pole[k] && uv[k].x < 0.5f) {
                    uv[k].x += 1.0f;
                    chart[k] = 1;
                }
            for (int k = 0; k < 3; ++k)
                if (pole[k]) {
                    float sum = 0.0f;
                    int count = 0;
                    for (int j = 0; j < 3; ++j)
                        if (!pole[j]) {
                            sum += uv[j].x;
                            ++count;
                        }
                    uv[k].x = count > 0 ? sum / float(count) : 0.5f;
                    chart[k] = 2 + uint64_t(t / 3);
                }
            for (int k = 0; k < 3; ++k)
                corner[k] = splitter.claim(corner[k], chart[k], uv[k]);
        }
}

} // namespace

glm::vec3 perpendicularTangent(const glm::vec3& n)
{
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    return {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
}

const std::array<BoxFace, 6>& boxProjectionFaces()
{
    // Each chart reads like a cubemap face seen from outside: u to the right, v up, with +Y's
    // top edge toward -Z and -Y's toward +Z. cross(tangent, bitangent) == normal for all six.
    static const std::array<BoxFace, 6> faces {{
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},
        {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},
        {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},
        {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
    }};
    return faces;
}

std::string_view uvProjectionName(UvProjection projection)
{
    return projection == UvProjection::Spherical ? "spherical" : "box";
}

std::optional<UvProjection> uvProjectionFromName(std::string_view name)
{
    if (name == "box")
        return UvProjection::Box;
    if (name == "spherical")
        return UvProjection::Spherical;
    return std::nullopt;
}

bool generateTangents(Mesh& mesh, std::string* problem, TangentStats* stats)
{
    const std::string prefix = "generateTangents: '" + mesh.name + "': ";
    if (!mesh.hasUvs)
        return fail(prefix + "the mesh has no UVs (generateUvs() first)", problem);
    if (!indicesInRange(mesh))
        return fail(prefix + "an index is out of range", problem);

    TangentStats counts;
    std::vector<glm::vec3> tangentSum(mesh.vertices.size(), glm::vec3(0.0f));
    std::vector<glm::vec3> bitangentSum(mesh.vertices.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const uint32_t index[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
        const Vertex* v[3] = {&mesh.vertices[index[0]], &mesh.vertices[index[1]], &mesh.vertices[index[2]]};
        // dP/du and dP/dv of the linear map from UV to position over the triangle: with
        // e1 = P1 - P0, e2 = P2 - P0 and their UV differences (s1, t1), (s2, t2),
        // [e1 e2] = [dP/du dP/dv] [[s1 s2] [t1 t2]], inverted by Cramer's rule (Lengyel,
        // "Computing Tangent Space Basis Vectors for an Arbitrary Mesh", 2001).
        const glm::vec3 e1 = v[1]->position - v[0]->position;
        const glm::vec3 e2 = v[2]->position - v[0]->position;
        const glm::vec2 d1 = v[1]->uv - v[0]->uv;
        const glm::vec2 d2 = v[2]->uv - v[0]->uv;
        const float det = d1.x * d2.y - d2.x * d1.y; // twice the signed UV area
        const glm::vec3 dPdu = (e1 * d2.y - e2 * d1.y) / det;
        const glm::vec3 dPdv = (e2 * d1.x - e1 * d2.x) / det;
        const float geometricArea2 = glm::dot(glm::cross(e1, e2), glm::cross(e1, e2));
        // As libmikktspace, a triangle with no UV area (or no area at all) says nothing about
        // the direction of u and is skipped; its vertices take the neighbours' tangents.
        if (det == 0.0f || !(geometricArea2 > 0.0f) || !std::isfinite(glm::dot(dPdu, dPdu))
            || !std::isfinite(glm::dot(dPdv, dPdv))) {
            ++counts.degenerateTriangles;
            continue;
        }
        for (int k = 0; k < 3; ++k) {
            // Angle weights make the sum independent of how a fan around the vertex is
            // triangulated (MikkTSpace does the same; Thurmer and Wuthrich 1998 for normals).
            const float angle
                = cornerAngle(v[k]->position, v[(k + 1) % 3]->position, v[(k + 2) % 3]->position);
            tangentSum[index[k]] += angle * perpendicularPart(dPdu, v[k]->normal);
            bitangentSum[index[k]] += angle * perpendicularPart(dPdv, v[k]->normal);
        }
    }

    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        Vertex& v = mesh.vertices[i];
        const glm::vec3& n = v.normal;
        glm::vec3 t = perpendicularPart(tangentSum[i], n);
        const glm::vec3 b = perpendicularPart(bitangentSum[i], n);
        // When the u directions cancelled out (e.g. a vertex on a mirror seam that shares its
        // UV) but v survived, u is the right-handed complement of v.
        if (t == glm::vec3(0.0f) && b != glm::vec3(0.0f))
            t = perpendicularPart(glm::cross(b, n), n);
        if (t == glm::vec3(0.0f)) {
            ++counts.fallbackVertices;
            t = perpendicularTangent(n);
        }
        const float w = glm::dot(glm::cross(n, t), b) < 0.0f ? -1.0f : 1.0f;
        v.tangent = glm::vec4(t, w);
    }
    mesh.hasTangents = true;
    if (stats)
        *stats = counts;
    return true;
}

bool generateUvs(
    Mesh& mesh, UvProjection projection, std::string* problem, const std::vector<std::size_t>& onlySubMeshes)
{
    const std::string prefix = "generateUvs: '" + mesh.name + "': ";
    if (!indicesInRange(mesh))
        return fail(prefix + "an index is out of range", problem);
    for (std::size_t s : onlySubMeshes)
        if (s >= mesh.subMeshes.size())
            return fail(prefix + "no sub-mesh " + std::to_string(s), problem);

    mesh.updateBounds();
    const glm::vec3 centre = mesh.boundingSphereCenter();
    const float radius = mesh.boundingSphereRadius();
    const float scale = radius > 0.0f ? 1.0f / radius : 1.0f;
    const auto ranges = triangleRanges(mesh, onlySubMeshes);
    if (projection == UvProjection::Spherical)
        sphereProject(mesh, ranges, centre);
    else
        boxProject(mesh, ranges, centre, scale);
    mesh.hasUvs = true;
    mesh.uvsGenerated = true;
    mesh.hasTangents = false;
    mesh.updateBounds();
    return true;
}

bool ensureTangentFrame(Mesh& mesh, UvProjection fallback, std::string* problem)
{
    if (!mesh.hasUvs && !generateUvs(mesh, fallback, problem))
        return false;
    return mesh.hasTangents || generateTangents(mesh, problem);
}

} // namespace facet
