#include "core/mesh/MeshPicking.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "core/mesh/Mesh.h"
#include "core/project/Camera.h"
#include "core/support/Finite.h"

namespace facet {

namespace {

// Slab test of the ray against the (object-space) box, for t in (0, tMax]; a cheap rejection of
// clicks beside the object before the triangle loop.
bool hitsBox(const Bounds& box, const glm::dvec3& origin, const glm::dvec3& direction)
{
    if (box.isEmpty())
        return false;
    double tNear = 0.0;
    double tFar = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        const double lo = box.min[axis];
        const double hi = box.max[axis];
        if (direction[axis] == 0.0) {
            if (origin[axis] < lo || origin[axis] > hi)
                return false;
            continue;
        }
        double t0 = (lo - origin[axis]) / direction[axis];
        double t1 = (hi - origin[axis]) / direction[axis];
        if (t0 > t1)
            std::swap(t0, t1);
        tNear = std::max(tNear, t0);
        tFar = std::min(tFar, t1);
        // A little slack: a hit on the box's face must not be lost to rounding.
        if (tNear > tFar * (1.0 + 1e-9) + 1e-12)
            return false;
    }
    return true;
}

struct TriangleHit {
    double t = 0.0;
    double u = 0.0;
    double v = 0.0;
    double determinant = 0.0; // > 0: counter-clockwise seen along the ray (front face)
};

// Möller & Trumbore 1997, without the back-face branch (both sides; the caller culls by the
// determinant's sign). t > epsilon only: hits behind or at the origin do not count.
std::optional<TriangleHit> intersect(const glm::dvec3& origin, const glm::dvec3& direction,
    const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2)
{
    const glm::dvec3 edge1 = p1 - p0;
    const glm::dvec3 edge2 = p2 - p0;
    const glm::dvec3 pvec = glm::cross(direction, edge2);
    const double determinant = glm::dot(edge1, pvec);
    // Parallel to the triangle's plane (or a degenerate triangle): relative to the sizes involved.
    const double scale = glm::length(edge1) * glm::length(pvec);
    if (!(std::abs(determinant) > 1e-14 * scale))
        return std::nullopt;
    const double inverse = 1.0 / determinant;
    const glm::dvec3 tvec = origin - p0;
    const double u = glm::dot(tvec, pvec) * inverse;
    if (u < 0.0 || u > 1.0)
        return std::nullopt;
    const glm::dvec3 qvec = glm::cross(tvec, edge1);
    const double v = glm::dot(direction, qvec) * inverse;
    if (v < 0.0 || u + v > 1.0)
        return std::nullopt;
    const double t = glm::dot(edge2, qvec) * inverse;
    if (!(t > 1e-12))
        return std::nullopt;
    // Möller-Trumbore's determinant is dot(edge1, direction x edge2) = -dot(direction, edge1 x edge2):
    // positive when the ray meets the counter-clockwise (front) side.
    return TriangleHit {t, u, v, determinant};
}

} // namespace

std::optional<MeshHit> pickMesh(
    const Mesh& mesh, const glm::dmat4& model, const PickRay& ray, const std::vector<PickPart>& parts)
{
    if (mesh.indices.size() < 3 || !isFinite(model) || !isFinite(ray.origin) || !isFinite(ray.direction)
        || glm::length(ray.direction) == 0.0)
        return std::nullopt;
    const double modelDeterminant = glm::determinant(glm::dmat3(model));
    if (!std::isfinite(modelDeterminant) || std::abs(modelDeterminant) < 1e-300)
        return std::nullopt;
    // Into object space: for an affine map the ray parameter t is the same on both sides, so the
    // nearest hit there is the nearest in the world and t is the world distance in ray units.
    const glm::dmat4 toObject = glm::inverse(model);
    const glm::dvec3 origin = glm::dvec3(toObject * glm::dvec4(ray.origin, 1.0));
    const glm::dvec3 direction = glm::dvec3(toObject * glm::dvec4(ray.direction, 0.0));
    if (!isFinite(origin) || !isFinite(direction) || !hitsBox(mesh.bounds, origin, direction))
        return std::nullopt;
    // A mirroring model reverses the winding on screen (the renderer flips its front face then).
    const bool mirrored = modelDeterminant < 0.0;

    // A mesh without sub-meshes is one part: every triangle.
    std::vector<SubMesh> ranges = mesh.subMeshes;
    if (ranges.empty())
        ranges.push_back(SubMesh {mesh.name, 0, uint32_t(mesh.indices.size()), -1, true});

    std::optional<MeshHit> nearest;
    for (std::size_t part = 0; part < ranges.size(); ++part) {
        const PickPart pick = part < parts.size() ? parts[part] : PickPart {};
        if (!pick.visible)
            continue;
        const SubMesh& range = ranges[part];
        const std::size_t end
            = std::min<std::size_t>(std::size_t(range.firstIndex) + range.indexCount, mesh.indices.size());
        for (std::size_t i = range.firstIndex; i + 3 <= end; i += 3) {
            const uint32_t a = mesh.indices[i];
            const uint32_t b = mesh.indices[i + 1];
            const uint32_t c = mesh.indices[i + 2];
            if (a >= mesh.vertices.size() || b >= mesh.vertices.size() || c >= mesh.vertices.size())
                continue;
            const auto hit = intersect(origin, direction, glm::dvec3(mesh.vertices[a].position),
                glm::dvec3(mesh.vertices[b].position), glm::dvec3(mesh.vertices[c].position));
            if (!hit || (nearest && hit->t >= nearest->distance))
                continue;
            const bool front = (hit->determinant > 0.0) != mirrored;
            if (!front && pick.cullsBackFaces)
                continue;
            MeshHit result;
            result.subMesh = part;
            result.triangle = i / 3;
            result.distance = hit->t;
            result.position = ray.origin + hit->t * ray.direction;
            result.barycentric = {hit->u, hit->v};
            result.frontFace = front;
            nearest = result;
        }
    }
    return nearest;
}

PickRay cameraRay(const Camera& camera, double width, double height, const glm::dvec2& pixel)
{
    // Normalised device coordinates of the point (y up), then the view-space direction through it
    // for Camera::projectionMatrix's symmetric frustum: x scaled by aspect * tan(fov / 2).
    const double aspect = width / height;
    const double tanHalf = std::tan(glm::radians(camera.verticalFovDegrees) / 2.0);
    const double ndcX = 2.0 * pixel.x / width - 1.0;
    const double ndcY = 1.0 - 2.0 * pixel.y / height;
    const glm::dvec3 inView(ndcX * aspect * tanHalf, ndcY * tanHalf, -1.0);
    const glm::dmat4 toWorld = glm::inverse(camera.viewMatrix());
    PickRay ray;
    ray.origin = camera.position;
    ray.direction = glm::normalize(glm::dvec3(toWorld * glm::dvec4(inView, 0.0)));
    return ray;
}

} // namespace facet
