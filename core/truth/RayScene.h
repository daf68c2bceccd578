#pragma once
// Ray-scene intersection for the ground truth of staged scenes (core/truth/SceneTruth.h,
// docs/accuracy.md "Scenes"): triangle meshes and the floor through Embree (Intel's ray-tracing
// kernels, libembree 3, built once per scene), and the reference view's unit sphere exactly, in
// double precision as the convex-object truth (core/shading/GroundTruth.h) intersects it: the
// reference sphere on a floor is the reference view's sphere, not a tessellation of it.
//
// Surfaces are numbered in the order they are added; a hit names its surface, which the
// integrator maps to a material. Meshes and the floor are two-sided for intersection; a hit says
// which side the ray came from.

#include <limits>
#include <memory>
#include <optional>
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace facet {

class Mesh;

struct RayHit {
    double distance = 0.0; // along the ray's unit direction
    glm::dvec3 position {0.0};
    // Unit normals on the side the ray came from: the triangle's (or the sphere's) and the
    // interpolated vertex normal (the sphere's own; the floor's +Y), each flipped with the
    // geometric one when the ray hit the back face.
    glm::dvec3 geometricNormal {0.0, 1.0, 0.0};
    glm::dvec3 shadingNormal {0.0, 1.0, 0.0};
    glm::dvec4 tangent {1.0, 0.0, 0.0, 1.0}; // glTF convention (w: handedness); the sphere's as sphereTangent
    glm::dvec2 uv {0.0}; // a mesh's or the floor's, interpolated; 0 on the sphere (constant materials only)
    bool backFace = false; // the ray met the surface from behind (inside a closed mesh)
    int surface = 0;
};

class RayScene {
public:
    static constexpr double kInfinity = std::numeric_limits<double>::infinity();

    RayScene();
    ~RayScene();
    RayScene(RayScene&&) noexcept;
    RayScene& operator=(RayScene&&) noexcept;
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    // The reference view's unit sphere at the origin (core/shading/ReferenceView.h). At most one.
    int addUnitSphere();
    // A mesh's triangles, positions by `model`, normals by its inverse transpose.
    int addMesh(const Mesh& mesh, const glm::dmat4& model);
    // A square of side `size` in the plane y = `height`, centred on (centre.x, centre.y) in x and z,
    // facing +Y; its uv runs 0 to 1 across it.
    int addFloor(double height, double size, const glm::dvec2& centre);
    int surfaceCount() const;

    // Builds the acceleration structure: once, after the last add and before the first ray.
    // False with *error when Embree cannot make its device or scene ("Embree: ...").
    bool commit(std::string* error);

    // The nearest hit with distance in (tMin, tMax) of the ray origin + t direction (direction
    // unit). Thread-safe after commit().
    std::optional<RayHit> intersect(const glm::dvec3& origin, const glm::dvec3& direction, double tMin = 0.0,
        double tMax = kInfinity) const;
    // Whether anything lies on the ray within (tMin, tMax): a shadow ray.
    bool occluded(const glm::dvec3& origin, const glm::dvec3& direction, double tMin = 0.0,
        double tMax = kInfinity) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m;
};

} // namespace facet
