#include "core/project/AssetCache.h"
#include "core/support/Fnv1a.h"

#include "core/project/ProjectAssets.h"

#include <QDateTime>
#include <QFileInfo>

namespace facet {

namespace {

} // namespace

std::int64_t AssetCache::modifiedTime(const std::string& path)
{
    const QFileInfo info(QString::fromStdString(path));
    return info.isFile() ? info.lastModified().toMSecsSinceEpoch() : 0;
}

std::uint64_t AssetCache::meshKey(const std::string& nameOrPath, std::int64_t modified, bool keepUnits)
{
    Fnv1a64 hash(modified ? std::uint64_t(modified) : 1u);
    hash.addString(nameOrPath);
    if (keepUnits)
        hash.addString("\nasset units");
    return hash.value();
}

std::optional<Environment> AssetCache::environment(
    const std::string& spec, std::string* error, std::string* warning)
{
    const std::int64_t modified = modifiedTime(spec);
    std::lock_guard lock(m_mutex);
    if (const auto found = m_environments.find(spec);
        found != m_environments.end() && found->second.modified == modified)
        return found->second.environment;
    ++m_environmentLoads;
    auto environment = Environment::fromSpec(spec, error, warning);
    if (!environment)
        return std::nullopt;
    m_environments[spec] = EnvironmentEntry {modified, *environment};
    return environment;
}

std::optional<AssetCache::LoadedMesh> AssetCache::mesh(
    const std::string& nameOrPath, std::string* error, std::string* warning, bool keepUnits)
{
    const std::int64_t modified = modifiedTime(nameOrPath);
    const std::pair<std::string, bool> entry {nameOrPath, keepUnits};
    std::lock_guard lock(m_mutex);
    if (const auto found = m_meshes.find(entry);
        found != m_meshes.end() && found->second.modified == modified)
        return found->second.mesh;
    ++m_meshLoads;
    auto mesh = loadViewMesh(nameOrPath, error, warning, keepUnits);
    if (!mesh)
        return std::nullopt;
    LoadedMesh loaded;
    loaded.mesh = std::make_shared<const Mesh>(std::move(*mesh));
    loaded.key = meshKey(nameOrPath, modified, keepUnits);
    m_meshes[entry] = MeshEntry {modified, loaded};
    return loaded;
}

int AssetCache::environmentLoads() const
{
    std::lock_guard lock(m_mutex);
    return m_environmentLoads;
}

int AssetCache::meshLoads() const
{
    std::lock_guard lock(m_mutex);
    return m_meshLoads;
}

} // namespace facet
