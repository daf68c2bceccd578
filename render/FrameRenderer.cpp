#include "render/FrameRenderer.h"

#include <epoxy/gl.h>

#include "core/ProjectAssets.h"
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

FrameRenderer::~FrameRenderer()
{
    // GL objects go while the caller holds the context current: targets and the renderer's
    // objects first, then the precompute (when this was its last holder).
    m_targets.clear();
    m_accumulator.reset();
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

bool FrameRenderer::addDfgTables(
    const IblSettings& settings, RenderScene& scene, IblStats* stats, std::string* error)
{
    return facet::addDfgTables(*m_precompute, settings, scene, stats, error);
}

std::optional<RenderScene> FrameRenderer::prepare(const Project& project, const ProjectAssets& assets,
    const IblSettings& settings, const SceneOptions& options, IblStats* stats, std::string* error)
{
    const auto ibl = lighting(assets.environment, settings, stats, error);
    if (!ibl)
        return std::nullopt;
    RenderScene scene = sceneFromProject(project, assets, ibl, options);
    if (!addDfgTables(settings, scene, stats, error) || !addEnvironmentSource(assets.environment, scene, stats, error))
        return std::nullopt;
    return scene;
}

bool FrameRenderer::addEnvironmentSource(
    const Environment& environment, RenderScene& scene, IblStats* stats, std::string* error)
{
    if (scene.sampling.method != IblMethod::Reference)
        return true;
    const auto source = m_precompute->source(environment, stats, error);
    if (!source)
        return false;
    scene.environment.setSource(source);
    return true;
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
    if (!hdr || !m_renderer->render(scene, *hdr, error))
        return std::nullopt;
    if (output == FrameOutput::LinearRadiance)
        return hdr->readPixels();
    // The viewport's own display transform, on the GPU.
    Framebuffer* display = target(width, height, FramebufferFormat::RGBA16F, 1, error);
    if (!display || !m_renderer->toneMap(*hdr, *display, scene.view, error))
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
    if (scene.sampling.method != IblMethod::Reference) {
        auto image = renderImage(scene, width, height, output, error, format);
        stats->draws = 1;
        stats->seconds = secondsSince(start);
        return image;
    }
    if (!m_accumulator)
        m_accumulator = std::make_unique<FrameAccumulator>();
    Framebuffer* frame = target(width, height, FramebufferFormat::RGBA32F, 0, error);
    if (!frame || !m_accumulator->reset(width, height, error))
        return std::nullopt;
    RenderScene draw = scene;
    draw.view.msaaSamples = 1; // a draw's pixel is its centre's samples: no resolve mixes them
    samples = std::max(samples, 1);
    // A view of a value the samples do not change (base colour, normals, ...) is one draw.
    if (!debugViewShowsIntegratedLight(debugViewFromString(scene.view.debugView).value_or(DebugView::None)))
        samples = 1;
    for (int done = 0; done < samples;) {
        draw.sampling.sampleBase = done;
        draw.sampling.samples = std::min(kSamplesPerDraw, samples - done);
        if (!m_renderer->render(draw, *frame, error) || !m_accumulator->add(*frame, draw.sampling.samples, error))
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
    stats->noise = m_accumulator->noise(noiseMask);
    if (output == FrameOutput::LinearRadiance)
        return frame->readPixels();
    Framebuffer* display = target(width, height, FramebufferFormat::RGBA16F, 1, error);
    if (!display || !m_renderer->toneMap(*frame, *display, scene.view, error))
        return std::nullopt;
    Image image = display->readPixels();
    image.setEncoding(ColorEncoding::SRGB);
    return image;
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
    const bool direct
        = scale >= 1.0 && rect.x == 0 && rect.y == 0 && width == rect.width && height == rect.height;
    if (direct) {
        // The common case (the single view at full resolution): tone-map straight into the
        // caller's framebuffer, no copy.
        if (!m_renderer->toneMapTo(*hdr, framebuffer, scene.view, error))
            return false;
    } else {
        Framebuffer* display = target(width, height, FramebufferFormat::RGBA16F, 1, error);
        if (!display || !m_renderer->toneMap(*hdr, *display, scene.view, error))
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

} // namespace facet
