#pragma once
// The one way a frame is made, for every caller: the viewport (ui/viewport/ViewportRenderer, one per view),
// `facet render`, `facet bench`, the benchmarks and the GL tests. It owns, in one GL context (or
// share group):
//   - the IBL precompute (render/IblPrecompute) and so the IBL results, looked up by content
//     (the environment's pixel hash, the IBL settings, the DFG table's visibility term) in memory
//     (LRU within IblPrecompute::kMemoryBudgetBytes) and on disk: an environment shown by four
//     views, or by nine cells of a grid, is precomputed once;
//   - the surface renderer (render/Renderer: programs, the mesh, the material textures);
//   - the render targets, pooled by size, so grid cells of one size share one.
// A caller names a project and its assets (core/project/ProjectAssets: the mesh, the map images, the
// environment image); FrameRenderer turns them into a RenderScene with its GL textures and draws
// it, so no caller handles GL texture names or their lifetimes.
//
//   FrameRenderer frames;                                   // GL context current
//   auto scene = frames.prepare(project, assets, settings, {}, &stats, &error);
//   auto image = frames.renderImage(*scene, 512, 512, FrameOutput::LinearRadiance, &error);
//   frames.present(*scene, widgetFbo, {0, 0, w, h}, 0.5, &error); // a reduced preview, stretched
//
// Threading and lifetime: every call needs the same GL context current; destroy it with that
// context current. Several FrameRenderers may share one IblPrecompute (the constructor taking one):
// `facet render`-style tests make a fresh surface renderer per frame and keep the IBL results.

#include "core/image/Image.h"
#include "render/FrameAccumulator.h"
#include "render/Framebuffer.h"
#include "render/IblPrecompute.h"
#include "render/RenderScene.h"
#include "render/RenderStats.h"
#include "render/SceneFromProject.h"

#include <QString>

#include <cstdint>
#include <functional>
#include <list>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace facet {

class Environment;
class Renderer;
class TextureCache;
struct IblSettings;
struct Project;
struct ProjectAssets;

// What renderImage() reads back.
enum class FrameOutput {
    LinearRadiance, // the HDR target as it is: scene radiance, no exposure, no tone mapping
    DisplayReferred, // the viewport's display transform (exposure, tone mapper, encoding), tagged sRGB
};

// A rectangle of a framebuffer in device pixels, origin bottom-left (GL's).
struct FrameRect {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
};

class FrameRenderer {
public:
    // Needs the context current. `cacheDirectory` empty: the IBL disk cache's default folder;
    // `useDiskCache` false: memory only (tests and benchmarks never touch the user's cache).
    explicit FrameRenderer(const QString& cacheDirectory = {}, bool useDiskCache = true);
    // Shares `precompute` (and so its IBL results) and, when given, `textures` (the material
    // textures) with other FrameRenderers of the context or of contexts sharing with it (the views
    // of a window: ui/viewport/ViewShareGroup). Targets, the mesh's buffers and vertex arrays stay per
    // renderer (container objects are per context).
    explicit FrameRenderer(
        std::shared_ptr<IblPrecompute> precompute, std::shared_ptr<TextureCache> textures = nullptr);
    ~FrameRenderer();
    FrameRenderer(const FrameRenderer&) = delete;
    FrameRenderer& operator=(const FrameRenderer&) = delete;

    // The one way every caller builds a frame (the views and their refinement, the Compare view's
    // cells, `facet render`, `sheet`, `bench`, the tests): the frame `project` describes with `assets`
    // (core/project/ProjectAssets.h), as `options` say (render/SceneFromProject.h: reference view, method,
    // the view's turntable and wireframe), lit by the IBL of its environment at `settings`, with the
    // DFG table of every visibility term its materials use and, for a sampled method, the
    // environment at source resolution. `ibl`: the IBL set when the caller has it already (the
    // window's lighting worker made it); null: made here (a memory hit after the first call).
    // `stats` (optional) says what the precompute did (reset when the set is made here, then the
    // tables added). nullopt with *error ("IblPrecompute::prepare: ...", "IblPrecompute::dfgTable:
    // ...") on failure.
    std::optional<RenderScene> prepare(const Project& project, const ProjectAssets& assets,
        const IblSettings& settings, const SceneOptions& options, IblStats* stats, std::string* error,
        std::shared_ptr<const IblTextures> ibl = nullptr);

