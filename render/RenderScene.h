#pragma once
// A snapshot of everything one frame shows, built by the caller (ui/ or the headless commands)
// from core's document. Renderer::render() reads it and keeps nothing but GPU caches keyed by
// content: the mesh by `meshKey`, each map by (path, timestamp, colour space).
// No GL header here: GL objects that the scene refers to (the IBL textures of
// render/IblPrecompute) travel as plain names.

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/image/Image.h"
#include "core/image/MapImage.h"
#include "core/material/Material.h"
#include "core/mesh/Mesh.h"
#include "core/project/Camera.h"
#include "core/project/Light.h"
#include "core/project/Project.h"
#include "core/shading/ShadingModel.h"
#include "render/DfgLut.h"
#include "render/EnvironmentSource.h"
#include "render/IblTextures.h"

namespace facet {

// One material map's texture as core loaded it, in the file's own bit depth and channels
// (core/image/MapImage.h). The numbers are as the file stores them (not converted to linear): render/
// decodes per MaterialMap::colorSpace.
struct RenderMapImage {
    std::shared_ptr<const MapImage> image; // null: the slot uses its constant factor only
    std::string path;                   // the cache key with timestamp and colour space
    std::int64_t timestamp = 0;         // file modification time (any unit, e.g. ms since epoch)
};

// One split-sum DFG table as the renderer binds it (render/DfgLut.h has the layout).
struct DfgLutBinding {
    unsigned texture
        = 0; // GL_TEXTURE_2D, RGBA = scale, bias, E, W (core/shading/DfgTable.h layout), LINEAR; 0: none
    int size = 0;
};

// The environment at source resolution and its sampling tables (render/EnvironmentSource.h), as
// GL names: what IblMethod::Reference reads instead of the cubes, and Fis for its sharpest lobes.
struct EnvironmentSourceBinding {
    unsigned radiance = 0; // GL_RGB32F equirect; 0: none (the scene cannot use those methods)
    unsigned conditionalCdf = 0;
    unsigned marginalCdf = 0;
    unsigned pdf = 0;
};

// The IBL textures of the environment (render/IblTextures.h, made by render/IblPrecompute), as
// GL names owned by whoever made them (or by `textures` and `dfgTables`); they must outlive the
// render() call. Tests build tiny ones by hand (a uniform environment needs no precompute).
struct EnvironmentLighting {
    unsigned environmentCubemap = 0; // radiance with its box-filtered mip chain (the background, Fis)
    int environmentSize = 0;         // its level-0 face size
    int environmentMipLevels = 1;
    unsigned prefilteredCubemap = 0; // level i: perceptual roughness i / (levels - 1)
    int prefilteredLevels = 1;
    unsigned irradianceCubemap = 0; // irradiance E (not / pi); unused when useSH
    // The split-sum tables by the visibility term V they were integrated with, index int(V): a
    // table holds integrals of D V F (n.l), so each material needs the one of its own
    // ShadingModel::visibility, and one frame may hold several. Renderer::render draws a material
    // only with dfgLutFor(its V) and fails when that is missing: it never falls back to another
    // V's table (a Schlick-GGX material on the correlated table was 3.5-11% too bright).
    std::array<DfgLutBinding, kVisibilityCount> dfgLuts {};
    bool useSH = false;
    std::array<glm::vec3, 9> irradianceSH {}; // premultiplied c_i A_l of the UNROTATED environment
    double rotationDegrees = 0.0; // about +Y (Environment::toImageFrame)
    double intensity = 1.0;       // linear radiance multiplier
    EnvironmentSourceBinding source;
    // The source textures of IblPrecompute::source(), bound and kept alive.
    void setSource(const std::shared_ptr<const EnvironmentSourceTextures>& made)
    {
        sourceTextures = made;
        source = made ? EnvironmentSourceBinding {made->radiance.id(), made->conditionalCdf.id(), made->marginalCdf.id(),
                                                  made->pdf.id()}
                      : EnvironmentSourceBinding {};
    }
    // Keep the textures above alive while the scene is held (optional).
    std::shared_ptr<const IblTextures> textures;
    std::shared_ptr<const EnvironmentSourceTextures> sourceTextures;
    std::array<std::shared_ptr<const DfgLut>, kVisibilityCount> dfgTables {};

