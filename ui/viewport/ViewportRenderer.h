#pragma once
// The GPU side of the viewport (not a widget): the view's state around a render::FrameRenderer
// (which owns the IBL results, the surface renderer and the targets in the viewport's GL
// context), drawing the SceneController's snapshot into the widget's framebuffer. It runs the IBL precompute
// only when SceneController::iblKey() changed (a new environment image or quality; the disk cache makes a
// second start fast), fetches the split-sum DFG table of the material's visibility term when the frame needs
// one it has not made yet (IblPrecompute caches them per variant), and otherwise only renders. At a scale
// below 1 it renders and tone-maps a smaller image and stretches it onto the widget (the
// interactive preview; llvmpipe's cost is per pixel).
//
// Material maps are uploaded between frames, not in them: a frame draws only complete textures
// (a map still uploading shows the previous version of its file, or its factor alone) and queues
// the rest; uploadSlice() uploads rows of the queued ones for a bounded time, so a 2K texture set
// never stalls the window for a whole upload (render/TextureCache.h). Anisotropic filtering is
// chosen per frame from the GL implementation (render/TextureFiltering.h: none on a software
// rasteriser at reduced resolution). While maps load, frames are reduced-resolution previews
// (kLoadingScale); the frame after the last map is complete is a full one.
//
// With a lighting worker (setLightingWorker, ui/viewport/LightingWorker.h), an environment whose IBL set
// is not in memory is precomputed (or read from the disk cache) on the worker's thread: frames
// meanwhile show the lighting the view had (lastFrame().lightingPending), or the empty grey when
// it had none, and the frame after lightingFinished() adopted the set shows it. A request for
// another environment cancels the one running; going back to a set in memory cancels it too.
//
// Every call needs the viewport's context current; destroy it with the context current.

#include "core/image/Image.h"
#include "core/project/Project.h"
#include "render/FrameRenderer.h"
#include "render/GLInfo.h"
#include "render/IblPrecompute.h"
#include "render/RenderStats.h"
#include "render/Turntable.h"
#include "ui/viewport/ViewState.h"

#include <glm/ext/vector_uint4_sized.hpp>
#include <glm/vec4.hpp>

#include <QString>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace facet {

class FrameRenderer;
class LightingWorker;
class TextureCache;
class SceneController;
struct RenderScene;

// What the last frame cost, for the status bar and the View dock.
// What a still adds to the view's scene (File > Save Image, Save Turntable).
struct StillOptions {
    bool transparent = false; // the background's pixels alpha 0 (BackgroundMode::Transparent)
    TurntableSubject turntableSubject = TurntableSubject::Object;
    double turntableDegrees = 0.0;
};
// The most MSAA samples a still's colour target holds (4096 x 4096 at 4x): larger stills get
// fewer samples a pixel (an 8192 x 8192 one: 1).
inline constexpr long long kMaxStillMsaaSamplePixels = 4096LL * 4096LL * 4LL;
// The largest still, pixels a side.
inline constexpr int kMaxStillSide = 8192;

struct ViewportFrameStats {
    std::uint64_t frameNumber = 0; // frames drawn since the renderer was made (1 = the first)
    int width = 0; // rendered size in device pixels (smaller than the widget when reduced)
    int height = 0;
    bool reduced = false; // drawn at reduced resolution (an interaction is running)
    double frameMs = 0.0; // render + tone map + present, GPU finished (glFinish)
    double iblMs = 0.0; // the IBL precompute this frame ran (0: cached / not needed)
    int mapsHeldBack = 0; // maps drawn without their texture (or with its previous version): uploading
    bool loadingMaps = false; // map files were decoding or textures uploading: a preview
    float anisotropy = 1.0f; // the maps' maximum anisotropy in this frame
    std::string textureProblem; // a map that cannot be a texture on this GL (named), else empty
    // The environment's IBL set is being made on the lighting worker: the frame shows the view's
    // previous lighting (or the empty grey, before any).
    bool lightingPending = false;
    IblStats ibl; // of the last precompute (kept until the next one)
    // The shared IBL memory cache after this frame (ui/widgets/CacheBudget.h): its sets and environment
    // sources, and their GPU bytes.
    int iblCacheEntries = 0;
    std::size_t iblCacheBytes = 0;
    RenderStats render; // Renderer::lastFrameStats()
    // A refinement frame (ViewportRenderer::refine): the method and where it stands; SplitSum
    // and empty for a plain frame.
    IblMethod refineMethod = IblMethod::SplitSum;
    FrameRenderer::Refinement refinement;

    // "1280×720 · 112 ms" (+ " (preview)" when reduced); while refining
    // "1280×720 · Reference 256/1024 spp · 41.2 s (refining)", then "(done)".
    QString summary() const;
};