    // The IBL set of `environment` at `settings` (a memory hit after the first call), for callers
    // that keep it across frames (the viewport).
    std::shared_ptr<const IblTextures> lighting(
        const Environment& environment, const IblSettings& settings, IblStats* stats, std::string* error);

    // Renders `scene` into a width x height target of `format` and reads it back (top row first).
    // nullopt with *error set by the step that failed ("Framebuffer::create: ...", "Renderer::render: ...").
    std::optional<Image> renderImage(const RenderScene& scene, int width, int height, FrameOutput output,
        std::string* error, FramebufferFormat format = FramebufferFormat::RGBA16F);

    // What renderConverged() did.
    struct ConvergedStats {
        int samples = 0; // per pixel
        int draws = 0;
        double seconds = 0.0; // wall time of the draws, glFinish'ed
        // FrameAccumulator::noise over `noiseMask` (Reference: a random estimate; an empty mask:
        // the object, objectMask of the first draw's coverage, or every pixel when nothing is
        // covered); unset for one draw and for Fis (deterministic: its error is a bias, not noise)
        std::optional<double> noise;
    };
    // renderImage() for any method: a Reference or Fis scene is drawn in draws of at most
    // kSamplesPerDraw samples (Fis: [0, samples) of a run of `samples`; Reference: two
    // independent runs of samples / 2, draws alternating, as refine() draws them, so that the
    // noise estimate is the error's; scene.sampling's sampleBase, samples, seed and runLength
    // replaced) into RGBA32F targets summed by a FrameAccumulator, then
    // resolved and read back; a split-sum scene is one renderImage() into a target of `format`. A
    // debug view that does not show the integrated light (debugViewShowsIntegratedLight) takes
    // one sample whatever `samples` says.
    static constexpr int kSamplesPerDraw = 64;
    std::optional<Image> renderConverged(const RenderScene& scene, int width, int height, FrameOutput output,
        int samples, std::string* error, ConvergedStats* stats = nullptr,
        const std::vector<std::uint8_t>& noiseMask = {}, FramebufferFormat format = FramebufferFormat::RGBA16F);

