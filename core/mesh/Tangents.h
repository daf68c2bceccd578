#pragma once
// The tangent frame a normal map needs: per-vertex tangents generated from the UVs, and UVs
// generated for meshes that have none (the CC0 sample meshes, docs/architecture.md "Sample data (CC0)"), so
// every mesh can show a tangent-space normal map. docs/meshes.md explains the choices.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace facet {

class Mesh;

// A unit vector perpendicular to the unit vector n, continuous except across n.z = 0's sign
// flip: Duff, Burgess, Christensen, Hery, Kensler, Liani and Villemin, "Building an Orthonormal
// Basis, Revisited", JCGT 6(1), 2017 (its branchless construction; the first basis vector).
glm::vec3 perpendicularTangent(const glm::vec3& n);

struct TangentStats {
    std::size_t degenerateTriangles = 0; // zero UV or geometric area: they add nothing
    std::size_t fallbackVertices = 0; // no usable UV direction: tangent from perpendicularTangent()
};

// Generates every vertex's tangent from positions, normals and UVs in the manner of MikkTSpace
// (Mikkelsen, "Simulation of Wrinkled Surfaces Revisited", MSc thesis, 2008; the tangent basis
// that glTF 2.0 asks for when a file has none): per triangle, dP/du and dP/dv from the UV
// derivatives; at each corner both are projected onto the vertex normal's plane, normalised and
// weighted by the corner angle; per vertex the sums are Gram-Schmidt orthogonalised against the
// normal, and w = +-1 is the sign of the summed bitangent against cross(normal, tangent).
// Compatible in spirit, NOT bit-exact with the reference libmikktspace: that one also merges
// vertices by position, normal and UV before summing and splits by handedness; Debian 12 ships
// no libmikktspace package, and Facet's meshes are already indexed by JoinIdenticalVertices.
// A vertex with no usable triangle gets perpendicularTangent(normal), w = +1.
// Requires mesh.hasUvs and indices in range; false with *problem
// ("generateTangents: '<mesh name>': <problem>") otherwise. Sets mesh.hasTangents.
bool generateTangents(Mesh& mesh, std::string* problem = nullptr, TangentStats* stats = nullptr);

// How generateUvs() maps positions to UVs.
enum class UvProjection {
    // Box (cube) projection: each triangle is projected along the axis its face normal points
    // most along, one chart per axis and sign. The default: no singular points, no folds on
    // concave shapes (Suzanne's ears), the same texel density everywhere, which is what the
    // tileable maps an artist previews need. Seams where the charts meet.
    Box,
    // The sphere primitive's mapping of the direction from the bounding-sphere centre:
    // u = 0.5 - atan2(d.z, d.x) / (2 pi), v = asin(d.y) / pi + 0.5. Right for near-spherical
    // shapes; pinches at the poles and folds where a ray from the centre crosses the surface twice.
    Spherical,
};
std::string_view uvProjectionName(UvProjection projection); // "box", "spherical"
std::optional<UvProjection> uvProjectionFromName(std::string_view name);

// One face of the box projection: a triangle whose face normal points most along `normal` gets
// u along `tangent` and v along `bitangent`. cross(tangent, bitangent) == normal, so no chart is
// mirrored and every generated tangent has w = +1. The cube primitive uses the same layout.
struct BoxFace {
    glm::vec3 normal;
    glm::vec3 tangent;
    glm::vec3 bitangent;
};
// +X, -X, +Y, -Y, +Z, -Z, cubemap order (docs/architecture.md).
const std::array<BoxFace, 6>& boxProjectionFaces();

// Replaces the UVs of the triangles of `onlySubMeshes` (indices into mesh.subMeshes; empty:
// every triangle) with a projection of their positions relative to the mesh's bounding sphere,
// scaled so the sphere's diameter spans one UV unit. A vertex shared by triangles that fall in
// different charts, or, for Spherical, whose triangle straddles the u = 0/1 seam or touches a
// pole, is duplicated, so no triangle interpolates across a seam. (Seam triangles get u > 1 on
// the far side, which REPEAT sampling reads as the same texels.) The chosen sub-meshes must not
// share vertices with the others. Sets hasUvs and uvsGenerated, clears hasTangents, updates
// bounds. False with *problem ("generateUvs: '<mesh name>': <problem>") on out-of-range indices.
bool generateUvs(Mesh& mesh, UvProjection projection, std::string* problem = nullptr,
    const std::vector<std::size_t>& onlySubMeshes = {});

// UVs (generateUvs with `fallback`) when the mesh has none, then tangents when it has none.
bool ensureTangentFrame(
    Mesh& mesh, UvProjection fallback = UvProjection::Box, std::string* problem = nullptr);

} // namespace facet
