#pragma once
// The surface renderer: draws a RenderScene snapshot into an HDR (RGBA16F/32F) Framebuffer, and
// tone-maps an HDR framebuffer for display. It owns every GL object it uses (programs by variant
// key, the mesh buffers, the MSAA target, the tone-mapping pass) and no widget; the viewport and
// the headless commands call the same two functions. The material textures (render/TextureCache)
// may be shared with the renderers of other contexts of one share group (the views of a window):
// a texture set is uploaded once for every view that shows it. Textures no frame uses are
// deleted by TextureCache::evictUnused, which the caller runs once per complete frame (all the
// cells of a grid): render() keeps every texture, so cells with different materials never
// evict each other's maps mid-frame.
//
//   Renderer renderer;                                // GL context current
//   renderer.render(scene, hdr, &error);              // linear radiance, background included
//   renderer.toneMap(hdr, display, scene.view, &error); // exposure, tone mapper, encoding
//
// docs/rendering.md describes the passes, the variant flags, the IBL formulas and the caches.

#include <memory>
#include <string>
#include <vector>

#include "render/GLTexture.h"
#include "render/RenderScene.h"
#include "render/RenderStats.h"
#include "render/ShaderVariant.h"

namespace facet {

class Framebuffer;
class GpuMesh;
class ShaderProgram;
class TextureCache;
class ToneMapping;

class Renderer {
public:
    // Needs the GL context current; creates nothing until the first frame. `textures` null: a
    // texture cache of its own; otherwise one shared with renderers of contexts sharing this one.
    explicit Renderer(std::shared_ptr<TextureCache> textures = nullptr);
    ~Renderer(); // the same context must be current
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Draws the scene into `hdrTarget` (its size is the viewport; aspect from it): background,
    // then the mesh with the scene's surface variant, into an MSAA target resolved into
    // `hdrTarget` when view.msaaSamples > 1. False with *error ("Renderer::render: ...") when a
    // program does not compile or the MSAA target cannot be made; nothing is drawn then. Each
    // material is shaded with the DFG table of its own visibility term
    // (EnvironmentLighting::dfgLutFor): a scene without it is refused before anything is drawn.
    bool render(const RenderScene& scene, Framebuffer& hdrTarget, std::string* error);

    // Display transform of `hdr` into `output` (same size). Writes display-encoded values, with
    // straight alpha when `straightAlpha` (ToneMapping::apply), else alpha 1.
    bool toneMap(const Framebuffer& hdr, Framebuffer& output, const ViewSettings& view, std::string* error,
        bool straightAlpha = false);
    // The same into any framebuffer (0: the default one, e.g. a widget's), width x height = hdr's size.
    bool toneMapTo(const Framebuffer& hdr, unsigned framebuffer, const ViewSettings& view, std::string* error,
        bool straightAlpha = false);

    // Every map slot and the sheen's table: a variant never binds more textures than this.
    static constexpr int kAllMapUnits = kMapSlotCount + 1;
    // The variant key render() uses for material `materialIndex` of `scene`. A material whose
    // distinct textures (and the sheen's table) need more than `mapUnits` texture units leaves
    // out its least needed maps until they fit (the iridescence thickness first, then the
    // sheen's roughness, the coat's normal, ..., the base colour last; a texture another slot
    // of the material still reads is never the one left out): their factors shade alone, and
    // *mapsLeftOut (when given) lists them.
    static SurfaceVariantKey variantKeyFor(const RenderScene& scene, int materialIndex = 0,
        int mapUnits = kAllMapUnits, std::vector<MapSlot>* mapsLeftOut = nullptr);
    // The texture units the surface program may give maps: the driver's fragment units
    // (GL_MAX_TEXTURE_IMAGE_UNITS, 16 at least; llvmpipe and current desktop GPUs have 32) less the
    // lighting's (render/RendererDetail.h), read at the first frame. setMapUnitLimit lowers it
    // (a test of a 16-unit driver on a 32-unit one); 0 goes back to the driver's.
    int mapUnits() const;
    void setMapUnitLimit(int units) { m_mapUnitLimit = units; }

    // The material textures (render/TextureCache.h): the viewport uploads maps through it in
    // slices between frames and sets the frame's anisotropy; render() uploads what is missing.
    TextureCache& textureCache() { return *m_textures; }
    const std::shared_ptr<TextureCache>& sharedTextureCache() const { return m_textures; }

    const RenderStats& lastFrameStats() const { return m_frame; }
    // The slots the last frame shaded with their factors alone (variantKeyFor), over its materials,
    // in MapSlot order: as many as lastFrameStats().mapsLeftOut counts when one material has them.
    const std::vector<MapSlot>& lastFrameMapsLeftOut() const { return m_mapsLeftOut; }
    const RenderStats& totalStats() const { return m_total; }
    // Per-step milliseconds via glFinish() (stalls; for benchmarks and tests).
    void setTimingEnabled(bool enabled) { m_timing = enabled; }

private:
    bool ensureFixedPrograms(std::string* error);
    bool ensureMsaaTarget(int width, int height, int samples, bool fullFloat, std::string* error);
    void destroyMsaaTarget();
    // The mesh's edges over the surfaces (RenderScene::wireframe); false with *error when its
    // program does not compile.
    bool drawWireframe(
        const RenderScene& scene, const glm::dmat4& view, const glm::dmat4& projection, std::string* error);
    void drawBackground(const RenderScene& scene, const glm::dmat4& view, const glm::dmat4& projection);
    enum class SurfacePass { Opaque, Blended };
    void setFrameUniforms(const ShaderProgram& program, const SurfaceVariantKey& key, const RenderScene& scene,
                          const glm::dmat4& view, const glm::dmat4& projection);
    void setMaterialUniforms(const ShaderProgram& program, const SurfaceVariantKey& key,
                             const RenderMaterial& material, const EnvironmentLighting& environment);
    void updatePartCentres(const Mesh& mesh);
    bool drawSurface(const RenderScene& scene, const glm::dmat4& view, const glm::dmat4& projection, SurfacePass pass,
                     std::string* error);

    SurfaceProgramCache m_surfacePrograms;
    std::unique_ptr<ShaderProgram> m_backgroundProgram;
    std::unique_ptr<ShaderProgram> m_wireframeProgram; // made when a frame first asks for it
    std::unique_ptr<ToneMapping> m_toneMapping;
    std::unique_ptr<GpuMesh> m_mesh;
    std::shared_ptr<TextureCache> m_textures;
    unsigned m_emptyVao = 0;
    GLTexture m_sheenLut; // render/SheenLut.h: made when a sheen material is first drawn
    unsigned m_msaaFramebuffer = 0;
    unsigned m_msaaColor = 0;
    unsigned m_msaaDepth = 0;
    int m_msaaWidth = 0;
    int m_msaaHeight = 0;
    int m_msaaSamples = 0;
    bool m_msaaFullFloat = false;
    float m_maxRadiance = 65504.0f;
    std::vector<glm::dvec3> m_partCentres; // per sub-mesh of the uploaded mesh, model space
    RenderStats m_frame;
    RenderStats m_total;
    bool m_timing = false;
    int m_mapUnits = 0; // the driver's, less the lighting's; 0 until the first frame
    int m_mapUnitLimit = 0;
    std::vector<MapSlot> m_mapsLeftOut;
};

} // namespace facet