class ViewportRenderer {
public:
    // The resolution scale of frames drawn while a texture set loads (ViewportWidget's preview's).
    static constexpr double kLoadingScale = 0.5;

    // Needs the context current. `cacheDirectory` empty: the IBL disk cache's default folder.
    explicit ViewportRenderer(const QString& cacheDirectory = {});
    // Draws with the IBL results and material textures of the window's other views
    // (ui/viewport/ViewShareGroup), in a context sharing with theirs.
    ViewportRenderer(std::shared_ptr<IblPrecompute> precompute, std::shared_ptr<TextureCache> textures);
    ~ViewportRenderer();
    ViewportRenderer(const ViewportRenderer&) = delete;
    ViewportRenderer& operator=(const ViewportRenderer&) = delete;

    // A still of `scene` at width x height, read back (File > Save Image): the project's IBL
    // method converged to its samples (renderConverged: the split sum in one draw, fis and the
    // reference in draws of up to 64 samples), as `output` (linear radiance for an EXR, the
    // display transform for a PNG). Call with the context current, after the view has drawn the
    // scene (its maps are on the GPU). nullopt with *error.
    // `options`: the background transparent (alpha 0 there), a turntable's turn on top of the
    // view's own (render/Turntable.h). Above 4096x4096 pixels MSAA is lowered (a 8192x8192 frame
    // at 4x would take 3 GiB): kMaxStillMsaaSamplePixels samples in all.
    std::optional<Image> renderStill(const SceneController& scene, int width, int height, FrameOutput output,
        std::string* error, const StillOptions& options = {});

    // Whether the view does not show the lighting of the scene's environment and quality yet
    // (the next paint() precomputes it, or asks the worker; the caller may say so first).
    bool needsIbl(const SceneController& scene) const;

    // The view's turntable and wireframe (ViewportWidget's), added to every frame, refinement and
    // still from now on.
    void setViewState(const ViewState& view) { m_view = view; }

    // Precompute new lighting on `worker`'s thread from now on (null: on this thread, in paint()).
    void setLightingWorker(std::shared_ptr<LightingWorker> worker);
    const std::shared_ptr<LightingWorker>& lightingWorker() const { return m_lighting; }
    // The worker finished the set `key` (LightingWorker::finished): taken and put into the
    // shared precompute's memory (IblPrecompute::adopt) if no view took it before. True when it
    // is the set this view waits for (succeeded or failed): draw again. Context current.
    bool lightingFinished(std::uint64_t key);
    // The cache key of the set this view waits for from the worker, if any.
    std::optional<std::uint64_t> pendingLighting() const;

    // Draws `scene` into `targetFramebuffer` (width x height device pixels) at `scale` in (0, 1]
    // of the resolution. False with *error ("ViewportRenderer::paint: ...") when the frame could
    // not be drawn; the target is then cleared to the empty viewport's grey.
    bool paint(const SceneController& scene, unsigned targetFramebuffer, int width, int height, double scale,
        std::string* error);

    // One step of the still frame's refinement by the project's IBL method
    // (SceneController::refinementMethod, Fis or Reference; FrameRenderer::refine): `restart`
    // (after any change of the scene) draws and shows the split-sum frame and starts an empty
    // accumulation; each later call adds one draw of samples sized to kRefineDrawBudgetMs and
    // shows the mean once it has FrameRenderer::kRefinementShownAfter samples.
    // lastFrame().refinement says where it stands; once done() a call only shows it again.
    // It also starts again, whatever `restart` says, when what it sums changed since the last
    // call (the refinement key: the project withoutDisplaySettings, the assets, the turntable,
    // the size); a change of how it is shown only (exposure, tone mapper, OCIO, names) keeps
    // the samples and shows them anew.
    bool refine(const SceneController& scene, unsigned targetFramebuffer, int width, int height, bool restart,
        std::string* error);
    // The next band of the refinement draw under way (refine() began it in bands: one a call of
    // about kRefineSliceMs), drawn without presenting anything; the widget calls it between
    // frames, so that input is answered between bands and nothing is tone-mapped or composed for
    // a band. True while more bands of that draw remain; false when it is complete (the next
    // refine() shows it), when there is none, or when the scene changed since (the next refine()
    // starts again), or on failure (*error). Context current.
    bool continueRefinement(const SceneController& scene, int width, int height, std::string* error);
    // Whether the refinement shown sums what `scene` at width x height would: a change since was
    // display-only, and refine() without restarting shows it (the widget then skips previews).
    bool refinesSameSamples(const SceneController& scene, int width, int height) const;
    // What one refinement draw may take, so input events run between draws (llvmpipe: a
    // reference sample over a 720p view costs about 0.2 s, so draws there are 1 sample).
    static constexpr double kRefineDrawBudgetMs = 100.0;
    // The single view draws in bands of rows (FrameRenderer::refine's sliceMs) of about
    // kRefineSliceMs each, the first in a paint and the others between frames with nothing
    // presented (continueRefinement): a key press waits for a band, or for the first band, the
    // tone map and Qt's present of a paint, under 100 ms in all. Its draws are sized to
    // kRefineBandedDrawMs: a paint (tone map, present) a draw, the rest drawing.
    static constexpr double kRefineSliceMs = 25.0;
    static constexpr double kRefineBandedDrawMs = 200.0;
    // The samples of the next draw after one of `samples` took `milliseconds`: a power of two,
    // from 1 to FrameRenderer::kSamplesPerDraw, near `budgetMs`, at most 4x up or down.
    static int nextDrawSamples(int samples, double milliseconds, double budgetMs);

