// Includes epoxy (render/'s GL loader) and no Qt GL header: the two must not meet in one file.
#include <epoxy/gl.h>

#include "ui/viewport/ViewportRenderer.h"

#include "ui/widgets/CacheBudget.h"

#include "render/FrameRenderer.h"
#include "render/Renderer.h"
#include "render/SceneFromProject.h"
#include "render/TextureCache.h"
#include "render/TextureFiltering.h"
#include "ui/document/Document.h"
#include "ui/viewport/LightingWorker.h"
#include "ui/viewport/SceneController.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <algorithm>
#include <cmath>
#include <utility>

namespace facet {

namespace {

// The empty viewport's grey (ViewportWidget::kClearGrey), shown when a frame cannot be drawn.
constexpr float kFailureGrey = 0.18f;

} // namespace

QString ViewportFrameStats::summary() const
{
    QString text = QCoreApplication::translate("ViewportRenderer", "%1×%2 · %3 ms")
                       .arg(width)
                       .arg(height)
                       .arg(frameMs, 0, 'f', 0);
    if (reduced)
        text += QCoreApplication::translate("ViewportRenderer", " (preview)");
    if (refineMethod != IblMethod::SplitSum && refinement.target > 0) {
        // "1280×720 · Reference 256/1024 spp · noise 1.8% · 41.2 s (refining)"
        const QString method = refineMethod == IblMethod::Fis
            ? QCoreApplication::translate("ViewportRenderer", "FIS")
            : QCoreApplication::translate("ViewportRenderer", "Reference");
        // Reference's noise estimate, when it has one: "· noise 1.8%".
        const QString noise = refinement.noise
            ? QCoreApplication::translate("ViewportRenderer", " · noise %1%")
                  .arg(*refinement.noise * 100.0, 0, 'f', 2)
            : QString();
        QString state = QCoreApplication::translate("ViewportRenderer", "(refining)");
        // Fis's levels: "FIS 96/256 spp · … (refining; showing 64)".
        if (refinement.levelShown > 0 && !refinement.done())
            state = QCoreApplication::translate("ViewportRenderer", "(refining; showing %1)")
                        .arg(refinement.levelShown);
        if (refinement.noiseReached())
            state = QCoreApplication::translate("ViewportRenderer", "(done: noise under %1%)")
                        .arg(FrameRenderer::kRefinementNoiseTarget * 100.0, 0, 'g', 3);
        else if (refinement.done())
            state = QCoreApplication::translate("ViewportRenderer", "(done)");
        text = QCoreApplication::translate("ViewportRenderer", "%1×%2 · %3 %4/%5 spp%6 · %7 s %8")
                   .arg(width)
                   .arg(height)
                   .arg(method)
                   .arg(refinement.samples)
                   .arg(refinement.target)
                   .arg(noise)
                   .arg(refinement.seconds, 0, 'f', 1)
                   .arg(state);
    }
    // Maps the GPU's texture units could not hold (Renderer::variantKeyFor): shaded by their
    // factors, and said here rather than shown wrong.
    if (render.mapsLeftOut == 1)
        text += QCoreApplication::translate("ViewportRenderer", " · 1 map not shown: too few texture units");
    else if (render.mapsLeftOut > 1)
        text += QCoreApplication::translate("ViewportRenderer", " · %1 maps not shown: too few texture units")
                    .arg(render.mapsLeftOut);
    return text;
}

ViewportRenderer::ViewportRenderer(const QString& cacheDirectory)
    : m_frames(std::make_unique<FrameRenderer>(cacheDirectory))
    , m_glInfo(queryCurrentGLInfo())
{
}

ViewportRenderer::ViewportRenderer(
    std::shared_ptr<IblPrecompute> precompute, std::shared_ptr<TextureCache> textures)
    : m_frames(std::make_unique<FrameRenderer>(std::move(precompute), std::move(textures)))
    , m_glInfo(queryCurrentGLInfo())
{
}

ViewportRenderer::~ViewportRenderer()
{
    // GL objects go while the caller holds the context current: textures first, then their makers.
    if (m_lighting && m_pending)
        m_lighting->cancel();
    m_lighting.reset();
    m_ibl.reset();
    m_frames.reset();
}

void ViewportRenderer::setLightingWorker(std::shared_ptr<LightingWorker> worker)
{
    if (m_lighting && m_pending)
        m_lighting->cancel();
    m_pending.reset();
    m_lighting = std::move(worker);
}

std::optional<std::uint64_t> ViewportRenderer::pendingLighting() const
{
    if (m_pending && !m_pending->finished)
        return m_pending->cacheKey;
    return std::nullopt;
}

bool ViewportRenderer::lightingFinished(std::uint64_t key)
{
    if (!m_lighting)
        return false;
    std::optional<LightingWorker::Result> result = m_lighting->take(key);
    if (result && result->textures)
        m_frames->precompute().adopt(key, result->textures);
    if (!m_pending || m_pending->cacheKey != key || m_pending->finished)
        return false;
    if (!result) {
        // Another view took it first: it is in the shared precompute's memory.
        m_pending->finished = true;
        return true;
    }
    if (result->stats.cancelled) {
        // Superseded by another request. When the set is not asked for again behind it, this
        // view asks anew at its next frame.
        if (m_lighting->busyWith() == key)
            return false;
        m_pending.reset();
        return true;
    }
    m_pending->finished = true;
    m_pending->stats = result->stats;
    if (!result->textures)
        m_pending->error = result->error;
    return true;
}

bool ViewportRenderer::needsIbl(const SceneController& scene) const
{
    return m_iblKey != scene.iblKey();
}

std::optional<Image> ViewportRenderer::renderStill(const SceneController& scene, int width, int height,
    FrameOutput output, std::string* error, const StillOptions& options)
{
    if (m_iblKey != scene.iblKey() || !m_ibl) {
        std::string problem;
        std::shared_ptr<const IblTextures> ibl
            = m_frames->lighting(scene.assets().environment, scene.iblSettings(), nullptr, &problem);
        if (!ibl) {
            *error = problem;
            return std::nullopt;
        }
        m_iblKey = scene.iblKey();
        m_iblError.clear();
        m_ibl = std::move(ibl);
        if (m_pending && m_lighting)
            m_lighting->cancel(); // made here: the worker's is not wanted
        m_pending.reset();
    }
    // The scene the view refines (its method converged), turned and made transparent as asked.
    std::optional<RenderScene> sampled = refinementScene(scene, error);
    if (!sampled)
        return std::nullopt;
    RenderScene& frame = *sampled;
    applyTurntable(frame, options.turntableSubject, options.turntableDegrees);
    if (options.transparent)
        frame.view.background = BackgroundMode::Transparent;
    while (frame.view.msaaSamples > 1
        && (long long)width * height * frame.view.msaaSamples > kMaxStillMsaaSamplePixels)
        frame.view.msaaSamples /= 2;
    const IblMethod method = scene.refinementMethod();
    const EnvironmentSettings& environment = scene.document()->project().environment;
    const int samples = environment.samples > 0 ? environment.samples : defaultIblSamples(method);
    std::optional<Image> image = m_frames->renderConverged(frame, width, height, output, samples, error);
    m_frames->finishFrame();
    return image;
}

bool ViewportRenderer::paint(const SceneController& scene, unsigned targetFramebuffer, int width, int height,
    double scale, std::string* error)
{
    return draw(scene, targetFramebuffer, width, height, scale, nullptr, error);
}

ViewportRenderer::RefineKey ViewportRenderer::refineKeyOf(
    const SceneController& scene, int width, int height) const
{
    RefineKey key;
    key.project = withoutDisplaySettings(scene.document()->project());
    key.method = scene.refinementMethod();
    const ProjectAssets& assets = scene.assets();
    if (!assets.environment.isEmpty())
        key.environment = assets.environment.contentHash();
    key.environmentRotation = assets.environment.rotationDegrees();
    key.environmentIntensity = assets.environment.intensity();
    key.mesh = assets.mesh.get();
    for (const auto& material : assets.maps)
        for (const LoadedMapImage& map : material)
            key.maps.push_back(map.image.get());
    key.view = m_view;
    key.width = width;
    key.height = height;
    return key;
}

bool ViewportRenderer::refinesSameSamples(const SceneController& scene, int width, int height) const
{
    return m_stats.refineMethod != IblMethod::SplitSum && m_refineKey
        && *m_refineKey == refineKeyOf(scene, width, height);
}

bool ViewportRenderer::refine(const SceneController& scene, unsigned targetFramebuffer, int width, int height,
    bool restart, std::string* error)
{
    RefineKey key = refineKeyOf(scene, width, height);
    restart = restart || !m_refineKey || *m_refineKey != key;
    m_refineKey = std::move(key);
    return draw(scene, targetFramebuffer, width, height, 1.0, &restart, error);
}

int ViewportRenderer::nextDrawSamples(int samples, double milliseconds, double budgetMs)
{
    if (!(milliseconds > 0.0))
        return std::max(samples, 1);
    // A power of two near what fits the budget, changing by at most 4x a draw (a draw that
    // caught a busy moment does not swing the next far).
    const double fit = std::clamp(double(std::max(samples, 1)) * budgetMs / milliseconds,
        double(std::max(samples, 1)) / 4.0, double(std::max(samples, 1)) * 4.0);
    int next = 1;
    while (next * 2 <= fit && next < FrameRenderer::kSamplesPerDraw)
        next *= 2;
    return next;
}

bool ViewportRenderer::draw(const SceneController& scene, unsigned targetFramebuffer, int width, int height,
    double scale, const bool* refineRestart, std::string* error)
{
    QElapsedTimer clock;
    clock.start();
    m_stats.iblMs = 0.0;
    // The empty viewport's grey: a frame that failed, or one with no lighting yet.
    const auto clearToGrey = [&] {
        glBindFramebuffer(GL_FRAMEBUFFER, targetFramebuffer);
        glViewport(0, 0, width, height);
        glClearColor(kFailureGrey, kFailureGrey, kFailureGrey, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    };
    const auto fail = [&](const std::string& problem) {
        *error = "ViewportRenderer::paint: " + problem;
        clearToGrey();
        return false;
    };

    // The user's budget for the environments shown before (a change applies at the next frame).
    IblPrecompute& precompute = m_frames->precompute();
    precompute.setMemoryBudget(CacheBudget::bytes());
    bool iblPrepared = false;
    double iblMsHere = 0.0; // of this frame's own time (not the worker's)
    m_stats.lightingPending = false;
    if (m_iblKey != scene.iblKey()) {
        // A new environment or quality: its IBL set from memory at once; otherwise from the
        // worker (disk or passes, on its thread) while this view draws what it has, or, without
        // a worker, fetched or computed here.
        const Environment& environment = scene.assets().environment;
        const IblSettings settings = scene.iblSettings();
        const bool inMemory = !environment.isEmpty() && precompute.holds(environment, settings);
        const std::uint64_t cacheKey
            = environment.isEmpty() ? 0 : IblPrecompute::cacheKey(environment, settings);
        const bool failed = m_pending && m_pending->cacheKey == cacheKey && m_pending->finished
            && !m_pending->error.empty();
        if (m_lighting && !environment.isEmpty() && !inMemory && !failed) {
            if (!m_pending || m_pending->cacheKey != cacheKey || m_pending->finished) {
                m_pending = PendingLighting {};
                m_pending->cacheKey = m_lighting->request(environment, settings);
            }
            m_stats.lightingPending = true;
        } else {
            // A set of the worker's (adopted) or failed there, a memory hit, or no worker.
            std::optional<PendingLighting> arrived;
            if (m_pending && m_pending->cacheKey == cacheKey && m_pending->finished)
                arrived = std::move(m_pending);
            else if (m_pending && m_lighting)
                m_lighting->cancel(); // back to a set in memory: the one asked for is not wanted
            m_pending.reset();
            m_iblKey = scene.iblKey();
            m_iblError.clear();
            std::string problem;
            IblStats iblStats;
            std::shared_ptr<const IblTextures> ibl;
            if (failed)
                problem = arrived->error;
            else
                ibl = m_frames->lighting(environment, settings, &iblStats, &problem);
            iblMsHere = iblStats.msTotal;
            if (arrived)
                iblStats = arrived->stats; // what the worker did for it
            m_stats.ibl = iblStats;
            m_stats.iblMs = iblStats.msTotal;
            iblPrepared = true;
            if (ibl)
                m_ibl = std::move(ibl);
            else
                m_iblError = problem;
        }
    }
    if (!m_iblError.empty() && !m_ibl)
        return fail(m_iblError);
    if (!m_ibl && m_stats.lightingPending) {
        // Nothing to light with yet: the empty grey until the worker's set arrives.
        clearToGrey();
        m_stats.width = width;
        m_stats.height = height;
        m_stats.frameMs = double(clock.nsecsElapsed()) / 1e6;
        return true;
    }

    std::string problem;
    // The split-sum table of the material's visibility term: a memory hit in IblPrecompute after
    // the first frame that needed it; a BRDF switch loads or makes one table, nothing else.
    IblStats dfgStats;
    std::optional<RenderScene> preview = m_frames->prepare(scene.document()->project(), scene.assets(),
        scene.iblSettings(), m_view.appliedTo(scene.sceneOptions()), &dfgStats, &problem, m_ibl);
    if (!preview)
        return fail(problem);
    RenderScene& frame = *preview;
    // Maps: complete textures only (uploads happen between frames), filtered for this GL and
    // this kind of frame.
    m_stats.mapsHeldBack = holdBackUnreadyMaps(frame, &m_stats.textureProblem);
    // While a texture set loads (files decoding, textures uploading) the frames are previews:
    // they only show progress, and a full frame on llvmpipe would stall the window for longer
    // than the whole upload. The frame after the last map is up is a full one.
    m_stats.loadingMaps = scene.pendingMapLoads() > 0 || m_frames->textureCache().hasPendingUploads();
    if (m_stats.loadingMaps)
        scale = std::min(scale, kLoadingScale);

    scale = std::clamp(scale, 0.05, 1.0);
    const bool reduced = scale < 1.0;
    m_stats.anisotropy = TextureFiltering::anisotropyFor(m_glInfo, reduced);
    m_frames->textureCache().setMaxAnisotropy(m_stats.anisotropy);
    if (dfgStats.passesRun > 0 || dfgStats.cacheHitsDisk > 0 || dfgStats.dfgShipped > 0) {
        m_stats.iblMs += dfgStats.msTotal;
        iblMsHere += dfgStats.msTotal;
        if (!iblPrepared)
            m_stats.ibl = IblStats {};
        m_stats.ibl.passesRun += dfgStats.passesRun;
        m_stats.ibl.cacheHitsDisk += dfgStats.cacheHitsDisk;
        m_stats.ibl.dfgShipped += dfgStats.dfgShipped;
        m_stats.ibl.msDfg += dfgStats.msDfg;
        m_stats.ibl.msTotal += dfgStats.msTotal;
    }
    if (refineRestart) {
        // The still frame, refined by the project's method; `frame` (the split sum) is shown
        // until the accumulation is worth showing.
        std::optional<RenderScene> sampledScene = refinementScene(scene, &problem);
        if (!sampledScene)
            return fail(problem);
        const RenderScene& sampled = *sampledScene;
        if (*refineRestart)
            m_drawSamples = 1;
        if (!m_frames->refine(frame, sampled, targetFramebuffer, FrameRect {0, 0, width, height},
                *refineRestart, m_drawSamples, &problem, 0, kRefineSliceMs))
            return fail(problem);
        const FrameRenderer::Refinement& refinement = m_frames->refinement();
        if (!*refineRestart && refinement.draws > 0)
            m_drawSamples
                = nextDrawSamples(refinement.lastDrawSamples, refinement.lastDrawMs, kRefineBandedDrawMs);
        m_stats.refineMethod = sampled.sampling.method;
        m_stats.refinement = refinement;
    } else {
        if (!m_frames->present(frame, targetFramebuffer, FrameRect {0, 0, width, height}, scale, &problem))
            return fail(problem);
        m_stats.refineMethod = IblMethod::SplitSum;
        m_stats.refinement = {};
    }
    // The textures this frame neither drew nor queued go (another material's, a replaced file's).
    m_frames->finishFrame();
    const int renderWidth = m_frames->lastRenderWidth();
    const int renderHeight = m_frames->lastRenderHeight();
    // Honest frame times: wait for the GPU (llvmpipe renders on the CPU anyway).
    glFinish();

    ++m_stats.frameNumber;
    m_stats.width = renderWidth;
    m_stats.height = renderHeight;
    m_stats.reduced = reduced;
    m_stats.frameMs = double(clock.nsecsElapsed()) / 1e6 - iblMsHere;
    m_stats.render = m_frames->renderer().lastFrameStats();
    m_stats.iblCacheEntries = int(precompute.memoryEntries() + precompute.sourceEntries());
    m_stats.iblCacheBytes = precompute.memoryBytes();
    return true;
}

ViewportRenderer::ShownPixel ViewportRenderer::shownPixel(
    unsigned targetFramebuffer, int width, int height, int x, int y) const
{
    ShownPixel pixel;
    if (width <= 0 || height <= 0 || x < 0 || y < 0 || x >= width || y >= height)
        return pixel;
    // The shown frame may be smaller than the view (a preview stretched over it): the same point.
    pixel.radiance = m_frames->shownRadiance((double(x) + 0.5) / width, (double(y) + 0.5) / height);
    pixel.display = readDisplayPixel(targetFramebuffer, x, height - 1 - y);
    return pixel;
}

std::optional<RenderScene> ViewportRenderer::refinementScene(const SceneController& scene, std::string* error)
{
    std::optional<RenderScene> sampled
        = m_frames->prepare(scene.document()->project(), scene.assets(), scene.iblSettings(),
            m_view.appliedTo(scene.sceneOptions(scene.refinementMethod())), nullptr, error, m_ibl);
    if (!sampled)
        return std::nullopt;
    std::string ignored;
    holdBackUnreadyMaps(*sampled, &ignored);
    return sampled;
}

bool ViewportRenderer::continueRefinement(
    const SceneController& scene, int width, int height, std::string* error)
{
    // Only the draw the last refine() began, of the scene as it was: after any change the next
    // refine() starts again.
    if (!m_ibl || !m_refineKey || *m_refineKey != refineKeyOf(scene, width, height)
        || m_frames->refinement().bandsDrawn == 0)
        return false;
    std::optional<RenderScene> sampled = refinementScene(scene, error);
    if (!sampled || !m_frames->continueDraw(*sampled, error))
        return false;
    glFinish();
    m_stats.refinement = m_frames->refinement();
    return m_stats.refinement.bandsDrawn > 0;
}

int ViewportRenderer::holdBackUnreadyMaps(RenderScene& frame, std::string* problem)
{
    TextureCache& textures = m_frames->textureCache();
    problem->clear();
    int heldBack = 0;
    for (RenderMaterial& material : frame.materials)
        for (MapSlot slot : kAllMapSlots) {
            RenderMapImage& map = material.maps[std::size_t(slot)];
            if (!map.image || map.image->isEmpty())
                continue;
            const MaterialMap& settings = material.material.map(slot);
            const std::string& path = map.path.empty() ? settings.path : map.path;
            if (textures.isReady(path, map.timestamp, settings.colorSpace)) {
                textures.request(map.image, path, map.timestamp, settings.colorSpace); // kept: in use
                continue;
            }
            ++heldBack;
            if (!map.image->hasPixels()) {
                // Released once on the GPU, and its texture is gone (a new context, another
                // colour space): the file must be decoded again (SceneController::reloadMaps).
                if (std::find(m_releasedMapsNeeded.begin(), m_releasedMapsNeeded.end(), path)
                    == m_releasedMapsNeeded.end())
                    m_releasedMapsNeeded.push_back(path);
            } else if (!textures.request(map.image, path, map.timestamp, settings.colorSpace)) {
                *problem = textures.problem();
            }
            // The previous version of a file that is being reloaded, else the factor alone.
            if (const auto previous = textures.readyTimestamp(path, settings.colorSpace)) {
                map.timestamp = *previous;
                textures.request(map.image, path, map.timestamp, settings.colorSpace);
            } else {
                map = RenderMapImage {};
            }
        }
    return heldBack;
}

int ViewportRenderer::queueUploads(const SceneController& scene)
{
    // Only the maps are read: the scene without its tables (render/SceneFromProject.h).
    RenderScene frame = sceneFromProject(
        scene.document()->project(), scene.assets(), m_ibl, m_view.appliedTo(scene.sceneOptions()));
    std::string problem;
    return holdBackUnreadyMaps(frame, &problem);
}

std::vector<std::string> ViewportRenderer::takeReleasedMapsNeeded()
{
    return std::exchange(m_releasedMapsNeeded, {});
}

bool ViewportRenderer::textureReady(
    const std::string& path, std::int64_t timestamp, ColorEncoding colorSpace) const
{
    return m_frames->textureCache().isReady(path, timestamp, colorSpace);
}

bool ViewportRenderer::hasPendingUploads() const
{
    return m_frames->textureCache().hasPendingUploads();
}

ViewportRenderer::UploadProgress ViewportRenderer::uploadSlice(double budgetMs)
{
    TextureCache& textures = m_frames->textureCache();
    const TextureCache::SliceResult slice = textures.uploadSlice(budgetMs);
    return UploadProgress {slice.completed, textures.pendingUploads(), slice.milliseconds};
}

} // namespace facet
