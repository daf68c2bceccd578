#include "core/mesh/Mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vector_relational.hpp>

#include "core/support/Failure.h"
#include "core/support/Finite.h"

namespace facet {

glm::vec4 vertexColor(const Vertex& vertex)
{
    return glm::vec4(vertex.color) / 65535.0f;
}

glm::u16vec4 packVertexColor(const glm::vec4& rgba)
{
    glm::u16vec4 packed;
    for (int c = 0; c < 4; ++c) {
        const float unit = std::isnan(rgba[c]) ? 0.0f : std::clamp(rgba[c], 0.0f, 1.0f);
        packed[c] = static_cast<std::uint16_t>(std::lround(unit * 65535.0f));
    }
    return packed;
}

namespace {

// Tolerances of validate(). Everything this module writes is normalised in float (error about
// 1e-7); 1e-3 leaves room for data that other code edits and still catches a forgotten
// normalize() or a transform applied to normals without renormalising.
constexpr float kUnitTolerance = 1e-3f;
constexpr float kOrthogonalTolerance = 1e-3f;

std::string vec3Text(const glm::vec3& v)
{
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "(%.6g, %.6g, %.6g)", double(v.x), double(v.y), double(v.z));
    return buffer;
}

} // namespace

void Bounds::add(const glm::vec3& p)
{
    if (isEmpty()) {
        min = p;
        max = p;
        return;
    }
    min = glm::min(min, p);
    max = glm::max(max, p);
}

void Mesh::updateBounds()
{
    bounds = Bounds {};
    for (const Vertex& v : vertices)
        bounds.add(v.position);
}

float Mesh::boundingSphereRadius() const
{
    if (bounds.isEmpty())
        return 0.0f;
    const glm::vec3 c = bounds.center();
    // In double: the radius of a 50M-vertex scan must not depend on float rounding order.
    double r2 = 0.0;
    for (const Vertex& v : vertices) {
        const glm::dvec3 d = glm::dvec3(v.position) - glm::dvec3(c);
        r2 = std::max(r2, glm::dot(d, d));
    }
    return float(std::sqrt(r2));
}

glm::mat4 Mesh::normalizeToUnitSphere()
{
    updateBounds();
    if (bounds.isEmpty())
        return glm::mat4(1.0f);
    const glm::vec3 c = bounds.center();
    const float radius = boundingSphereRadius();
    // A mesh whose vertices all coincide (radius 0) cannot be scaled to radius 1: centre it only.
    const float scale = radius > 0.0f && std::isfinite(1.0f / radius) ? 1.0f / radius : 1.0f;
    for (Vertex& v : vertices)
        v.position = (v.position - c) * scale;
    updateBounds();
    scaleFromSource *= scale;
    // transform = S(scale) * T(-c)
    glm::mat4 m(scale);
    m[3] = glm::vec4(-c * scale, 1.0f);
    return m;
}

bool Mesh::transform(const glm::mat4& matrix, std::string* problem)
{
    const glm::mat3 linear(matrix);
    const float det = glm::determinant(linear);
    bool finite = std::isfinite(det);
    for (int c = 0; c < 4; ++c)
        finite = finite && isFinite(matrix[c]);
    // Relative singularity test: |det| against the cube of the largest column length, so a
    // uniformly tiny but valid scale (millimetres to kilometres) still passes.
    float largest = 0.0f;
    for (int c = 0; c < 3; ++c)
        largest = std::max(largest, glm::length(linear[c]));
    if (!finite || largest == 0.0f || std::abs(det) <= 1e-12f * largest * largest * largest)
        return fail("Mesh::transform: '" + name + "': the matrix is singular or not finite", problem);

    // Normals are covectors: they transform by the inverse transpose (Lengyel, "Mathematics for
    // 3D Game Programming and Computer Graphics", 3rd ed., section 4.5). Tangents and bitangents
    // are surface directions (dP/du, dP/dv) and take the matrix itself.
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));
    for (Vertex& v : vertices) {
        v.position = glm::vec3(matrix * glm::vec4(v.position, 1.0f));
        const glm::vec3 bitangent = glm::cross(v.normal, glm::vec3(v.tangent)) * v.tangent.w;
        const glm::vec3 n = glm::normalize(normalMatrix * v.normal);
        glm::vec3 t = linear * glm::vec3(v.tangent);
        t = t - n * glm::dot(n, t);
        const float tLength = glm::length(t);
        if (tLength > 0.0f && std::isfinite(tLength)) {
            t /= tLength;
            const float w = glm::dot(glm::cross(n, t), linear * bitangent) < 0.0f ? -1.0f : 1.0f;
            v.tangent = glm::vec4(t, w);
        }
        v.normal = n;
    }
    if (det < 0.0f)
        for (std::size_t i = 0; i + 2 < indices.size(); i += 3)
            std::swap(indices[i + 1], indices[i + 2]);
    updateBounds();
    return true;
}