    // The table for materials of visibility term `visibility`; null when the scene has none.
    const DfgLutBinding* dfgLutFor(Visibility visibility) const
    {
        const DfgLutBinding& binding = dfgLuts[std::size_t(visibility)];
        return binding.texture ? &binding : nullptr;
    }
    // A table made by hand (tests): `visibility` is the V it was integrated with.
    void setDfgLut(Visibility visibility, unsigned texture, int size)
    {
        dfgLuts[std::size_t(visibility)] = DfgLutBinding {texture, size};
        dfgTables[std::size_t(visibility)].reset();
    }
    // A table of IblPrecompute::dfgTable: filed under the V it carries, and kept alive.
    void setDfgLut(const std::shared_ptr<const DfgLut>& table)
    {
        if (!table)
            return;
        dfgLuts[std::size_t(table->visibility)] = DfgLutBinding {table->id(), table->size};
        dfgTables[std::size_t(table->visibility)] = table;
    }
};

// The lighting of an IblPrecompute::prepare() result, rotated and scaled as the environment says,
// with no DFG table yet: FrameRenderer::prepare (render/FrameRenderer.h) adds the ones the scene needs
// (or EnvironmentLighting::setDfgLut).
inline EnvironmentLighting environmentLighting(const std::shared_ptr<const IblTextures>& ibl, double rotationDegrees,
                                               double intensity, bool useSH)
{
    EnvironmentLighting lighting;
    if (ibl) {
        lighting.environmentCubemap = ibl->environmentCubemap();
        lighting.environmentSize = ibl->environmentSize;
        lighting.environmentMipLevels = ibl->environmentMipLevels;
        lighting.prefilteredCubemap = ibl->prefilteredCubemap();
        lighting.prefilteredLevels = ibl->prefilteredMipLevels;
        lighting.irradianceCubemap = ibl->irradianceCubemap();
        lighting.irradianceSH = ibl->irradianceSH;
        lighting.textures = ibl;
    }
    lighting.useSH = useSH;
    lighting.rotationDegrees = rotationDegrees;
    lighting.intensity = intensity;
    return lighting;
}

// The average albedos E_s,avg (MaterialBrdf::dielectricSpecularAverageAlbedo) of the compensated
// dielectric layer and of the film's Schlick layer (KHR_materials_iridescence, filmLayer), for the
// energy-preserving coupling; 0 where unused.
struct CouplingAlbedos {
    double dielectric = 0.0;
    double film = 0.0;
};

// One material of the scene with the images of its maps.
struct RenderMaterial {
    Material material;
    std::array<RenderMapImage, kMapSlotCount> maps {}; // indexed by MapSlot
    // E_s,avg at the material's constant roughness of the layers the energy-preserving coupling
    // couples the base to (render/SceneFromProject couplingAlbedosFor).
    CouplingAlbedos couplingAlbedos;
};

// What one sub-mesh of the scene's mesh shows (core/project/Project.h MeshPart).
struct RenderPart {
    int material = 0; // index into RenderScene::materials
    bool visible = true;
};

// How a draw integrates the environment (core/project/Project.h IblMethod). Reference and Fis draws take
// samples [sampleBase, sampleBase + samples) of a run of `total`: Reference of each pixel's
// sequence (shifted Sobol' points: any split of a run into draws gives the same points,
// core/shading/Sampling.h), Fis of hammersley(., total), whose points and footprints depend on the run's
// length; so frames accumulated by render/FrameAccumulator give what one draw of the whole run
// would.
// The split sum's sharpest lobes (perceptual roughness below its prefiltered level 1, 0.106 at
// the default six levels) are integrated per pixel by this many filtered importance samples of
// the environment cube (IblMethod::Fis's estimator, resources/shaders/ibl_fis.glsl) instead of
// the resampled level-0/1 lookup; blended in over the lookup's lod 0.5 to 1. Measured on the five
// CC0 maps (64^2 reference view, docs/benchmarks.md "Sharp lobes"): roughness 0.05 went from
// 7.75% to 4.34% mean relative RMSE (1.59% on the analytic sphere) with no case worse. A shader
// variant (SurfaceFeature::SplitSumSharpLobes) only for materials that reach below level 1: on
// llvmpipe a mirror-like 1280x720 sphere's surface pass takes 169-218 ms, a rougher one 42-54 ms.
inline constexpr int kSplitSumSharpLobeSamples = 4;

struct IblSampling {
    IblMethod method = IblMethod::SplitSum;
    // IblMethod::SplitSum: the sharp lobes' samples (0: the prefiltered lookup only).
    int sharpLobeSamples = kSplitSumSharpLobeSamples;
    int samples = 1;
    int sampleBase = 0;
    int runLength = 0; // the run's samples per pixel; 0: `samples` (one draw is the run)
    std::uint32_t seed = 0;
    int total() const { return runLength > 0 ? runLength : samples; }
    bool operator==(const IblSampling&) const = default;
};

// The wireframe's colour once exposed (linear radiance; the line's radiance is this over
// 2^exposureEV): an orange that reads on grey, metal and sky alike.
inline constexpr glm::vec3 kWireframeColor {1.0f, 0.6f, 0.15f};

struct RenderScene {
    std::shared_ptr<const Mesh> mesh; // drawn with the model matrix; null: background only
    std::uint64_t meshKey = 0;        // content key: a new key re-uploads, the same key never does
    glm::dmat4 modelMatrix {1.0};
    // At least one. Sub-mesh i of `mesh` is drawn with materials[parts[i].material]; a sub-mesh
    // without an entry in `parts` (or a mesh without sub-meshes) uses material 0 and is visible.
    std::vector<RenderMaterial> materials {RenderMaterial {}};
    std::vector<RenderPart> parts;
    std::vector<Light> lights; // enabled ones are drawn, at most kMaxPunctualLights
    Camera camera;
    EnvironmentLighting environment;
    IblSampling sampling;
    // The mesh is the unit sphere at the origin (model matrix identity) seen in docs/architecture.md's
    // reference view: shade each pixel at the exact hit of its ray, as core/shading/GroundTruth does.
    // The sphere mesh's interpolated normals are off by up to ~1e-3 rad, which moves a
    // roughness-0.05 reflection by about its own width (2% relative RMSE against the truth).
    bool analyticSphere = false;
    // docs/architecture.md's reference view: one ray through each pixel centre, so a converging method's
    // draws are not jittered (the metric compares pixel centres with the ground truth's).
    bool pixelCentres = false;
    // This draw's sub-pixel offset in pixels, each in [-0.5, 0.5): the projection is translated
    // by it, so draws accumulated at different offsets anti-alias the edges (FrameRenderer sets
    // it per draw of a converging method; 0 for every other frame).
    glm::dvec2 subpixelJitter {0.0};
    // The background writes alpha 0 instead of 1, so the target's alpha is the object's coverage
    // (fractional at MSAA-resolved silhouettes and under blended materials): what the error view
    // masks its numbers with (core/image/ImageMetrics objectMask). Radiance is the same either way.
    bool coverageAlpha = false;
    // The mesh's edges drawn over the surfaces (View > Wireframe): kWireframeColor lines, depth
    // tested against what is drawn (hidden edges stay hidden), offset towards the camera so a
    // line on its own face shows.
    bool wireframe = false;
    // exposureEV, toneMapper, displayEncoding, gamma (tone-map pass); debugView, msaaSamples,
    // background, backgroundColor, backgroundBlurRoughness (surface pass).
    ViewSettings view;

