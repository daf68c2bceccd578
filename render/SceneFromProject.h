#pragma once
// The one place a Project (core's document) and what it refers to become a RenderScene snapshot:
// the viewport, `facet render` and `facet bench` all build their frames here, so they draw the
// same thing for the same project.

#include <memory>

#include "render/RenderScene.h"

namespace facet {

struct Material;
struct Project;
struct ProjectAssets;
struct IblTextures;

struct SceneOptions {
    // DESIGN.md's reference view: the reference camera, one sample through each pixel centre
    // (no MSAA), the environment behind the object.
    bool referenceView = false;
    // Irradiance from the 9 SH coefficients instead of the irradiance cubemap.
    bool irradianceFromSH = false;
};

// The frame `project` describes, with `assets` (core/ProjectAssets.h: loadProjectAssets) and the
// environment's IBL textures `ibl` (render/IblPrecompute; may be null for a background-only or
// debug frame). Computes the dielectric average albedo the energy-preserving coupling needs.
RenderScene sceneFromProject(const Project& project, const ProjectAssets& assets,
                             const std::shared_ptr<const IblTextures>& ibl, const SceneOptions& options = {});

// The dielectric layer's average albedo E_s,avg of `material` (0 unless it uses the
// energy-preserving coupling); cheap after the first call per visibility term.
double dielectricAverageAlbedoFor(const Material& material);

} // namespace facet
