#pragma once
// The part of a glTF export that keeps the source asset (issue 29: exporting dropped what Facet
// does not edit): the source file's JSON with its scenes, node hierarchy and transforms, meshes
// and their primitives' attributes, morph targets and weights, skins, animations, cameras,
// extras and unknown extensions kept as written, its geometry's bytes copied into one buffer,
// and its materials, textures, images and samplers taken out for core/gltf/GltfExport to write
// Facet's. Internal to core/ (core/gltf/GltfExport writeGltfAsset with GltfExportOptions::source).
// docs/export.md, "glTF: the asset kept".

#include <optional>
#include <string>
#include <vector>

#include <QByteArray>
#include <QJsonArray>
#include <QJsonObject>

namespace facet {

struct GltfAssetCopy {
    // The asset's JSON without "materials", "textures", "images", "samplers", "buffers" and
    // "bufferViews"; every reference to a buffer view renumbered into `bufferViews`.
    QJsonObject root;
    // The buffer views the geometry (accessors, sparse accessors, Draco primitives) and anything
    // else but the source's images uses, each pointing into `bytes` as buffer 0.
    QJsonArray bufferViews;
    QByteArray bytes;
    // The source's "extensionsUsed" and "extensionsRequired" less the material and texture
    // extensions, which Facet writes (or not) for its own materials.
    QJsonArray extensionsUsed;
    QJsonArray extensionsRequired;
};

// Reads the glTF asset at `sourcePath` (checked as importGltf checks it) and sets each drawn
// primitive's material from `partMaterials` (indexed like the sub-meshes importGltf makes, each
// an index below `materialCount`). A mesh that two nodes instance with different materials is
// copied for the second node (glTF gives a material per primitive, not per instance). A
// primitive Facet does not draw (points, lines, no triangles) keeps its material index when it
// is below materialCount, else none. nullopt with *error "<sourcePath>: <problem>".
std::optional<GltfAssetCopy> copyGltfAsset(const std::string& sourcePath,
    const std::vector<int>& partMaterials, int materialCount, std::string* error);

} // namespace facet