    // The material of sub-mesh `part` (0 without an entry or for an index out of range) and
    // whether it is drawn.
    int materialOfPart(std::size_t part) const
    {
        const int m = part < parts.size() ? parts[part].material : 0;
        return m >= 0 && std::size_t(m) < materials.size() ? m : 0;
    }
    bool isPartVisible(std::size_t part) const { return part >= parts.size() || parts[part].visible; }
};

// The visibility terms whose split-sum table a frame of `scene` needs (the
// ShadingModel::visibility of each material a visible part draws with), without repeats: what a
// caller asks IblPrecompute::dfgTable for and Renderer::render looks up.
inline std::vector<Visibility> dfgVisibilitiesFor(const RenderScene& scene)
{
    std::vector<Visibility> needed;
    if (!scene.mesh || scene.mesh->indices.empty())
        return needed;
    const std::size_t partCount = std::max<std::size_t>(scene.mesh->subMeshes.size(), 1);
    for (std::size_t p = 0; p < partCount; ++p) {
        if (!scene.isPartVisible(p))
            continue;
        const Visibility v = scene.materials[std::size_t(scene.materialOfPart(p))].material.shading.visibility;
        if (std::find(needed.begin(), needed.end(), v) == needed.end())
            needed.push_back(v);
    }
    return needed;
}

} // namespace facet
