#pragma once
// Which part of a mesh is under a pixel: a CPU ray cast against the triangles (no GL, so the same
// answer whatever the viewport drew at reduced resolution). The window uses it to make the
// material of the clicked part the one the docks edit (ui/viewport/PartPicker.h).
//
// The ray is in world space; the mesh is drawn with `model` (world = model * object), exactly as
// render/ draws it, so a turntable rotation or any affine transform is honoured. Hidden parts are
// not hit, and a part whose faces are culled from behind (a single-sided material) is not hit
// from behind: a click goes through to what the viewport shows there. Alpha-masked cut-outs are
// NOT taken into account (that would need the textures): a click on a hole hits the part.

#include <cstddef>
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace facet {

class Mesh;
struct Camera;

struct PickRay {
    glm::dvec3 origin {0.0};
    glm::dvec3 direction {0.0, 0.0, -1.0}; // need not be unit length; hit distances are in its units
};

// How one sub-mesh takes part in picking (index = sub-mesh index; a sub-mesh without an entry is
// pickable from both sides, as the renderer draws a part without a MeshPart entry).
struct PickPart {
    bool visible = true;
    bool cullsBackFaces = false; // the part's material is single-sided (Material::doubleSided false)
};

struct MeshHit {
    std::size_t subMesh = 0; // index into Mesh::subMeshes (0 for a mesh without sub-meshes)
    std::size_t triangle = 0; // index of the triangle in Mesh::indices (first index / 3)
    double distance = 0.0; // ray parameter t: the hit is origin + t * direction (world space)
    glm::dvec3 position {0.0}; // world space
    glm::dvec2 barycentric {0.0}; // (u, v) of the hit in the triangle: p = (1-u-v) p0 + u p1 + v p2
    bool frontFace = true; // the triangle winds counter-clockwise as seen along the ray (after `model`)
};

// The nearest triangle of `mesh` (drawn with `model`) that the ray hits at t > 0, among the
// sub-meshes `parts` lets it hit; nullopt for a miss, an empty mesh, a zero direction or a
// singular / non-finite model matrix. Möller & Trumbore, "Fast, Minimum Storage Ray/Triangle
// Intersection", Journal of Graphics Tools 2(1), 1997, in double precision, on the ray taken
// into object space (t is the same there because the map is affine). Cost: linear in the
// triangles of the pickable parts (a bounding-box test first per call).
std::optional<MeshHit> pickMesh(
    const Mesh& mesh, const glm::dmat4& model, const PickRay& ray, const std::vector<PickPart>& parts = {});

// The world-space ray through the point `pixel` of a `width` x `height` image seen by `camera`
// (pixel coordinates: x right, y DOWN from the top-left corner, so the centre of pixel (i, j) is
// (i + 0.5, j + 0.5)), for the projection render/ uses (Camera::projectionMatrix(width / height)).
// Origin at the camera's position, direction unit length.
PickRay cameraRay(const Camera& camera, double width, double height, const glm::dvec2& pixel);

} // namespace facet
