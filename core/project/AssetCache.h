#pragma once
// Environments and meshes loaded once for a batch of frames that share them: the cells of a
// contact sheet (`facet sheet`: every row of one column shows one environment), a compare grid.
// Material maps have their own process-wide cache (core/image/MapImageCache.h), which this one leaves
// them to. An entry is reused while its file is unchanged (same modification time); built-in
// names, uniform: specs and library references are keyed by the name alone. Entries are strong:
// the cache lives as long as its batch and holds what the batch shows.
//
// Thread-safe: loads are serialised (two threads asking for one file at once decode it once).

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "core/ibl/Environment.h"
#include "core/mesh/Mesh.h"

namespace facet {

class AssetCache {
public:
    struct LoadedMesh {
        std::shared_ptr<const Mesh>
            mesh; // normalised to the unit bounding sphere unless kept in its units (loadViewMesh)
        std::uint64_t key = 0; // the content key the renderer uploads by (ProjectAssets::meshKey)
    };

    // Environment::fromSpec(spec) at rotation 0 and intensity 1 (copies share the pixels; set
    // a project's rotation and intensity on the copy). nullopt with *error (fromSpec's message).
    // `warning` (optional) gets the load's notes the first time only.
    std::optional<Environment> environment(
        const std::string& spec, std::string* error, std::string* warning = nullptr);
    // loadViewMesh(nameOrPath, keepUnits), with its content key (the two scalings are two meshes).
    std::optional<LoadedMesh> mesh(const std::string& nameOrPath, std::string* error,
        std::string* warning = nullptr, bool keepUnits = false);

    // Decodes and mesh loads run so far (tests: "each environment once").
    int environmentLoads() const;
    int meshLoads() const;

    // The file's modification time in ms since the epoch; 0 for what is not a file (a built-in
    // name, uniform:, a library reference): those are keyed by the name alone.
    static std::int64_t modifiedTime(const std::string& path);
    // The content key of a mesh loaded from `nameOrPath` at `modified` (ProjectAssets::meshKey):
    // a new file version is a new key (the renderer uploads again); a built-in name keeps its key.
    static std::uint64_t meshKey(
        const std::string& nameOrPath, std::int64_t modified, bool keepUnits = false);

private:
    struct EnvironmentEntry {
        std::int64_t modified = 0;
        Environment environment;
    };
    struct MeshEntry {
        std::int64_t modified = 0;
        LoadedMesh mesh;
    };

    mutable std::mutex m_mutex;
    std::map<std::string, EnvironmentEntry> m_environments;
    std::map<std::pair<std::string, bool>, MeshEntry> m_meshes; // by (name or path, keepUnits)
    int m_environmentLoads = 0;
    int m_meshLoads = 0;
};

} // namespace facet