    // Renders `scene` at `scale` in (0, 1] of `rect`'s size and writes its display transform into
    // `rect` of `framebuffer` (0: the default one, e.g. a widget's): at scale 1 over the whole
    // framebuffer directly, otherwise through a display target stretched (bilinear) or copied
    // into the rectangle. Leaves `framebuffer` bound for drawing with the rectangle's viewport.
    // False with *error when a step failed; the rectangle is then untouched.
    bool present(const RenderScene& scene, unsigned framebuffer, const FrameRect& rect, double scale,
        std::string* error);
    // One step of a view's progressive refinement (the window's still frame, docs/rendering.md
    // "Refinement"): `scene` drawn by its sampled method (Fis, Reference) toward
    // scene.sampling.samples per pixel, accumulated across calls, shown in `rect` of
    // `framebuffer` at full resolution. A restart (`restart`, or a new size) draws `preview` (the
    // same scene by the split sum) into a held target and shows it; each later call adds one draw
    // of `drawSamples` samples (at most what is left) and shows the held frame until
    // kRefinementShownAfter samples are in for Reference (an image of a few samples is noise) or
    // all of them for a level of Fis (fisRefinementLevels: a partial run of its points covers part
    // of the lobe; each complete level is held on screen while the next accumulates), then the mean
    // so far. Calls once done add nothing and show the mean again (an exposure edit). Draws come
    // in pairs of one power-of-two size and one sub-pixel offset, each pair an aligned block of
    // the run: a draw takes at most `drawSamples` (rounded down to a power of two), fewer while
    // the run's alignment allows no more (Refinement::lastDrawSamples says what it took).
    //
    // Reference's noise is estimated over the object (FrameAccumulator::noise over objectMask of
    // the first draw's coverage, RenderScene::coverageAlpha) after a pair of draws once
    // min(kNoiseIntervalSeconds, four draws' time) of drawing has passed since the last estimate,
    // and at the end; the refinement is done at its samples or once that estimate is at most
    // kRefinementNoiseTarget, whichever comes first. Its two halves are independent randomised
    // quasi-Monte Carlo runs (their own seeds), so the estimate is the mean's error, not a bound
    // far above it (renderConverged's halves share one run: its estimate is conservative).
    struct Refinement {
        int samples = 0; // per pixel so far, of the run being accumulated
        int target = 0; // per pixel when that run is done (1 for a debug view the samples cannot change)
        // Fis refines in levels (fisRefinementLevels): the last level's samples, the whole
        // estimate, and the complete level on screen meanwhile (0: the split-sum preview).
        int finalTarget = 0;
        int levelShown = 0;
        int draws = 0;
        double seconds = 0.0; // of the draws, glFinish'ed
        double lastDrawMs = 0.0;
        int lastDrawSamples = 0; // the last draw's samples (lastDrawMs is its time, all its bands)
        // A draw that would take longer than refine()'s `sliceMs` is drawn in `bands` bands of
        // rows, one a call; `bandsDrawn` of the draw under way are done (0: none under way).
        int bands = 1;
        int bandsDrawn = 0;
        double drawMs = 0.0; // of the bands of the draw under way so far
        double lastSliceMs = 0.0; // the last call's drawing: a band, or a whole draw
        bool showing
            = false; // the accumulation, not the held frame (split sum, or fis's last level), is on screen
        // Reference: the last noise estimate (relative RMSE of the mean's noise over the object).
        std::optional<double> noise;
        double noiseSeconds = 0.0; // `seconds` when it was made
        bool noiseReached() const { return noise && *noise <= kRefinementNoiseTarget; }
        bool done() const
        {
            return target > 0 && ((samples >= target && target >= finalTarget) || noiseReached());
        }
    };
    // Fis's levels for `samples` points: samples / 4^k for k = K ... 0, the first at least
    // kFisFirstLevel (64; 1024 -> 64, 256, 1024). A level is a complete estimate with its own
    // footprints (a prefix of a run's points is not: it covers part of the lobe), shown when done
    // while the next accumulates; the error falls level by level, and the levels before the last
    // cost at most a third more. docs/ibl.md, "Refining in the window".
    static std::vector<int> fisRefinementLevels(int samples);
    static constexpr int kFisFirstLevel = 64;
    static constexpr int kRefinementShownAfter = 16;
    static constexpr double kRefinementNoiseTarget = 0.01;
    static constexpr double kNoiseIntervalSeconds = 0.5;
    // `slot`: which of several refinements (each its own accumulation and state; the window's view
    // is slot 0, the Compare view's cells and error view others).
    //
    // `sliceMs` > 0 (the window's view): a draw estimated (from the last one's cost per sample and
    // pixel) to take longer is drawn in bands of rows under a scissor, one band a call (at most
    // kMaxBands), and added to the accumulation when its last band is in; what is on screen
    // stays meanwhile. Input then waits for a band, not for a whole draw.
    static constexpr int kMaxBands = 32;
    bool refine(const RenderScene& preview, const RenderScene& scene, unsigned framebuffer,
        const FrameRect& rect, bool restart, int drawSamples, std::string* error, int slot = 0,
        double sliceMs = 0.0);
    // The next band of the draw under way in `slot` (refine() began a draw in bands), drawn and,
    // when it is the last, added to the accumulation as refine() would; nothing is shown: the
    // caller draws bands between frames without presenting (ui/viewport/ViewportWidget) and shows the
    // result with its next refine(). `scene`: the one refine() was given. True (doing nothing)
    // when no draw is under way.
    bool continueDraw(const RenderScene& scene, std::string* error, int slot = 0);
    const Refinement& refinement(int slot = 0) const;
    // The Reference refinement's mean and its per-pixel noise (FrameAccumulator::spread, linear
    // radiance, top row first) as read back for its last noise estimate (Spread::samples says at
    // how many samples; at the end, all of them): what the error view measures against. nullopt
    // before the first estimate, and for Fis.
    const std::optional<FrameAccumulator::Spread>& refinementSpread(int slot = 0) const;
    // Frees the refinements of the slots `keep` says no (their targets and accumulation).
    void dropRefinements(const std::function<bool(int slot)>& keep);

