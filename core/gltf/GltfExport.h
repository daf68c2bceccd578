#pragma once
// A project's materials on a mesh written as a glTF 2.0 asset (issue 11, "glTF 2.0"): a .gltf with
// its .bin and PNG textures beside it, or one .glb with everything inside. What Facet shades with
// is baked to glTF's conventions by the texture-set export (core/export/TextureSetExport, the
// "gltf-textures" template's outputs): base colour RGBA (sRGB), the OpenGL normal map with a
// DirectX map's green flipped (its strength is normalTexture.scale), occlusion R (its strength is
// occlusionTexture.strength) + roughness G + metallic B in one texture that
// serves both occlusionTexture and metallicRoughnessTexture, emissive (sRGB). A slot without a
// texture is written as a factor, not as a texture. A UV transform every textured slot of a
// material shares is written as KHR_texture_transform (the textures unbaked); different transforms
// are baked into the textures. IOR other than 1.5 is KHR_materials_ior; an emissive strength
// other than 1 KHR_materials_emissive_strength. docs/export.md, "glTF".
//
// Without GltfExportOptions::source the mesh is written as Facet holds it: positions (fitted to the unit
// sphere for an imported mesh, core/project/ProjectAssets loadViewMesh), unit normals, texture coordinates (v
// flipped to glTF's top-left origin), tangents when the mesh has them, one primitive per sub-mesh with its
// material.

#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/export/TextureSetExport.h"
#include "core/material/Material.h"
#include "core/mesh/Mesh.h"

namespace facet {

struct GltfExportOptions {
    bool binary = false; // .glb: one file, images embedded
    TextureSetOptions textures; // size; bit depth 8 or 16 (PNG)
    std::string generator = "Facet";
    // The glTF file the mesh was read from (core/project/ProjectAssets viewMeshGltfFile), or empty. When
    // set, the asset is kept (core/gltf/GltfAssetCopy): its scenes, nodes and their transforms, meshes,
    // morph targets, skins, animations, cameras and extras as the file has them, in its own units,
    // with only the materials and textures Facet's; `mesh` then serves for its TEXCOORD_1 flag
    // and partMaterials index importGltf's parts.
    std::string source;
};

// KHR_texture_transform's values (glTF's top-left UV space, rotation in radians) for Facet's
// UvTransform: the inverse of core/gltf/GltfImport gltfTextureTransform.
struct GltfTextureTransform {
    glm::dvec2 offset {0.0};
    double rotation = 0.0;
    glm::dvec2 scale {1.0};
};
GltfTextureTransform toGltfTextureTransform(const UvTransform& uv);

// Writes `materials` on `mesh` (sub-mesh i drawn with materials[partMaterials[i]]; a mesh without
// sub-meshes is one primitive with material 0) to `path` (.gltf or .glb). Nothing is replaced
// without `replace` (every file checked first: "<path>: exists"); a failed write removes the
// files it made; *error names the file. *written gets every path written.
bool writeGltfAsset(const std::string& path, const Mesh& mesh, const std::vector<int>& partMaterials,
    const std::vector<Material>& materials, const GltfExportOptions& options, bool replace,
    std::vector<std::string>* written, std::string* error);

// The files writeGltfAsset writes for `path` (the asset last), for a dry run.
// `meshHasTexCoord1`: without TEXCOORD_1 every map reads set 0, so maps naming different sets
// are not refused (the export writes them on set 0).
std::vector<std::string> gltfAssetFiles(const std::string& path, const std::vector<Material>& materials,
    const GltfExportOptions& options, std::string* error, bool meshHasTexCoord1 = true);

} // namespace facet
