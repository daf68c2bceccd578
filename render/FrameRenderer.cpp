#include "render/FrameRenderer.h"

#include <epoxy/gl.h>

#include "core/project/ProjectAssets.h"
#include "core/shading/Sampling.h"
#include "render/FrameAccumulator.h"
#include "render/IblSettings.h"
#include "render/Renderer.h"
#include "render/TextureCache.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

namespace facet {

namespace {
using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Draw `index`'s sub-pixel offset: the Halton (2, 3) point index / 2 + 1 about the pixel's centre
// (+ 1: point 0 is the corner), none in the reference view (pixel centres) or for a view the
// samples do not change (one draw). Draws come in pairs at one offset, one to each of the
// accumulator's halves (which take alternate draws), so that the halves see the same offsets and
// their difference, the noise estimate, is the sampling noise alone: with an offset of its own
// per draw, each half was a different average over the pixel, and a mesh's inner edges (an ear in
// front of a head) read as noise that no number of samples takes away (20% at 256 samples on
// Suzanne in the window, against 6% for `facet render`'s four draws).
// Whether the scene's debug view shows light the samples integrate (not base colour, normals, ...).
bool showsIntegratedLight(const RenderScene& scene)
{
    return debugViewShowsIntegratedLight(scene.view.debugView);
}

glm::dvec2 jitterOf(const RenderScene& scene, int index)
{
    if (scene.pixelCentres || !showsIntegratedLight(scene))
        return glm::dvec2(0.0);
    return sampling::halton23(std::uint32_t(index / 2) + 1u) - glm::dvec2(0.5);
}
// The seed of the second half of a refinement's Reference draws (FrameRenderer::refine): an
// independent run beside the first's.
constexpr std::uint32_t kSecondHalfSeed = 0x9e3779b9u;

// The object in a draw made with RenderScene::coverageAlpha (core/image/ImageMetrics objectMask); empty
// (every pixel) when nothing is covered whole.
PixelMask coverageMaskOf(const Framebuffer& frame)
{
    PixelMask mask = objectMask(frame.readPixels());
    if (std::find(mask.begin(), mask.end(), std::uint8_t(1)) == mask.end())
        mask.clear();
    return mask;
}

} // namespace

FrameRenderer::FrameRenderer(const QString& cacheDirectory, bool useDiskCache)
    : FrameRenderer(std::make_shared<IblPrecompute>(cacheDirectory, useDiskCache))
{
}

FrameRenderer::FrameRenderer(
    std::shared_ptr<IblPrecompute> precompute, std::shared_ptr<TextureCache> textures)
    : m_precompute(std::move(precompute))
    , m_renderer(std::make_unique<Renderer>(std::move(textures)))
{
}

// A view's refinement: its own accumulator and targets, so a grid's or a command's renders in
// the same FrameRenderer never disturb it.
struct FrameRenderer::ViewRefinement {
    FrameAccumulator accumulator;
    std::optional<Framebuffer> frame; // RGBA32F: one draw, then the resolved mean
    std::optional<Framebuffer> held;  // RGBA16F: the split-sum frame shown until the mean is
    Refinement state;
    // What a sample of a pixel cost in the last complete draw (ms), to size the next draw's bands;
    // kept across restarts (0: not known yet).
    double msPerSamplePixel = 0.0;
    PixelMask mask; // the object, for the noise estimate (Reference)
    // The accumulation read back for the last noise estimate (refinementSpread hands it out, so
    // nothing reads the halves back twice).
    std::optional<FrameAccumulator::Spread> spread;
};

FrameRenderer::~FrameRenderer()
{
    // GL objects go while the caller holds the context current: targets and the renderer's
    // objects first, then the precompute (when this was its last holder).
    m_targets.clear();
    m_accumulator.reset();
    m_views.clear();
    m_renderer.reset();
    m_precompute.reset();
}

TextureCache& FrameRenderer::textureCache()
{
    return m_renderer->textureCache();
}

const std::shared_ptr<TextureCache>& FrameRenderer::sharedTextureCache() const
{
    return m_renderer->sharedTextureCache();
}

void FrameRenderer::finishFrame()
{
    m_renderer->textureCache().evictUnused();
}

std::shared_ptr<const IblTextures> FrameRenderer::lighting(
    const Environment& environment, const IblSettings& settings, IblStats* stats, std::string* error)
{
    return m_precompute->prepare(environment, settings, stats, error);
}

std::optional<RenderScene> FrameRenderer::prepare(const Project& project, const ProjectAssets& assets,
    const IblSettings& settings, const SceneOptions& options, IblStats* stats, std::string* error,
    std::shared_ptr<const IblTextures> ibl)
{
    if (!ibl)
        ibl = lighting(assets.environment, settings, stats, error);
    if (!ibl)
        return std::nullopt;
    RenderScene scene = sceneFromProject(project, assets, ibl, options);
    if (!addDfgTables(*m_precompute, settings, scene, stats, error))
        return std::nullopt;
    if (scene.sampling.method != IblMethod::SplitSum) {
        const auto source = m_precompute->source(assets.environment, stats, error);
        if (!source)
            return std::nullopt;
        scene.environment.setSource(source);
    }
    return scene;
}

Framebuffer* FrameRenderer::target(
    int width, int height, FramebufferFormat format, int slot, std::string* error)
{
    for (auto it = m_targets.begin(); it != m_targets.end(); ++it) {
        const Framebuffer& f = it->framebuffer;
        if (it->slot == slot && f.width() == width && f.height() == height && f.format() == format) {
            m_targets.splice(m_targets.begin(), m_targets, it);
            return &m_targets.front().framebuffer;
        }
    }
    std::optional<Framebuffer> made = Framebuffer::create(width, height, format, error);
    if (!made)
        return nullptr;
    m_targets.push_front(PooledTarget {slot, std::move(*made)});
    // A resized window leaves its old sizes behind: keep the few most recent (a grid's cells,
    // the HDR image and its display copy).
    while (m_targets.size() > std::size_t(kPooledTargets))
        m_targets.pop_back();
    return &m_targets.front().framebuffer;
}

std::optional<Image> FrameRenderer::renderImage(const RenderScene& scene, int width, int height,
    FrameOutput output, std::string* error, FramebufferFormat format)
{
    Framebuffer* hdr = target(width, height, format, 0, error);
    if (hdr == m_shown)
        m_shown = nullptr; // it will hold this image, not the one shown
    if (!hdr || !m_renderer->render(scene, *hdr, error))
        return std::nullopt;
    return readBack(*hdr, scene, output, error);
}

std::optional<Image> FrameRenderer::readBack(
    Framebuffer& hdr, const RenderScene& scene, FrameOutput output, std::string* error)
{
    if (output == FrameOutput::LinearRadiance)
        return hdr.readPixels();
    // The viewport's own display transform, on the GPU.
    Framebuffer* display = target(hdr.width(), hdr.height(), FramebufferFormat::RGBA16F, 1, error);
    // A transparent background keeps its alpha: straight, as PNG stores it.
    if (!display
        || !m_renderer->toneMap(
            hdr, *display, scene.view, error, scene.view.background == BackgroundMode::Transparent))
        return std::nullopt;
    Image image = display->readPixels();
    image.setEncoding(ColorEncoding::SRGB);
    return image;
}

std::optional<Image> FrameRenderer::renderConverged(const RenderScene& scene, int width, int height,
    FrameOutput output, int samples, std::string* error, ConvergedStats* stats,
    const std::vector<std::uint8_t>& noiseMask, FramebufferFormat format)
{
    const Clock::time_point start = Clock::now();
    ConvergedStats ignored;
    if (!stats)
        stats = &ignored;
    *stats = {};
    if (scene.sampling.method == IblMethod::SplitSum) {
        auto image = renderImage(scene, width, height, output, error, format);
        stats->draws = 1;
        stats->seconds = secondsSince(start);
        return image;
    }
    if (!m_accumulator)
        m_accumulator = std::make_unique<FrameAccumulator>();
    Framebuffer* frame = target(width, height, FramebufferFormat::RGBA32F, 0, error);
    if (frame == m_shown)
        m_shown = nullptr; // it will hold this image, not the one shown
    if (!frame || !m_accumulator->reset(width, height, error))
        return std::nullopt;
    RenderScene draw = scene;
    draw.view.msaaSamples = 1; // a draw's pixel is its centre's samples: no resolve mixes them
    samples = std::max(samples, 1);
    // A view of a value the samples do not change (base colour, normals, ...) is one draw.
    if (!showsIntegratedLight(scene))
        samples = 1;
    draw.sampling.runLength = samples;
    // The noise is estimated over the object when no mask is given: the first draw's coverage.
    const bool maskFromCoverage = scene.sampling.method == IblMethod::Reference && noiseMask.empty();
    PixelMask coverage;
    const bool reference = scene.sampling.method == IblMethod::Reference;
    for (int done = 0; done < samples;) {
        const int half = m_accumulator->draws() % 2;
        draw.subpixelJitter = jitterOf(draw, m_accumulator->draws());
        draw.sampling.sampleBase = done;
        draw.sampling.samples = std::min(kSamplesPerDraw, samples - done);
        if (reference) {
            // As refine(): pairs of draws of one size, one to each of the accumulator's halves,
            // the halves two independent runs of samples / 2 (seeds seed and seed ^
            // kSecondHalfSeed), each draw the next aligned block of its half's points. Their
            // difference is then the mean's error (issue 29: halves taking alternate blocks of one
            // run printed 0.91% where the error was 0.37%).
            if (half == 0)
                draw.sampling.samples = std::min(kSamplesPerDraw, std::max((samples - done) / 2, 1));
            else
                draw.sampling.samples = std::min(
                    draw.sampling.samples, m_accumulator->halfSamples(0) - m_accumulator->halfSamples(1));
            draw.sampling.sampleBase = m_accumulator->halfSamples(half);
            draw.sampling.seed = half == 0 ? scene.sampling.seed : scene.sampling.seed ^ kSecondHalfSeed;
        }
        draw.coverageAlpha = maskFromCoverage && done == 0;
        if (!accumulateDraw(draw, *frame, *m_accumulator, coverage, error))
            return std::nullopt;
        done += draw.sampling.samples;
    }
    // The resolved mean goes back into the frame target (the sums are separate textures).
    if (!m_accumulator->resolve(*frame, error))
        return std::nullopt;
    glFinish();
    stats->samples = m_accumulator->samples();
    stats->draws = m_accumulator->draws();
    stats->seconds = secondsSince(start);
    if (scene.sampling.method == IblMethod::Reference)
        stats->noise = m_accumulator->noise(maskFromCoverage ? coverage : noiseMask);
    return readBack(*frame, scene, output, error);
}

bool FrameRenderer::accumulateDraw(const RenderScene& draw, Framebuffer& frame, FrameAccumulator& accumulator,
    PixelMask& coverage, std::string* error)
{
    if (!m_renderer->render(draw, frame, error))
        return false;
    if (draw.coverageAlpha)
        coverage = coverageMaskOf(frame);
    return accumulator.add(frame, draw.sampling.samples, error);
}

bool FrameRenderer::present(
    const RenderScene& scene, unsigned framebuffer, const FrameRect& rect, double scale, std::string* error)
{
    scale = std::clamp(scale, 0.05, 1.0);
    const int width = std::max(1, int(std::lround(rect.width * scale)));
    const int height = std::max(1, int(std::lround(rect.height * scale)));
    Framebuffer* hdr = target(width, height, FramebufferFormat::RGBA16F, 0, error);
    if (!hdr || !m_renderer->render(scene, *hdr, error))
        return false;
    m_lastWidth = width;
    m_lastHeight = height;
    return show(*hdr, scene.view, framebuffer, rect, error);
}

bool FrameRenderer::show(
    const Framebuffer& hdr, const ViewSettings& view, unsigned framebuffer, const FrameRect& rect, std::string* error)
{
    m_shown = &hdr;
    const int width = hdr.width();
    const int height = hdr.height();
    const bool direct = rect.x == 0 && rect.y == 0 && width == rect.width && height == rect.height;
    if (direct) {
        // The common case (the single view at full resolution): tone-map straight into the
        // caller's framebuffer, no copy.
        if (!m_renderer->toneMapTo(hdr, framebuffer, view, error))
            return false;
    } else {
        Framebuffer* display = target(width, height, FramebufferFormat::RGBA16F, 1, error);
        if (!display || !m_renderer->toneMap(hdr, *display, view, error))
            return false;
        // Into the rectangle: stretched (bilinear) when reduced, texel for texel otherwise.
        glBindFramebuffer(GL_READ_FRAMEBUFFER, display->framebufferId());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
        glBlitFramebuffer(0, 0, width, height, rect.x, rect.y, rect.x + rect.width, rect.y + rect.height,
            GL_COLOR_BUFFER_BIT, width == rect.width && height == rect.height ? GL_NEAREST : GL_LINEAR);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(rect.x, rect.y, rect.width, rect.height);
    return true;
}

bool FrameRenderer::refine(const RenderScene& preview, const RenderScene& scene, unsigned framebuffer,
    const FrameRect& rect, bool restart, int drawSamples, std::string* error, int slot, double sliceMs)
{
    std::unique_ptr<ViewRefinement>& made = m_views[slot];
    if (!made)
        made = std::make_unique<ViewRefinement>();
    ViewRefinement& view = *made;
    const int width = std::max(rect.width, 1);
    const int height = std::max(rect.height, 1);
    if (!view.frame || view.frame->width() != width || view.frame->height() != height) {
        view.frame = Framebuffer::create(width, height, FramebufferFormat::RGBA32F, error);
        view.held = Framebuffer::create(width, height, FramebufferFormat::RGBA16F, error);
        if (!view.frame || !view.held) {
            view.frame.reset();
            return false;
        }
        restart = true;
    }
    if (restart) {
        // The split-sum frame first: shown at once, and until the accumulation is worth showing.
        view.state = {};
        view.spread.reset();
        view.state.target = std::max(scene.sampling.samples, 1);
        if (!showsIntegratedLight(scene))
            view.state.target = 1;
        view.state.finalTarget = view.state.target;
        if (scene.sampling.method == IblMethod::Fis)
            view.state.target = fisRefinementLevels(view.state.target).front();
        if (!view.accumulator.reset(width, height, error) || !m_renderer->render(preview, *view.held, error))
            return false;
        m_lastWidth = width;
        m_lastHeight = height;
        return show(*view.held, scene.view, framebuffer, rect, error);
    }
    if (!view.state.done() && !drawStep(view, scene, width, height, drawSamples, sliceMs, error))
        return false;
    m_lastWidth = width;
    m_lastHeight = height;
    return showRefinement(view, scene, framebuffer, rect, error);
}

bool FrameRenderer::continueDraw(const RenderScene& scene, std::string* error, int slot)
{
    const auto found = m_views.find(slot);
    if (found == m_views.end() || !found->second->frame || found->second->state.bandsDrawn == 0)
        return true; // no draw under way
    ViewRefinement& view = *found->second;
    return drawStep(
        view, scene, view.frame->width(), view.frame->height(), view.state.lastDrawSamples, 0.0, error);
}

bool FrameRenderer::drawStep(ViewRefinement& view, const RenderScene& scene, int width, int height,
    int drawSamples, double sliceMs, std::string* error)
{
    Refinement& state = view.state;
    RenderScene draw = scene;
    draw.view.msaaSamples = 1;
    draw.sampling.sampleBase = state.samples;
    // Draws come in pairs of one size k, a power of two, one to each of the accumulator's
    // halves at one sub-pixel offset (jitterOf). For Reference the halves are independent
    // runs (seeds run.seed and run.seed ^ kSecondHalfSeed: their own Cranley-Patterson
    // shifts), each draw the next aligned block of its half's Sobol' points ([S, S + k) with k
    // dividing S), so each half is a randomised quasi-Monte Carlo estimate as good as one
    // run, and their difference estimates the mean's error. Halves taking alternate blocks of
    // one run (as renderConverged's) differ far more than the whole errs: in a white furnace
    // the estimate read 1% where the error was 0.06%, and 20% where the image had about 1%
    // with unaligned blocks. So k grows by at most 2x a pair (1, 1, 2, 2, 4, 4 ...) up to the
    // budget's size, and a pair never takes more than what is left. Fis is one
    // deterministic run: its draws are consecutive parts of it.
    const int half = state.draws % 2;
    const int halfBase = view.accumulator.halfSamples(half);
    if (half == 1 || state.bandsDrawn > 0) {
        drawSamples = state.lastDrawSamples; // the pair's size, or the draw under way
    } else {
        const int left = state.target - state.samples;
        int k = 1;
        while (k * 2 <= std::max(drawSamples, 1) && k * 4 <= left)
            k *= 2;
        if (halfBase > 0)
            k = std::min(k, halfBase & -halfBase);
        drawSamples = k;
    }
    if (scene.sampling.method == IblMethod::Reference) {
        draw.sampling.sampleBase = halfBase;
        draw.sampling.seed = half == 0 ? scene.sampling.seed : scene.sampling.seed ^ kSecondHalfSeed;
    }
    draw.sampling.samples = std::clamp(drawSamples, 1, state.target - state.samples);
    state.lastDrawSamples = draw.sampling.samples;
    draw.sampling.runLength = state.target;
    draw.subpixelJitter = jitterOf(draw, state.draws);
    const bool reference = scene.sampling.method == IblMethod::Reference;
    draw.coverageAlpha = reference && state.draws == 0; // the object, for the noise estimate
    // A draw that would take longer than `sliceMs` is drawn in bands of rows, one a call, so
    // that input waits for a band, not a draw (llvmpipe: one fis sample over a 1278x902 view
    // is about 0.3 s). The estimate is the last draw's cost per sample and pixel.
    if (state.bandsDrawn == 0) {
        const double estimateMs = view.msPerSamplePixel * double(draw.sampling.samples) * width * height;
        state.bands = sliceMs > 0.0 && estimateMs > sliceMs
            ? int(std::min(std::ceil(estimateMs / sliceMs), double(std::min(kMaxBands, height))))
            : 1;
        state.drawMs = 0.0;
    }
    const Clock::time_point start = Clock::now();
    const int band = state.bandsDrawn;
    const int y0 = height * band / state.bands;
    const int y1 = height * (band + 1) / state.bands;
    if (state.bands > 1) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, y0, width, y1 - y0);
    }
    const bool drawn = m_renderer->render(draw, *view.frame, error);
    glDisable(GL_SCISSOR_TEST);
    if (!drawn)
        return false;
    glFinish();
    if (band + 1 < state.bands) {
        // More bands to come: what is on screen stays (the held frame, or the mean in it).
        ++state.bandsDrawn;
        state.lastSliceMs = secondsSince(start) * 1000.0;
        state.drawMs += state.lastSliceMs;
        return true;
    }
    state.bandsDrawn = 0;
    if (draw.coverageAlpha)
        view.mask = coverageMaskOf(*view.frame);
    if (!view.accumulator.add(*view.frame, draw.sampling.samples, error))
        return false;
    glFinish();
    state.lastSliceMs = secondsSince(start) * 1000.0;
    state.lastDrawMs = state.drawMs + state.lastSliceMs; // every band, and the accumulation
    view.msPerSamplePixel = state.lastDrawMs / (double(draw.sampling.samples) * width * height);
    state.seconds += state.lastDrawMs / 1000.0;
    state.samples += draw.sampling.samples;
    ++state.draws;
    // The estimate reads both halves back: after a pair, once the drawing since the last one
    // took kNoiseIntervalSeconds or four draws' time (whichever is less: a small view checks
    // often, a large one pays the read-back rarely), and at the end.
    const double interval = std::min(kNoiseIntervalSeconds, 4.0 * state.lastDrawMs / 1000.0);
    if (reference
        && (state.samples >= state.target
            || (state.draws % 2 == 0 && state.seconds - state.noiseSeconds >= interval))) {
        if (std::optional<FrameAccumulator::Spread> spread = view.accumulator.spread()) {
            state.noise = relativeNoiseRmse(spread->mean, spread->variance, view.mask);
            state.noiseSeconds = state.seconds;
            view.spread = std::move(spread);
        }
    }
    if (scene.sampling.method == IblMethod::Fis && state.samples >= state.target
        && state.target < state.finalTarget) {
        // A level is complete: its estimate is held on screen while the next, four times the
        // samples, accumulates from nothing.
        if (!view.accumulator.resolve(*view.held, error) || !view.accumulator.reset(width, height, error))
            return false;
        state.levelShown = state.target;
        state.target = std::min(state.target * 4, state.finalTarget);
        state.samples = 0;
        state.draws = 0;
        state.lastDrawSamples = 0;
        state.showing = false;
    }
    return true;
}

