#pragma once
// What a project refers to, loaded: the environment, the mesh and the material's map images.
// core loads, render uploads (docs/architecture.md): the viewport and the headless commands both
// turn a Project into ProjectAssets here, then hand the assets to the renderer.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/ibl/Environment.h"
#include "core/image/Image.h"
#include "core/image/MapImage.h"
#include "core/material/Material.h"
#include "core/mesh/Mesh.h"

namespace facet {

struct EnvironmentSettings;
struct Project;

struct LoadedMapImage {
    std::shared_ptr<const MapImage> image; // null: the slot uses its constant factor only
    std::string path;
    std::int64_t timestamp = 0; // file modification time, ms since the epoch
};

struct ProjectAssets {
    Environment environment; // rotation and intensity applied
    std::shared_ptr<const Mesh> mesh; // normalised to the unit bounding sphere
    std::uint64_t meshKey = 0; // changes when the mesh source or its file changes
    // The map images of every material of the project, indexed [material][MapSlot], in the files'
    // own bit depth (core/image/MapImage.h). A file used by several slots or materials (a packed ORM
    // texture, a shared normal map) is decoded once and shared (core/image/MapImageCache.h).
    std::vector<std::array<LoadedMapImage, kMapSlotCount>> maps;
};

// The one builder of a frame's assets from a project, used by the command line
// (loadProjectAssets), the window's single view (ui/viewport/SceneController) and the Compare
// view's cells, each with its own source of files:
// - `environment` placed as `settings` say (rotation and intensity);
// - assets.maps sized to the project's materials, each slot that names a file set from
//   lookup(material, slot, map) (an empty LoadedMapImage: the slot shows its factor alone).
void placeEnvironment(Environment& environment, const EnvironmentSettings& settings);
using MapLookup = std::function<LoadedMapImage(std::size_t material, MapSlot slot, const MaterialMap& map)>;
void assignMaps(ProjectAssets& assets, const Project& project, const MapLookup& lookup);

// Loads everything `project` names. Errors name the file and the problem (the environment,
// the mesh, or a map: "loadProjectAssets: baseColor map: MapImage::load: <path>: <reason>"; a
// map beyond the size budget, core/image/MapImage.h MapBudget, is refused before it is decoded).
// Warnings (sanitised pixels, generated UVs...) are appended to `warning`, one per line.
std::optional<ProjectAssets> loadProjectAssets(
    const Project& project, std::string* error, std::string* warning = nullptr);
// The same, taking the environment and the mesh from `cache` (core/project/AssetCache.h): a batch of
// frames sharing them (a contact sheet's cells) loads each once.
class AssetCache;
std::optional<ProjectAssets> loadProjectAssets(
    const Project& project, AssetCache& cache, std::string* error, std::string* warning = nullptr);

// The mesh a view names: a built-in primitive ("sphere", "cube", ...), a mesh file or a library
// reference ("library:installed/models/bunny.glb", core/project/AssetLibrary.h), normalised to the unit
// bounding sphere (the built-in sphere is already the unit sphere of the reference view), or in
// the file's own units with `keepUnits` (ViewSettings::keepUnits). A missing library file says how
// to get it (AssetLibrary::missingFileAdvice).
std::optional<Mesh> loadViewMesh(const std::string& nameOrPath, std::string* error,
    std::string* warning = nullptr, bool keepUnits = false);

// The glTF file (.gltf, .glb) behind a view's mesh name, resolved as loadViewMesh resolves it; empty
// for a built-in primitive, another mesh format or a name that does not resolve. A glTF export keeps
// this asset's nodes, skins and animations (GltfExportOptions::source).
std::string viewMeshGltfFile(const std::string& nameOrPath);

} // namespace facet
