#pragma once
// Mesh files through Assimp (OBJ, FBX, PLY, DAE, STL, ... whatever Assimp 5.2 reads) and glTF/GLB
// through core/gltf/GltfImport, flattened into one facet::Mesh with a sub-mesh per mesh instance.
// docs/meshes.md describes the pipeline and its limits.

#include <cstddef>
#include <optional>
#include <string>

#include "core/mesh/Mesh.h"
#include "core/mesh/Tangents.h"

namespace facet {

struct MeshImportOptions {
    // Limits, so a wrong or hostile file is refused instead of exhausting memory: at 56 bytes a
    // Vertex, 50M vertices are 2.8 GB in RAM and as much again on the GPU, past what the
    // machines Facet targets can hold (and far past what a material preview needs).
    std::size_t maxVertices = 50'000'000;
    std::size_t maxTriangles = 100'000'000; // 1.2 GB of 32-bit indices
    // How UVs are made for a file without them (the CC0 sample meshes have none).
    UvProjection uvFallback = UvProjection::Box;
    // Assimp's smooth-normal generation, used only for meshes without normals: faces meeting
    // at a sharper angle keep a hard edge (a cube stays a cube). Assimp's default, 175, would
    // smooth everything.
    float smoothingAngleDegrees = 80.0f;
};

// Reads a mesh file and returns it in the file's own units and placement (every node's
// transform applied, normals by the inverse transpose; mirroring nodes get their winding
// reversed). It is NOT normalised: the caller decides (the viewer calls
// normalizeToUnitSphere()). Points and lines are dropped; files without normals get smooth
// normals; without UVs get generated ones (options.uvFallback, uvsGenerated set); tangents come
// from the file when every part has them, otherwise from generateTangents(). The result passes
// Mesh::validate(). Never throws.
// On failure returns nullopt and sets *error to "importMesh: <path>: <problem>": missing,
// unreadable, empty, not a mesh format, malformed, no triangles, over the limits. On success
// *warning (if given) is empty or "importMesh: <path>: <what was repaired or generated>".
std::optional<Mesh> importMesh(const std::string& path, std::string* error, std::string* warning = nullptr,
    const MeshImportOptions& options = {});

// The file name patterns Assimp reads, "*.3ds;*.obj;...", for a file dialog's filter.
std::string importableMeshPatterns();

} // namespace facet
