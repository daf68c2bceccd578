#pragma once
// The steps every mesh importer runs after reading a file's vertices (core/mesh/MeshImport.cpp for
// Assimp's formats, core/gltf/GltfImport.cpp for glTF): repair missing or broken normals, generate UVs
// for parts without any, make tangents (the file's, orthonormalised, or generated from the UVs),
// update the bounds and validate. docs/meshes.md describes the pipeline.

#include <cstddef>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/mesh/Mesh.h"
#include "core/mesh/Tangents.h"

namespace facet {

// `v` / |v|, or zero when v is zero or not finite.
glm::vec3 normalizedOrZero(const glm::vec3& v);

// Vertices whose normal is missing, zero or not finite get the angle-free, area-weighted sum of
// their faces' normals (the face cross products), or +Y if even that is zero. Returns how many.
std::size_t repairNormals(Mesh& mesh);

// What finishImportedMesh() needs to know about the parts the importer appended.
struct ImportedParts {
    std::vector<std::size_t> withoutUvs; // sub-mesh indices whose file had no texture coordinates
    bool allHaveTangents = false; // every part came with tangents from the file
};

// Repairs normals, generates UVs for `parts.withoutUvs` by `uvFallback`, keeps the file's tangents
// (orthonormalised) when every part has them and no UVs were generated, otherwise generates them;
// updates the bounds and validates. Appends one artist-readable note per repair to `warnings`.
// False with *problem on a mesh that cannot be finished.
bool finishImportedMesh(Mesh& mesh, const ImportedParts& parts, UvProjection uvFallback,
    std::vector<std::string>& warnings, std::string* problem);

} // namespace facet
