#pragma once
// glTF 2.0 assets in: the meshes AND their materials of a .gltf (external or data-URI buffers and
// images) or .glb file, read with tinygltf (Debian's libtinygltf-dev 2.7) rather than Assimp.
// Why: Facet needs glTF's material model exactly (factor x texture for every input, the packed
// metallicRoughness texture's G and B channels, normal scale, occlusion strength, emissive with
// KHR_materials_emissive_strength, KHR_materials_ior, KHR_texture_transform per texture, alpha
// mode and cutoff, double-sidedness), and the node graph under our own control: Assimp 5.2's glTF
// reader recurses through nodes and overflows the stack on a crafted file (issue 12), while here
// the graph is walked with an explicit stack and every accessor, index and reference is checked
// before it is used. docs/meshes.md and docs/gltf.md describe the mapping and the limits.
//
// Images are not decoded here: a material map names its image by path, an external image file
// (resolved against the asset's folder) or, for an image embedded in the asset (a .glb buffer
// view or a data URI), a reference "<asset path>#images/<index>" that core/image/Image::load reads
// through readGltfImage(). Conventions: glTF's UV origin is the image's top-left, Facet's the
// bottom-left (core/mesh/Mesh.h), so v becomes 1 - v and each KHR_texture_transform is conjugated
// into Facet's UV space (gltfTextureTransform()).

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/material/Material.h"
#include "core/mesh/Mesh.h"
#include "core/mesh/MeshImport.h"

namespace facet {

struct GltfImportOptions {
    MeshImportOptions mesh; // vertex/triangle limits, UV fallback for primitives without UVs
    // Refused before parsing: a material preview asset is megabytes, not gigabytes.
    std::size_t maxFileBytes = std::size_t(1) << 30;
    std::size_t maxNodes = 100'000; // node instances visited in the scene graph
    std::size_t maxParts = 65'536; // primitive instances (sub-meshes)
    std::size_t maxMaterials = 4'096;
    // The materials and the parts (sub-meshes with their names and material indices, no vertices):
    // what a project needs from an asset whose mesh the view loads separately. Faster, and the
    // mesh's own repairs are noted once, by the mesh import.
    bool materialsOnly = false;
    // Whether the materials' notes (an extension or texture not read, a factor clamped, an image
    // missing) are part of *warning. importMesh turns them off: its callers read the materials
    // through importGltf, which reports them, or take none of the asset's materials (a mesh only),
    // so they would be said twice, or about materials not used.
    bool materialNotes = true;
};

struct GltfAsset {
    // Every primitive instance is a SubMesh whose materialIndex indexes `materials`. Positions
    // are in the file's units with each node's transform applied (not normalised).
    Mesh mesh;
    // The file's materials in file order, then "Default" (glTF's default material: white,
    // metallic 1, roughness 1) when a primitive names none. At least one.
    std::vector<Material> materials;
    // Where each sub-mesh comes from, parallel to mesh.subMeshes: the node that instances it, and
    // the mesh and primitive in the file (what an export that keeps the asset's nodes rewrites).
    struct PartSource {
        int node = -1;
        int mesh = -1;
        int primitive = -1;
    };
    std::vector<PartSource> partSources;
};

// Reads `path` (.gltf or .glb, by content). On failure returns nullopt and sets *error to
// "importGltf: <path>: <problem>" (missing, not a regular file, too large, not glTF, cut short, a
// broken accessor, an index or reference out of range, a cycle in the node graph, no triangles,
// over the limits, an extension the file requires that Facet does not read). On success *warning
// (if given) is empty or "importGltf: <path>: <note>; <note>" naming what was repaired or
// ignored (missing images, unsupported extensions, texture coordinate sets other than 0, ...).
std::optional<GltfAsset> importGltf(const std::string& path, std::string* error,
    std::string* warning = nullptr, const GltfImportOptions& options = {});

// True for the extensions importGltf() reads: ".gltf", ".glb" (case-insensitive).
bool isGltfFileName(const std::string& path);

// An image embedded in a glTF asset, as a material map's path names it.
struct GltfImageReference {
    std::string assetPath;
    int imageIndex = -1;
};
// "<assetPath>#images/<index>".
std::string gltfImageReference(const std::string& assetPath, int imageIndex);
// The reference in `path`, when it is one (a glTF file name followed by "#images/<digits>").
std::optional<GltfImageReference> parseGltfImageReference(const std::string& path);
// The file on disk behind a map path: the asset of an embedded-image reference, else the path.
std::string fileOfImagePath(const std::string& path);

// The encoded bytes (PNG, JPEG, ...) of the image a reference names, and its MIME type when the
// asset says it. nullopt with *error ("readGltfImage: <path>#images/<i>: <problem>") when the
// asset cannot be read or has no such embedded image.
std::optional<std::vector<unsigned char>> readGltfImage(
    const GltfImageReference& reference, std::string* mimeType, std::string* error);

// The KHR_texture_transform of a glTF textureInfo (offset, rotation in radians, scale, applied in
// glTF's top-left UV space) as the UvTransform that reads the same texels in Facet's bottom-left
// UV space: with F(u, v) = (u, 1 - v), Facet's matrix is F * M_gltf * F, which is again
// translation * rotation * scale with the rotation negated and the offset moved.
UvTransform gltfTextureTransform(const glm::dvec2& offset, double rotationRadians, const glm::dvec2& scale);

// A glTF sampler's numbers (glTF 2.0 section 5.26: magFilter, minFilter, wrapS, wrapT; the
// WebGL enum values) as a TextureSampler: an absent (-1) or unknown filter is Auto, an unknown
// wrap Repeat (glTF's default). gltfSamplerValues() gives them back {magFilter, minFilter, wrapS,
// wrapT}, -1 for an Auto filter (left out of the file: the reader's choice, as Auto is Facet's).
TextureSampler textureSamplerFromGltf(int magFilter, int minFilter, int wrapS, int wrapT);
std::array<int, 4> gltfSamplerValues(const TextureSampler& sampler);

} // namespace facet
