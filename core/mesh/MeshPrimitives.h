#pragma once
// Built-in meshes, built procedurally with analytic normals, UVs and tangents (w = +1
// everywhere: no primitive has a mirrored UV chart). Every one passes Mesh::validate(); the
// closed ones (sphere, cube, cylinder, torus, shader ball) are watertight once coincident seam
// vertices are welded. docs/meshes.md has pictures in words of each and its UV layout.
//
// Sizes are the natural ones below; the viewer frames every mesh with normalizeToUnitSphere().
// Apart from the sphere, UVs run at about one UV unit per 2 world units (a face of the cube, the
// plane) so one tileable texture looks the same size on each.
// Tessellation arguments are clamped to [3, 4096] (rings: [2, 4096]); nothing here fails.

#include <optional>
#include <span>
#include <string_view>

#include "core/mesh/Mesh.h"

namespace facet {

// UV sphere of radius 1 at the origin. u runs around +Y, v from the south pole (0) to the north
// pole (1): u = 0.5 - atan2(z, x) / (2 pi), v = asin(y) / pi + 0.5. That is docs/architecture.md's
// equirectangular mapping with u mirrored: the equirectangular image is seen from inside the
// sphere, a material from outside, and with this u a texture reads the right way round (w = +1).
// The u = 0/1 seam is on -X. The pole rows have one vertex per segment, at mid-segment u, so no
// triangle is degenerate.
// 64 x 32: 2,143 vertices, 3,968 triangles.
Mesh makeSphere(int segments = 64, int rings = 32);

// Cube from -1 to 1: 24 vertices (4 per face, hard edges), each face the full [0, 1] UV square,
// laid out like boxProjectionFaces() (Tangents.h).
Mesh makeCube();

// The XZ square from -1 to 1 facing +Y, `subdivisions` quads along each side; u along +X, v
// along -Z (so from above, with -Z up the screen, the texture reads upright). Open: not closed.
Mesh makePlane(int subdivisions = 1);

// Cylinder about +Y, radius 1, y from -1 to 1, flat caps with hard edges. The side's u goes
// around three times (its circumference is 2 pi, about 3 x its height of 2), v up the side;
// the caps are planar-mapped like the plane (the bottom seen from below).
Mesh makeCylinder(int segments = 64);

// Torus of major radius 0.7 and tube radius 0.3 (outer radius 1), its axis along +Z so the
// reference camera on +Z looks through the hole. u goes twice around the ring, v once around
// the tube.
Mesh makeTorus(int segments = 64, int sides = 32);

// A material-preview "shader ball" in the manner of Substance's and Marmoset's: a sphere with a
// recessed band around its equator (hard-edged walls catch highlights at every angle), on a
// short neck and a bevelled round base. A lathe: a 2D profile of arcs and lines with analytic
// normals, revolved about +Y. About 2 units tall: y from -0.95 to 0.95, ball radius 0.8.
Mesh makeShaderBall(int segments = 96);

// "sphere", "cube", "plane", "cylinder", "torus", "shaderball" with default tessellation;
// nullopt for any other name.
std::optional<Mesh> makePrimitive(std::string_view name);
// The names makePrimitive() accepts, in menu order.
std::span<const std::string_view> primitiveNames();

} // namespace facet