    // The linear radiance (the HDR target as it is: no exposure, no tone mapping) of the frame the
    // last present() or refine() showed (a reduced preview, the refinement's held frame or its
    // mean), at the point (fx, fy) of its rectangle, fractions from the top-left corner; the value
    // picker's reading (ui/viewport/ValuePicker.h). nullopt before any frame, outside [0, 1), or when that
    // target is gone.
    std::optional<glm::vec4> shownRadiance(double fx, double fy) const;

    // The size present() rendered at in its last call.
    int lastRenderWidth() const { return m_lastWidth; }
    int lastRenderHeight() const { return m_lastHeight; }

    // Ends a complete frame (every cell of a grid drawn): deletes the material textures no
    // render since the last call used or requested (TextureCache::evictUnused). Callers that
    // draw a sequence of unrelated images (a contact sheet, a benchmark) need not call it.
    void finishFrame();

    Renderer& renderer() { return *m_renderer; }
    TextureCache& textureCache();
    const std::shared_ptr<TextureCache>& sharedTextureCache() const;
    IblPrecompute& precompute() { return *m_precompute; }
    const std::shared_ptr<IblPrecompute>& sharedPrecompute() const { return m_precompute; }

    // The targets pooled (at most kPooledTargets, least recently used out).
    static constexpr int kPooledTargets = 4;
    int pooledTargets() const { return int(m_targets.size()); }

private:
    // A pooled target of this size and format, made on first use.
    Framebuffer* target(int width, int height, FramebufferFormat format, int slot, std::string* error);
    // `hdr`'s display transform into `rect` of `framebuffer` (directly when it fills it, else
    // through a pooled display target, stretched).
    bool show(const Framebuffer& hdr, const ViewSettings& view, unsigned framebuffer, const FrameRect& rect,
        std::string* error);
    struct ViewRefinement;
    // One call's drawing of a refinement: a band of a draw (all of it when in one band), the draw's
    // completion when it is the last, and a fis level's when that completes it.
    bool drawStep(ViewRefinement& view, const RenderScene& scene, int width, int height, int drawSamples,
        double sliceMs, std::string* error);
    // What a refinement shows after a call: the held frame, or the mean resolved into it.
    bool showRefinement(ViewRefinement& view, const RenderScene& scene, unsigned framebuffer,
        const FrameRect& rect, std::string* error);
    // One draw of a converging method: `draw` rendered into `frame` and added to `accumulator`
    // (its draw.sampling.samples); with draw.coverageAlpha, `coverage` becomes the object's mask.
    bool accumulateDraw(const RenderScene& draw, Framebuffer& frame, FrameAccumulator& accumulator,
        PixelMask& coverage, std::string* error);
    // `hdr` read back as `output`: itself, or its display transform through a pooled target.
    std::optional<Image> readBack(
        Framebuffer& hdr, const RenderScene& scene, FrameOutput output, std::string* error);

    struct PooledTarget {
        int slot = 0; // two targets of one size in one frame (the HDR image and its display copy)
        Framebuffer framebuffer;
    };
    std::shared_ptr<IblPrecompute> m_precompute;
    std::unique_ptr<Renderer> m_renderer;
    std::unique_ptr<FrameAccumulator> m_accumulator;
    std::map<int, std::unique_ptr<ViewRefinement>> m_views; // by slot
    std::list<PooledTarget> m_targets; // most recently used first
    int m_lastWidth = 0;
    int m_lastHeight = 0;
    const Framebuffer* m_shown = nullptr; // what show() last showed (may be gone since: checked)
};

} // namespace facet