bool FrameRenderer::showRefinement(ViewRefinement& view, const RenderScene& scene, unsigned framebuffer,
    const FrameRect& rect, std::string* error)
{
    Refinement& state = view.state;
    // Between the bands of a draw what is on screen stays: the held frame, or the mean in it.
    if (state.bandsDrawn > 0)
        return show(*view.held, scene.view, framebuffer, rect, error);
    // Fis's partial runs are biased (a Hammersley prefix covers only part of the lobe): shown
    // when complete. Reference's are unbiased, and shown once no longer mostly noise.
    state.showing = state.samples
        >= (scene.sampling.method == IblMethod::Fis ? state.target : std::min(kRefinementShownAfter, state.target));
    if (state.showing && scene.sampling.method == IblMethod::Fis)
        state.levelShown = state.target;
    if (!state.showing)
        return show(*view.held, scene.view, framebuffer, rect, error);
    // The mean so far into the held target (the sums are the accumulator's own textures; the
    // frame target is the next draw's, band by band), shown from there until the next draw is done.
    return view.accumulator.resolve(*view.held, error)
        && show(*view.held, scene.view, framebuffer, rect, error);
}

std::vector<int> FrameRenderer::fisRefinementLevels(int samples)
{
    std::vector<int> levels;
    for (int level = std::max(samples, 1); !levels.empty() ? level >= kFisFirstLevel : true; level /= 4)
        levels.push_back(level);
    std::reverse(levels.begin(), levels.end());
    return levels;
}