bool Mesh::validate(std::string* problem) const
{
    const std::string prefix = "Mesh::validate: '" + name + "': ";
    const auto vertexProblem = [&](std::size_t i, const std::string& what) {
        return fail(prefix + "vertex " + std::to_string(i) + ": " + what, problem);
    };

    if (vertices.size() > std::numeric_limits<uint32_t>::max())
        return fail(prefix + "more vertices than 32-bit indices can address", problem);
    if (indices.size() % 3 != 0)
        return fail(prefix + "the index count " + std::to_string(indices.size()) + " is not a multiple of 3",
            problem);
    for (std::size_t i = 0; i < indices.size(); ++i)
        if (indices[i] >= vertices.size())
            return fail(prefix + "index " + std::to_string(i) + " is " + std::to_string(indices[i])
                    + ", out of range (" + std::to_string(vertices.size()) + " vertices)",
                problem);

    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const Vertex& v = vertices[i];
        if (!isFinite(v.position))
            return vertexProblem(i, "position is not finite");
        if (!isFinite(v.normal) || std::abs(glm::length(v.normal) - 1.0f) > kUnitTolerance)
            return vertexProblem(i, "normal " + vec3Text(v.normal) + " is not unit length");
        if (hasTexCoord1 && !isFinite(v.uv1))
            return vertexProblem(i, "second UV (TEXCOORD_1) is not finite");
        if (hasUvs && !isFinite(v.uv))
            return vertexProblem(i, "UV is not finite");
        if (hasTangents) {
            const glm::vec3 t(v.tangent);
            if (!isFinite(v.tangent) || std::abs(glm::length(t) - 1.0f) > kUnitTolerance)
                return vertexProblem(i, "tangent " + vec3Text(t) + " is not unit length");
            if (std::abs(glm::dot(t, v.normal)) > kOrthogonalTolerance)
                return vertexProblem(i,
                    "tangent " + vec3Text(t) + " is not perpendicular to the normal " + vec3Text(v.normal));
            if (v.tangent.w != 1.0f && v.tangent.w != -1.0f)
                return vertexProblem(
                    i, "tangent handedness w is " + std::to_string(v.tangent.w) + ", not +-1");
        }
        // Bounds must hold every vertex (to a relative float tolerance): render/ culls and frames by them.
        const glm::vec3 slack = 1e-5f * (glm::abs(bounds.min) + glm::abs(bounds.max) + 1.0f);
        if (bounds.isEmpty() || glm::any(glm::lessThan(v.position, bounds.min - slack))
            || glm::any(glm::greaterThan(v.position, bounds.max + slack)))
            return vertexProblem(
                i, "position " + vec3Text(v.position) + " is outside the bounds (call updateBounds())");
    }

    for (std::size_t s = 0; s < subMeshes.size(); ++s) {
        const SubMesh& sub = subMeshes[s];
        const uint64_t end = uint64_t(sub.firstIndex) + sub.indexCount;
        if (sub.firstIndex % 3 != 0 || sub.indexCount % 3 != 0 || end > indices.size())
            return fail(prefix + "sub-mesh " + std::to_string(s) + " ('" + sub.name + "') covers indices "
                    + std::to_string(sub.firstIndex) + " to " + std::to_string(end)
                    + ", not whole triangles within " + std::to_string(indices.size()),
                problem);
    }
    return true;
}

} // namespace facet
