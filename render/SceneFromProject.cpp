#include "render/SceneFromProject.h"

#include <map>
#include <mutex>

#include "core/project/Project.h"
#include "core/project/ProjectAssets.h"
#include "core/shading/Brdf.h"
#include "core/shading/DfgTable.h"
#include "core/shading/GroundTruth.h"
#include "core/shading/MaterialBrdf.h"
#include "render/IblPrecompute.h"
#include "render/IblTextures.h"
#include "render/Turntable.h"

namespace facet {

namespace {

// E_s,avg of the material's constant dielectric layer (its IOR and KHR_materials_specular factors
// at its roughness factor) and of its film's Schlick layer (the film's index and thickness without
// a texture), as MaterialBrdf's coupling takes them.
CouplingAlbedos averageAlbedos(const MaterialBrdf& brdf, const Material& material)
{
    MaterialInfo info;
    info.ior = material.ior;
    info.specular = material.specular();
    info.specularColor = material.specularColor();
    info.iridescence = material.iridescence();
    info.iridescenceIor = material.iridescenceIor;
    info.iridescenceThickness = material.iridescenceThicknessMaximum();
    const DielectricReflectance layer = dielectricReflectance(info);
    CouplingAlbedos albedos;
    albedos.dielectric = brdf.dielectricSpecularAverageAlbedo(layer.maxF0(), material.roughness(), layer.f90);
    if (material.hasIridescence()) {
        const DielectricReflectance film = filmLayer(info, layer.f0);
        albedos.film = brdf.dielectricSpecularAverageAlbedo(film.maxF0(), material.roughness(), film.f90);
    }
    return albedos;
}

} // namespace

CouplingAlbedos couplingAlbedosFor(const Material& material, IblMethod method)
{
    const ShadingModel& shading = material.shading;
    if (shading.coupling != DielectricCoupling::EnergyPreserving)
        return {};
    if (method == IblMethod::Reference) {
        // The ground truth's own albedo table (core/shading/GroundTruth), so the reference method
        // integrates the same BRDF as `facet render --spp`.
        const GroundTruthSettings truth;
        const MaterialBrdf brdf(shading, *albedoTable(truth.albedoTableSize, truth.albedoTableSamples, shading.visibility));
        return averageAlbedos(brdf, material);
    }
    // One 32 x 32 table per visibility term for the process: E_s,avg is an integral over n.v, so
    // the table's resolution is ample (docs/energy.md).
    static std::mutex mutex;
    static std::map<Visibility, std::shared_ptr<const DfgTable>> tables;
    std::shared_ptr<const DfgTable> table;
    {
        std::lock_guard lock(mutex);
        auto& slot = tables[shading.visibility];
        if (!slot)
            slot = std::make_shared<const DfgTable>(DfgTable::compute(32, 512, shading.visibility));
        table = slot;
    }
    const MaterialBrdf brdf(shading, *table);
    return averageAlbedos(brdf, material);
}

IblSettings dfgSettingsFor(const IblSettings& settings, IblMethod method)
{
    IblSettings s = settings;
    if (method == IblMethod::Reference) {
        const GroundTruthSettings truth;
        s.dfgSize = truth.albedoTableSize;
        s.dfgSamples = truth.albedoTableSamples;
    }
    return s;
}

bool addDfgTables(IblPrecompute& precompute, const IblSettings& settings, RenderScene& scene, IblStats* stats,
    std::string* error)
{
    const IblSettings tableSettings = dfgSettingsFor(settings, scene.sampling.method);
    for (Visibility visibility : dfgVisibilitiesFor(scene)) {
        const std::shared_ptr<const DfgLut> table = precompute.dfgTable(tableSettings, visibility, stats, error);
        if (!table)
            return false;
        scene.environment.setDfgLut(table);
    }
    return true;
}

RenderScene sceneFromProject(const Project& project, const ProjectAssets& assets,
                             const std::shared_ptr<const IblTextures>& ibl, const SceneOptions& options)
{
    const IblMethod method = options.iblMethod.value_or(project.environment.method);
    RenderScene scene;
    scene.mesh = assets.mesh;
    scene.meshKey = assets.meshKey;
    scene.materials.assign(project.materials.size(), RenderMaterial {});
    for (std::size_t m = 0; m < project.materials.size(); ++m) {
        RenderMaterial& material = scene.materials[m];
        material.material = project.materials[m];
        material.couplingAlbedos = couplingAlbedosFor(material.material, method);
        if (m >= assets.maps.size())
            continue; // not loaded (yet): the factors alone
        for (MapSlot slot : kAllMapSlots) {
            const LoadedMapImage& map = assets.maps[m][std::size_t(slot)];
            material.maps[std::size_t(slot)] = RenderMapImage {map.image, map.path, map.timestamp};
        }
    }
    scene.parts.reserve(project.parts.size());
    for (const MeshPart& part : project.parts)
        scene.parts.push_back(RenderPart {part.material, part.visible});
    scene.lights = project.lights;
    scene.sampling.method = method;
    scene.sampling.samples = project.environment.samples > 0 && method == project.environment.method
        ? project.environment.samples
        : defaultIblSamples(method);
    scene.view = project.view;
    scene.camera = project.camera;
    if (options.referenceView) {
        scene.camera = Camera::referenceView();
        scene.view.msaaSamples = 1;
        // The reference view's background is the environment, as the ground truth's; a
        // transparent one stays transparent (coverage in alpha, nothing behind).
        if (project.view.background != BackgroundMode::Transparent)
            scene.view.background = BackgroundMode::Environment;
        scene.analyticSphere = method != IblMethod::SplitSum && project.view.mesh == "sphere";
        scene.pixelCentres = true;
    }
    scene.environment = environmentLighting(ibl, assets.environment.rotationDegrees(), assets.environment.intensity(),
                                            options.irradianceFromSH);
    applyTurntable(scene, TurntableSubject::Object, options.objectTurnDegrees);
    applyTurntable(scene, TurntableSubject::Environment, options.environmentTurnDegrees);
    scene.wireframe = options.wireframe;
    return scene;
}

SceneOptions sceneOptionsFor(const IblSettings& settings, bool referenceView)
{
    SceneOptions options;
    options.referenceView = referenceView;
    options.irradianceFromSH = settings.irradiance == IblSettings::Irradiance::SH;
    return options;
}

} // namespace facet
