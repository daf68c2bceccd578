#include "core/project/AssetProject.h"

#include <QDir>
#include <QFileInfo>

#include "core/gltf/GltfImport.h"

namespace facet {

Project withAsset(Project project, const GltfAsset& asset, const std::string& assetPath)
{
    // B of A/B may name one of the materials about to go: it keeps showing it, as a snapshot.
    project.compare.removeAllMaterials(project.materials);
    project.materials = asset.materials;
    project.currentMaterial = 0;
    project.parts.clear();
    project.parts.reserve(asset.mesh.subMeshes.size());
    for (const SubMesh& sub : asset.mesh.subMeshes)
        project.parts.push_back(
            MeshPart {sub.name, sub.materialIndex < 0 ? 0 : sub.materialIndex, sub.visible});
    project.view.mesh = assetPath;
    return project;
}

std::optional<Project> projectFromAsset(const std::string& path, std::string* error, std::string* warning)
{
    const std::string absolute
        = QDir::cleanPath(QFileInfo(QString::fromStdString(path)).absoluteFilePath()).toStdString();
    std::string importWarning;
    GltfImportOptions options;
    options.materialsOnly = true; // the view's mesh import reads (and checks) the geometry
    const std::optional<GltfAsset> asset = importGltf(absolute, error, &importWarning, options);
    if (warning)
        *warning = importWarning;
    if (!asset)
        return std::nullopt;
    Project project = withAsset(Project::defaultProject(), *asset, absolute);
    project.compare = CompareLayout::defaultFor(project); // B: a snapshot of the asset's first material
    std::string problem;
    if (!project.validate(&problem)) { // importGltf clamps into range: a failure here is a bug
        if (error)
            *error = "projectFromAsset: " + absolute + ": " + problem;
        return std::nullopt;
    }
    return project;
}

bool isAssetFileName(const std::string& path)
{
    return isGltfFileName(path);
}

} // namespace facet
