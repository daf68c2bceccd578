#pragma once
// The window's asset cache, one per document (not a widget, no GL): environments, meshes and
// material maps decoded on worker threads (a QThreadPool) and shared by every view: the window's
// one loader of them. The single view's ui/viewport/SceneController and the Compare view's cells
// take their environments, meshes and maps from here, so an environment or a map shown by the
// single view and three grid cells is decoded once. Maps go through the process-wide
// core/image/MapImageCache (shared with the map slots and thumbnails); environments and meshes are
// held here. (core/project/AssetCache is the command line's synchronous equivalent for one
// batch: `facet sheet`.)
//
// A request returns what is loaded, or null and starts the load; its arrival is announced
// (assetArrived) on this object's thread, and the requester asks again. What needs no file (a
// built-in environment, uniform:V, a primitive mesh) is made at once, on the caller's thread
// (a few milliseconds). A file changed on disk since it was loaded (or failed) is loaded again
// when next requested; until the new version arrives the previous one is returned. A file that
// could not be read is not tried again until it changes or retry() is called; problem() says why.
//
// Entries are kept while a user names them: each user (SceneController, CompareView) says which
// it shows (setInUse), and what no user names is dropped.

#include "core/ibl/Environment.h"
#include "core/image/MapImage.h"
#include "core/project/AssetCache.h"

#include <QObject>
#include <QThreadPool>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>

namespace facet {

class DocumentAssets : public QObject {
    Q_OBJECT
public:
    enum class Kind { Environment, Mesh, Map };

    explicit DocumentAssets(QObject* parent = nullptr);
    ~DocumentAssets() override; // drops queued loads, waits for running ones

    // Environment::fromSpec(spec) at rotation 0 and intensity 1 (a copy shares its pixels: set
    // rotation and intensity on the copy); null while it loads or when it could not be read.
    std::shared_ptr<const Environment> environment(const std::string& spec);
    // loadViewMesh with its content key; null while it loads or when it failed. `source` is a
    // view's mesh name or path as meshSource() makes it (the same file in its own units is another
    // mesh, with another name here).
    std::shared_ptr<const AssetCache::LoadedMesh> mesh(const std::string& source);
    static std::string meshSource(const std::string& nameOrPath, bool keepUnits);
    // The map image of `path` (MapImageCache); null while it decodes or when it failed. Its
    // warning() names what the decode sanitised ("replaced 3 NaN, Inf or negative samples").
    std::shared_ptr<const MapImage> map(const std::string& path);
    // The modification time (ms since the epoch) of the file the current map entry of `path` came
    // from: LoadedMapImage::timestamp, the key of its textures; 0 when there is no entry.
    std::int64_t mapTimestamp(const std::string& path) const;
    // Memory: the entry of `path` keeps a stand-in without pixels (MapImage::withoutPixels) in place
    // of `image` once a view has it on the GPU; an entry that is no longer `image` (a newer file, a
    // decode asked for again) is left as it is. Returns the stand-in, or null when nothing changed.
    std::shared_ptr<const MapImage> releaseMapPixels(const std::string& path, const MapImage* image);

    bool isLoading(Kind kind, const std::string& name) const;
    // Why `name` could not be loaded (core's message, naming the file); empty otherwise.
    std::string problem(Kind kind, const std::string& name) const;
    // Notes of the load that gave the current entry ("replaced 3 NaN samples"); empty if none.
    std::string warning(Kind kind, const std::string& name) const;
    // Forgets that `name` failed: the next request loads it again (an explicit reload).
    void retry(Kind kind, const std::string& name);
    // The next request of `name` loads it again although its file did not change (a map whose
    // pixels were released, wanted by a view without its texture); the current entry is returned
    // meanwhile.
    void reload(Kind kind, const std::string& name);

    // `user` shows `names` of `kind` (replacing what it said before); entries of that kind that
    // no user names are dropped (a load under way finishes and is kept until the next call).
    void setInUse(const void* user, Kind kind, std::set<std::string> names);
    // The user is gone: its names no longer keep anything.
    void forgetUser(const void* user);

    // Loads started, by kind (tests: "each environment once").
    int loads(Kind kind) const;
    int pendingLoads() const { return int(m_loading.size()); }
    // Blocks until every queued load finished (tests and benchmarks), then delivers them.
    void waitForLoads();

Q_SIGNALS:
    // An asset finished loading (or failed): whoever waits for it asks again.
    void assetArrived();
    // An environment delivered before its pixels were decoded (found in the environment index)
    // now has them (Environment::decoded()); `contentHash` is its Environment::contentHash().
    void environmentDecoded(quint64 contentHash);

private:
    struct Entry {
        std::shared_ptr<const Environment> environment;
        std::shared_ptr<const AssetCache::LoadedMesh> mesh;
        std::shared_ptr<const MapImage> map;
        std::int64_t modified = 0; // of the file the entry (or its failure) came from
        std::string problem; // set: it could not be loaded
        std::string warning;
        bool reload = false; // reload(): loaded again at the next request
    };
    using Load = std::function<Entry()>;

    // The current entry of `name`: loads it (at once when `immediate`, else on a worker) when
    // there is none, or when its file changed; a stale entry is returned while it reloads.
    const Entry* lookup(Kind kind, const std::string& name, bool immediate, const Load& load);
    void deliver(const std::string& key, Entry entry);
    void dropUnused(Kind kind);

    std::map<std::string, Entry> m_entries; // by key (kind prefix + name)
    std::set<std::string> m_loading; // keys
    std::map<const void*, std::map<Kind, std::set<std::string>>> m_inUse;
    std::map<Kind, int> m_loads;
    // Declared last: destroyed (waited for) first. Maps decode on a pool of their own, beside
    // the environments' and meshes': a project's maps do not wait behind its EXR environment.
    QThreadPool m_pool;
    QThreadPool m_mapPool;
};

} // namespace facet
