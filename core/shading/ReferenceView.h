#pragma once
// The reference view of docs/architecture.md, used by the headless renderer, the benchmarks and the
// accuracy tests: a unit sphere at the origin, a pinhole camera at (0, 0, 3) looking at the
// origin, +Y up, 45 degree vertical field of view, square image, one ray through each pixel
// centre. Pixel (0, 0) is the top-left of the image.

#include <cmath>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace facet::referenceview {

inline constexpr double kVerticalFovDegrees = 45.0;
inline const glm::dvec3 kEye {0.0, 0.0, 3.0};
inline constexpr double kSphereRadius = 1.0;

// World-space direction of the ray through the centre of pixel (x, y) of a width x height image.
inline glm::dvec3 rayDirection(int x, int y, int width, int height)
{
    const double tanHalf = std::tan(kVerticalFovDegrees * std::numbers::pi / 360.0);
    const double aspect = double(width) / double(height);
    const double sx = ((double(x) + 0.5) / width * 2.0 - 1.0) * tanHalf * aspect;
    const double sy = (1.0 - (double(y) + 0.5) / height * 2.0) * tanHalf;
    return glm::normalize(glm::dvec3(sx, sy, -1.0));
}

// Nearest intersection of the ray (kEye, direction) with the unit sphere, as the hit point
// (which is also the outward normal); nullopt on a miss.
inline std::optional<glm::dvec3> intersectSphere(const glm::dvec3& direction)
{
    // |e + t d|^2 = 1  ->  t^2 + 2 (e.d) t + (e.e - 1) = 0
    const double b = glm::dot(kEye, direction);
    const double c = glm::dot(kEye, kEye) - kSphereRadius * kSphereRadius;
    const double discriminant = b * b - c;
    if (discriminant < 0.0)
        return std::nullopt;
    const double t = -b - std::sqrt(discriminant);
    if (t <= 0.0)
        return std::nullopt;
    return glm::normalize(kEye + t * direction);
}

// The glTF tangent (xyz along dP/du, w = +1) of the sphere mesh the real-time renderer draws
// (core/mesh/MeshPrimitives.h makeSphere: u = 0.5 - atan2(z, x) / (2 pi)) at the unit point p:
// (z, 0, -x) normalised, +X at the front. The ground truth's tangent frame (anisotropy); zero at
// the poles, which the reference view does not see.
inline glm::dvec4 sphereTangent(const glm::dvec3& p)
{
    const glm::dvec3 t(p.z, 0.0, -p.x);
    const double length = glm::length(t);
    return length > 0.0 ? glm::dvec4(t / length, 1.0) : glm::dvec4(0.0, 0.0, 0.0, 1.0);
}

// True when pixel (x, y) sees the sphere and none of its neighbours sees the background: the
// pixels an accuracy comparison uses, away from the silhouette where a tessellated sphere and
// the analytic one disagree.
inline bool isInteriorSpherePixel(int x, int y, int width, int height, int margin = 1)
{
    for (int dy = -margin; dy <= margin; ++dy)
        for (int dx = -margin; dx <= margin; ++dx)
            if (!intersectSphere(rayDirection(x + dx, y + dy, width, height)))
                return false;
    return true;
}

} // namespace facet::referenceview
