#include "core/project/ProjectAssets.h"

#include <map>

#include <QDateTime>
#include <QFileInfo>

#include "core/gltf/GltfImport.h"
#include "core/image/MapImageCache.h"
#include "core/mesh/MeshImport.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/project/AssetCache.h"
#include "core/project/AssetLibrary.h"
#include "core/project/Project.h"

namespace facet {

namespace {

void appendWarning(std::string* warning, const std::string& text)
{
    if (!warning || text.empty())
        return;
    if (!warning->empty())
        *warning += '\n';
    *warning += text;
}

std::int64_t modificationTime(const std::string& path)
{
    return QFileInfo(QString::fromStdString(path)).lastModified().toMSecsSinceEpoch();
}

// "material 'Visor' " in messages when the project has several materials, else nothing.
std::string materialLabel(const Project& project, std::size_t material)
{
    if (project.materials.size() < 2)
        return {};
    return "material '" + project.materials[material].name + "' ";
}

} // namespace

std::optional<Mesh> loadViewMesh(
    const std::string& nameOrPath, std::string* error, std::string* warning, bool keepUnits)
{
    if (auto primitive = makePrimitive(nameOrPath)) {
        if (!keepUnits)
            primitive->normalizeToUnitSphere();
        return primitive;
    }
    const std::optional<std::string> file = AssetLibrary::fileForSpec(nameOrPath, "loadViewMesh", error);
    if (!file)
        return std::nullopt;
    std::string path = *file;
    std::string importError;
    std::string importWarning;
    auto mesh = importMesh(path, &importError, &importWarning);
    appendWarning(warning, importWarning);
    if (!mesh) {
        if (error) {
            *error = importError;
            // Say where a missing library file was meant to come from, and how to get it.
            if (!QFileInfo::exists(QString::fromStdString(path)))
                if (const std::string advice = AssetLibrary::missingFileAdvice(path); !advice.empty())
                    *error += "; " + advice;
        }
        return std::nullopt;
    }
    if (!keepUnits)
        mesh->normalizeToUnitSphere();
    return mesh;
}

std::string viewMeshGltfFile(const std::string& nameOrPath)
{
    if (makePrimitive(nameOrPath))
        return {};
    std::string error;
    const std::optional<std::string> file = AssetLibrary::fileForSpec(nameOrPath, "viewMeshGltfFile", &error);
    return file && isGltfFileName(*file) ? *file : std::string();
}

void placeEnvironment(Environment& environment, const EnvironmentSettings& settings)
{
    environment.setRotationDegrees(settings.rotationDegrees);
    environment.setIntensity(settings.intensity);
}

void assignMaps(ProjectAssets& assets, const Project& project, const MapLookup& lookup)
{
    assets.maps.assign(project.materials.size(), {});
    for (std::size_t m = 0; m < project.materials.size(); ++m)
        for (MapSlot slot : kAllMapSlots)
            if (const MaterialMap& map = project.materials[m].map(slot); map.hasTexture())
                assets.maps[m][std::size_t(slot)] = lookup(m, slot, map);
}

std::optional<ProjectAssets> loadProjectAssets(
    const Project& project, std::string* error, std::string* warning)
{
    AssetCache assets;
    return loadProjectAssets(project, assets, error, warning);
}

std::optional<ProjectAssets> loadProjectAssets(
    const Project& project, AssetCache& cache, std::string* error, std::string* warning)
{
    ProjectAssets assets;
    std::string problem;
    std::string note;
    auto environment = cache.environment(project.environment.source, &problem, &note);
    appendWarning(warning, note);
    if (!environment) {
        if (error)
            *error = "loadProjectAssets: environment: " + problem;
        return std::nullopt;
    }
    placeEnvironment(*environment, project.environment);
    assets.environment = std::move(*environment);

    auto mesh = cache.mesh(project.view.mesh, &problem, warning, project.view.keepUnits);
    if (!mesh) {
        if (error)
            *error = "loadProjectAssets: mesh: " + problem;
        return std::nullopt;
    }
    assets.mesh = mesh->mesh;
    assets.meshKey = mesh->key;

    // Each file once: a packed file used by several slots or materials is decoded once
    // (MapImageCache) and reported once; the first that fails ends the load.
    std::map<std::string, std::shared_ptr<const MapImage>> decoded;
    std::string budgetNote;
    const MapBudget budget = MapBudget::fromEnvironment(&budgetNote);
    appendWarning(warning, budgetNote);
    std::string mapError;
    assignMaps(assets, project, [&](std::size_t m, MapSlot slot, const MaterialMap& map) -> LoadedMapImage {
        if (!mapError.empty() || !project.materials[m].usesSlot(slot))
            return {}; // a lobe that is off: not read (Material::usesSlot)
        std::shared_ptr<const MapImage>& image = decoded[map.path];
        if (!image) {
            ImageLoadStats stats;
            image = MapImageCache::shared().load(map.path, &problem, &stats, budget);
            if (!image) {
                mapError
                    = "loadProjectAssets: " + materialLabel(project, m) + toString(slot) + " map: " + problem;
                return {};
            }
            if (stats.total() > 0)
                appendWarning(warning,
                    map.path + ": replaced " + std::to_string(stats.nanCount) + " NaN, "
                        + std::to_string(stats.infCount) + " Inf, " + std::to_string(stats.negativeCount)
                        + " negative samples");
        }
        return {image, map.path, modificationTime(fileOfImagePath(map.path))};
    });
    if (!mapError.empty()) {
        if (error)
            *error = mapError;
        return std::nullopt;
    }
    return assets;
}

} // namespace facet
