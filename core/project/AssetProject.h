#pragma once
// A glTF asset (core/gltf/GltfImport.h) as a Facet project, for opening or dropping an asset
// (File > Open, File > Import, `facet ASSET.glb`, `facet render ASSET.glb`): the asset's materials
// become the project's, each mesh part shows the material the asset gives it, and the asset is
// the view's mesh. docs/gltf.md describes the mapping.

#include <optional>
#include <string>

#include "core/project/Project.h"

namespace facet {

struct GltfAsset;

// `project` with the asset's materials and parts and `assetPath` as its mesh; everything else
// (environment, lights, camera, view settings, the compare layout) stays, except that an A/B
// whose B was one of the replaced materials shows it as a snapshot (CompareLayout::
// removeAllMaterials). The first material is the current one.
Project withAsset(Project project, const GltfAsset& asset, const std::string& assetPath);

// Project::defaultProject() with the asset at `path` (absolute or relative to the working
// folder). On failure nullopt with *error naming the file and the problem (importGltf's message);
// *warning (optional) gets the import's notes.
std::optional<Project> projectFromAsset(
    const std::string& path, std::string* error, std::string* warning = nullptr);

// True for the files projectFromAsset() opens (glTF: .gltf, .glb).
bool isAssetFileName(const std::string& path);

} // namespace facet
