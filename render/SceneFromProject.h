#pragma once
// The one place a Project (core's document) and what it refers to become a RenderScene snapshot:
// the viewport, `facet render` and `facet bench` all build their frames here, so they draw the
// same thing for the same project.

#include <memory>
#include <optional>
#include <string>

#include "render/IblSettings.h"
#include "render/RenderScene.h"

namespace facet {

struct Material;
struct Project;
struct ProjectAssets;
struct IblTextures;
struct IblStats;
class IblPrecompute;

struct SceneOptions {
    // docs/architecture.md's reference view: the reference camera, one sample through each pixel centre
    // (no MSAA), the environment behind the object. With the fis or reference method and the
    // "sphere" mesh, also the analytic sphere (RenderScene::analyticSphere): the split sum keeps the mesh
    // normals, so its goldens and measured errors stay those of the real-time path.
    bool referenceView = false;
    // Irradiance from the 9 SH coefficients instead of the irradiance cubemap.
    bool irradianceFromSH = false;
    // The IBL method of the frame instead of the project's environment.method: the window
    // previews with the split sum and refines by the sampled method in scenes of its own
    // (FrameRenderer::refine; the error view's reference).
    std::optional<IblMethod> iblMethod;
    // The window's view of it (render/Turntable.h): the object turned about +Y by objectTurnDegrees
    // (the model matrix), the environment by environmentTurnDegrees on top of its own rotation, and
    // the mesh's edges drawn over it (RenderScene::wireframe). None of them is part of the project.
    double objectTurnDegrees = 0.0;
    double environmentTurnDegrees = 0.0;
    bool wireframe = false;
};

// The SceneOptions that go with IBL `settings`: irradiance from the SH9 coefficients when the
// settings choose them, the irradiance cubemap otherwise.
SceneOptions sceneOptionsFor(const IblSettings& settings, bool referenceView);

// The frame `project` describes, with `assets` (core/project/ProjectAssets.h: loadProjectAssets) and the
// environment's IBL textures `ibl` (render/IblPrecompute; may be null for a background-only or
// debug frame), turned and drawn as `options` say. Computes the dielectric average albedo the
// energy-preserving coupling needs. The scene has no split-sum DFG table and no environment source
// yet: a frame is built with FrameRenderer::prepare (render/FrameRenderer.h), which adds them; this
// alone serves callers that only read the scene (which maps a frame would draw).
RenderScene sceneFromProject(const Project& project, const ProjectAssets& assets,
                             const std::shared_ptr<const IblTextures>& ibl, const SceneOptions& options = {});

// The DFG table settings a frame of `method` uses: `settings`' for the split sum; for Reference the
// ground truth's albedo table size and samples (GroundTruthSettings: 64^2 x 2048), so that the
// multiple-scattering and coupling terms read the E the truth reads.
IblSettings dfgSettingsFor(const IblSettings& settings, IblMethod method);

// Puts into scene.environment the split-sum DFG table of every visibility term the scene's
// materials use (dfgVisibilitiesFor), at dfgSettingsFor(settings, scene.sampling.method), from
// `precompute` (memory, disk, or one GPU pass each), so
// that Renderer::render finds the table of each material's own variant. Needs the precompute's
// GL context current. `stats` (optional) is added to (IblStats). False with *error
// ("IblPrecompute::dfgTable: ...") when a table cannot be made.
bool addDfgTables(IblPrecompute& precompute, const IblSettings& settings, RenderScene& scene, IblStats* stats,
    std::string* error);

// The average albedos E_s,avg of the layers `material`'s energy-preserving coupling couples its
// base to (zero unless it uses that coupling); cheap after the first call per visibility term.
// Reference frames take them from the ground truth's albedo table, the others from a 32^2 x 512 one.
CouplingAlbedos couplingAlbedosFor(const Material& material, IblMethod method = IblMethod::SplitSum);

} // namespace facet
