#include "ui/document/DocumentAssets.h"

#include "core/gltf/GltfImport.h"
#include "core/image/MapImageCache.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/project/ProjectAssets.h"

#include <QCoreApplication>
#include <QMetaObject>
#include <QPointer>
#include <QThread>

#include <algorithm>

namespace facet {

namespace {

std::string keyOf(DocumentAssets::Kind kind, const std::string& name)
{
    switch (kind) {
    case DocumentAssets::Kind::Environment:
        return "env:" + name;
    case DocumentAssets::Kind::Mesh:
        return "mesh:" + name;
    case DocumentAssets::Kind::Map:
        return "map:" + name;
    }
    return name;
}

} // namespace

DocumentAssets::DocumentAssets(QObject* parent)
    : QObject(parent)
{
    // Decoding beside llvmpipe's threads and the GUI thread: leave a core to them, at most 4 (per
    // pool: environments and meshes, maps).
    const int threads = std::clamp(QThread::idealThreadCount() - 1, 1, 4);
    m_pool.setMaxThreadCount(threads);
    m_mapPool.setMaxThreadCount(threads);
}

DocumentAssets::~DocumentAssets()
{
    m_mapPool.clear();
    m_pool.clear();
    m_mapPool.waitForDone();
    m_pool.waitForDone();
}

std::shared_ptr<const Environment> DocumentAssets::environment(const std::string& spec)
{
    const Entry* entry = lookup(Kind::Environment, spec, !Environment::namesFile(spec), [spec] {
        Entry loaded;
        if (std::optional<Environment> environment
            = Environment::fromSpec(spec, &loaded.problem, &loaded.warning)) {
            // An environment found in its index (core/ibl/EnvironmentIndex) is not decoded here: it is
            // delivered at once, so that the view's lighting worker can read its IBL set from
            // the disk cache, and decoded next on this pool (deliver()).
            loaded.environment = std::make_shared<const Environment>(std::move(*environment));
        } else if (loaded.problem.empty())
            loaded.problem = "Environment::fromSpec: " + spec + ": could not be loaded";
        return loaded;
    });
    return entry ? entry->environment : nullptr;
}

namespace {
const std::string kAssetUnits = "asset units:";

// The mesh a meshSource() names, and whether it keeps the asset's units.
std::pair<std::string, bool> meshOfSource(const std::string& source)
{
    const bool keepUnits = source.starts_with(kAssetUnits);
    return {keepUnits ? source.substr(kAssetUnits.size()) : source, keepUnits};
}
} // namespace

std::string DocumentAssets::meshSource(const std::string& nameOrPath, bool keepUnits)
{
    return keepUnits ? kAssetUnits + nameOrPath : nameOrPath;
}

std::shared_ptr<const AssetCache::LoadedMesh> DocumentAssets::mesh(const std::string& source)
{
    const std::pair<std::string, bool> parsed = meshOfSource(source);
    const std::string& nameOrPath = parsed.first;
    const bool keepUnits = parsed.second;
    const bool primitive
        = std::find(primitiveNames().begin(), primitiveNames().end(), nameOrPath) != primitiveNames().end();
    const Entry* entry = lookup(Kind::Mesh, source, primitive, [nameOrPath, keepUnits] {
        Entry loaded;
        if (std::optional<Mesh> mesh
            = loadViewMesh(nameOrPath, &loaded.problem, &loaded.warning, keepUnits)) {
            auto result = std::make_shared<AssetCache::LoadedMesh>();
            result->mesh = std::make_shared<const Mesh>(std::move(*mesh));
            result->key = AssetCache::meshKey(nameOrPath, AssetCache::modifiedTime(nameOrPath), keepUnits);
            loaded.mesh = std::move(result);
        } else if (loaded.problem.empty()) {
            loaded.problem = "loadViewMesh: " + nameOrPath + ": could not be loaded";
        }
        return loaded;
    });
    return entry ? entry->mesh : nullptr;
}

std::shared_ptr<const MapImage> DocumentAssets::map(const std::string& path)
{
    const Entry* entry = lookup(Kind::Map, path, false, [path] {
        Entry loaded;
        ImageLoadStats stats;
        loaded.map = MapImageCache::shared().load(path, &loaded.problem, &stats);
        if (!loaded.map && loaded.problem.empty())
            loaded.problem = path + ": could not be read";
        if (loaded.map && stats.total() > 0)
            loaded.warning
                = path + ": replaced " + std::to_string(stats.total()) + " NaN, Inf or negative samples";
        return loaded;
    });
    return entry ? entry->map : nullptr;
}

std::int64_t DocumentAssets::mapTimestamp(const std::string& path) const
{
    const auto found = m_entries.find(keyOf(Kind::Map, path));
    return found == m_entries.end() ? 0 : found->second.modified;
}

std::shared_ptr<const MapImage> DocumentAssets::releaseMapPixels(
    const std::string& path, const MapImage* image)
{
    const auto found = m_entries.find(keyOf(Kind::Map, path));
    if (found == m_entries.end() || found->second.map.get() != image || !image || !image->hasPixels())
        return nullptr;
    found->second.map = std::make_shared<const MapImage>(MapImage::withoutPixels(*image));
    return found->second.map;
}

const DocumentAssets::Entry* DocumentAssets::lookup(
    Kind kind, const std::string& name, bool immediate, const Load& load)
{
    const std::string key = keyOf(kind, name);
    const std::int64_t modified = AssetCache::modifiedTime(kind == Kind::Map ? fileOfImagePath(name)
            : kind == Kind::Mesh                                             ? meshOfSource(name).first
                                                                             : name);
    const auto found = m_entries.find(key);
    const bool current
        = found != m_entries.end() && found->second.modified == modified && !found->second.reload;
    if (current || m_loading.count(key))
        return found == m_entries.end() ? nullptr : &found->second;
    ++m_loads[kind];
    if (immediate) {
        Entry entry = load();
        entry.modified = modified;
        m_entries[key] = std::move(entry);
        return &m_entries[key];
    }
    m_loading.insert(key);
    QPointer<DocumentAssets> self(this);
    (kind == Kind::Map ? m_mapPool : m_pool).start([self, key, modified, load] {
        Entry entry = load();
        entry.modified = modified;
        QMetaObject::invokeMethod(
            self.data(),
            [self, key, entry = std::move(entry)]() mutable {
                if (self)
                    self->deliver(key, std::move(entry));
            },
            Qt::QueuedConnection);
    });
    // A changed file (or one asked for again): the previous version until the new one arrives.
    if (found != m_entries.end())
        found->second.reload = false;
    return found == m_entries.end() || !found->second.problem.empty() ? nullptr : &found->second;
}

void DocumentAssets::deliver(const std::string& key, Entry entry)
{
    m_loading.erase(key);
    const std::shared_ptr<const Environment> undecoded
        = entry.environment && !entry.environment->decoded() ? entry.environment : nullptr;
    m_entries[key] = std::move(entry);
    Q_EMIT assetArrived();
    if (undecoded) {
        // Its pixels, off the GUI thread (shared by every copy): what reads them (a disk-cache
        // miss, fis and reference, thumbnails) finds them decoded, or waits for this.
        QPointer<DocumentAssets> self(this);
        m_pool.start([self, undecoded] {
            undecoded->image();
            QMetaObject::invokeMethod(
                self.data(),
                [self, undecoded] {
                    if (self)
                        Q_EMIT self->environmentDecoded(undecoded->contentHash());
                },
                Qt::QueuedConnection);
        });
    }
}

bool DocumentAssets::isLoading(Kind kind, const std::string& name) const
{
    return m_loading.count(keyOf(kind, name)) > 0;
}

std::string DocumentAssets::problem(Kind kind, const std::string& name) const
{
    const auto found = m_entries.find(keyOf(kind, name));
    return found == m_entries.end() ? std::string() : found->second.problem;
}

std::string DocumentAssets::warning(Kind kind, const std::string& name) const
{
    const auto found = m_entries.find(keyOf(kind, name));
    return found == m_entries.end() ? std::string() : found->second.warning;
}

void DocumentAssets::retry(Kind kind, const std::string& name)
{
    const auto found = m_entries.find(keyOf(kind, name));
    if (found != m_entries.end() && !found->second.problem.empty())
        m_entries.erase(found);
}

void DocumentAssets::reload(Kind kind, const std::string& name)
{
    const auto found = m_entries.find(keyOf(kind, name));
    if (found != m_entries.end())
        found->second.reload = true;
}

void DocumentAssets::setInUse(const void* user, Kind kind, std::set<std::string> names)
{
    m_inUse[user][kind] = std::move(names);
    dropUnused(kind);
}

void DocumentAssets::forgetUser(const void* user)
{
    if (m_inUse.erase(user) == 0)
        return;
    for (Kind kind : {Kind::Environment, Kind::Mesh, Kind::Map})
        dropUnused(kind);
}

void DocumentAssets::dropUnused(Kind kind)
{
    std::set<std::string> keep;
    for (const auto& [user, kinds] : m_inUse)
        if (const auto names = kinds.find(kind); names != kinds.end())
            for (const std::string& name : names->second)
                keep.insert(keyOf(kind, name));
    const std::string prefix = keyOf(kind, {});
    std::erase_if(m_entries,
        [&](const auto& entry) { return entry.first.rfind(prefix, 0) == 0 && !keep.count(entry.first); });
}

int DocumentAssets::loads(Kind kind) const
{
    const auto found = m_loads.find(kind);
    return found == m_loads.end() ? 0 : found->second;
}

void DocumentAssets::waitForLoads()
{
    m_mapPool.waitForDone();
    m_pool.waitForDone();
    QCoreApplication::sendPostedEvents(this);
}

} // namespace facet