    const ViewportFrameStats& lastFrame() const { return m_stats; }

    // What the view shows at device pixel (x, y from the top) of the `width` x `height`
    // framebuffer it draws into (the value picker, ui/viewport/ValuePicker.h): the linear radiance of the
    // frame shown there (FrameRenderer::shownRadiance: scene-referred, before exposure) and the
    // 8-bit value on screen (after exposure, tone mapping and the display encoding). Either is
    // nullopt when it cannot be read (no frame yet, a still rendered since). Context current.
    struct ShownPixel {
        std::optional<glm::vec4> radiance;
        std::optional<glm::u8vec4> display;
    };
    ShownPixel shownPixel(unsigned targetFramebuffer, int width, int height, int x, int y) const;

    // Map uploads queued by frames (or queueUploads) and not finished yet.
    bool hasPendingUploads() const;
    // Queues the uploads the scene's maps need, without drawing (context current); returns how
    // many maps are not on the GPU yet.
    int queueUploads(const SceneController& scene);
    // Uploads rows of the queued maps for about `budgetMs` (context current). `completed` > 0:
    // a map is complete, and the next frame shows it.
    struct UploadProgress {
        int completed = 0;
        int pending = 0;
        double milliseconds = 0.0;
    };
    UploadProgress uploadSlice(double budgetMs);

    // Whether the texture of a map file (as the scene keys it) is complete on the GPU
    // (SceneController::releaseMapPixels asks before it frees a decoded copy).
    bool textureReady(const std::string& path, std::int64_t timestamp, ColorEncoding colorSpace) const;
    // The maps whose decoded pixels were released and whose textures frames since the last call
    // needed and did not find (a new GL context, another colour space): to be decoded again
    // (SceneController::reloadMaps).
    std::vector<std::string> takeReleasedMapsNeeded();

private:
    // paint() (refineRestart null) or refine().
    bool draw(const SceneController& scene, unsigned targetFramebuffer, int width, int height, double scale,
        const bool* refineRestart, std::string* error);
    // The scene the refinement samples (and a still converges): the project's method, complete
    // textures only, with the DFG tables and the environment's source. nullopt with *error.
    std::optional<RenderScene> refinementScene(const SceneController& scene, std::string* error);
    // Takes out of `frame` the maps whose textures are not complete (the previous version of the
    // file where there is one) and queues their uploads; returns how many were held back.
    int holdBackUnreadyMaps(RenderScene& frame, std::string* problem);

    std::unique_ptr<FrameRenderer> m_frames;
    std::shared_ptr<const IblTextures> m_ibl;
    std::optional<std::uint64_t> m_iblKey; // SceneController::iblKey() of m_ibl
    std::string m_iblError; // the precompute failed for this key: do not retry every frame
    std::shared_ptr<LightingWorker> m_lighting;
    // What the view asked of the worker and, once it finished, how that went.
    struct PendingLighting {
        std::uint64_t cacheKey = 0;
        bool finished = false;
        IblStats stats;
        std::string error; // failed (not cancelled)
    };
    std::optional<PendingLighting> m_pending;
    ViewportFrameStats m_stats;
    GLInfo m_glInfo;
    std::vector<std::string> m_releasedMapsNeeded;
    int m_drawSamples = 1; // of the next refinement draw
    // What the refinement sums (refine()'s key).
    struct RefineKey {
        Project project;
        IblMethod method = IblMethod::SplitSum;
        std::uint64_t environment = 0; // content hash
        double environmentRotation = 0.0;
        double environmentIntensity = 1.0;
        const void* mesh = nullptr;
        std::vector<const void*> maps;
        ViewState view;
        int width = 0;
        int height = 0;
        bool operator==(const RefineKey&) const = default;
    };
    RefineKey refineKeyOf(const SceneController& scene, int width, int height) const;
    ViewState m_view;
    std::optional<RefineKey> m_refineKey;
};

} // namespace facet