const FrameRenderer::Refinement& FrameRenderer::refinement(int slot) const
{
    static const Refinement none;
    const auto found = m_views.find(slot);
    return found != m_views.end() ? found->second->state : none;
}

const std::optional<FrameAccumulator::Spread>& FrameRenderer::refinementSpread(int slot) const
{
    static const std::optional<FrameAccumulator::Spread> none;
    const auto found = m_views.find(slot);
    return found != m_views.end() ? found->second->spread : none;
}

std::optional<glm::vec4> FrameRenderer::shownRadiance(double fx, double fy) const
{
    if (!m_shown || !(fx >= 0.0 && fx < 1.0 && fy >= 0.0 && fy < 1.0))
        return std::nullopt;
    // m_shown may have been freed since (a pooled target evicted, a refinement dropped or resized):
    // read it only while it is still one of the live targets.
    bool live = std::any_of(m_targets.begin(), m_targets.end(),
        [this](const PooledTarget& t) { return &t.framebuffer == m_shown; });
    for (const auto& [slot, view] : m_views)
        live = live || (view->frame && &*view->frame == m_shown) || (view->held && &*view->held == m_shown);
    if (!live)
        return std::nullopt;
    return m_shown->readPixel(int(fx * m_shown->width()), int(fy * m_shown->height()));
}

void FrameRenderer::dropRefinements(const std::function<bool(int slot)>& keep)
{
    std::erase_if(m_views, [&keep](const auto& entry) { return !keep(entry.first); });
}

} // namespace facet
