#include "ReferenceViewRenderer.h"

#include <QTemporaryDir>

#include "core/image/ImageMetrics.h"
#include "core/project/Project.h"
#include "core/project/ProjectAssets.h"
#include "core/shading/ReferenceView.h"
#include "render/FrameRenderer.h"
#include "render/HeadlessGLContext.h"
#include "render/IblSettings.h"

namespace facet::test {

// Members in construction order: destroyed in reverse, so the GL objects go while the context
// is still current.
struct ReferenceViewRenderer::State {
    std::optional<HeadlessGLContext> context;
    QTemporaryDir cacheDir;
    std::optional<FrameRenderer> frames;
    int sharpLobeSamples = kSplitSumSharpLobeSamples;
};

ReferenceViewRenderer::ReferenceViewRenderer() = default;

ReferenceViewRenderer::~ReferenceViewRenderer()
{
    if (m_state)
        m_state->frames.reset();
}

bool ReferenceViewRenderer::initialize(std::string* error)
{
    m_state = std::make_unique<State>();
    m_state->context = HeadlessGLContext::create(error);
    if (!m_state->context)
        return false;
    if (!m_state->cacheDir.isValid()) {
        *error = "ReferenceViewRenderer: no temporary directory for the IBL cache";
        return false;
    }
    m_state->frames.emplace(m_state->cacheDir.path(), /*useDiskCache=*/false);
    return true;
}

std::optional<RenderScene> ReferenceViewRenderer::prepareScene(
    const Project& project, const std::string& preset, std::string* error)
{
    if (!m_state || !m_state->frames) {
        *error = "ReferenceViewRenderer::render: not initialised";
        return std::nullopt;
    }
    const auto assets = loadProjectAssets(project, error);
    if (!assets)
        return std::nullopt;
    const auto settings = IblSettings::preset(preset);
    if (!settings) {
        *error = "ReferenceViewRenderer::render: unknown IBL preset '" + preset + "'";
        return std::nullopt;
    }
    auto scene = m_state->frames->prepare(
        project, *assets, *settings, sceneOptionsFor(*settings, /*referenceView=*/true), nullptr, error);
    if (scene)
        scene->sampling.sharpLobeSamples = m_state->sharpLobeSamples;
    return scene;
}

void ReferenceViewRenderer::setSharpLobeSamples(int samples)
{
    if (m_state)
        m_state->sharpLobeSamples = samples;
}

std::optional<Image> ReferenceViewRenderer::render(const Project& project, const std::string& preset, int size,
    std::string* error, std::optional<double>* noise, bool jittered)
{
    auto scene = prepareScene(project, preset, error);
    if (!scene)
        return std::nullopt;
    scene->pixelCentres = !jittered;
    // The noise estimate over the pixels the accuracy metric reads.
    const PixelMask mask = sphereMask(size, size);
    FrameRenderer::ConvergedStats stats;
    auto image = m_state->frames->renderConverged(
        *scene, size, size, FrameOutput::LinearRadiance, scene->sampling.samples, error, &stats, mask,
        FramebufferFormat::RGBA32F);
    if (noise)
        *noise = stats.noise;
    return image;
}

std::optional<FrameRenderer::Refinement> ReferenceViewRenderer::refine(const Project& project,
    const std::string& preset, int size, int drawSamples, std::string* error,
    std::optional<FrameAccumulator::Spread>* spread, std::vector<int>* draws, std::vector<RefineStep>* steps,
    double sliceMs, bool bandsBetweenFrames)
{
    auto scene = prepareScene(project, preset, error);
    if (!scene)
        return std::nullopt;
    RenderScene preview = *scene;
    preview.sampling = {};
    std::optional<Framebuffer> target = Framebuffer::create(size, size, FramebufferFormat::RGBA16F, error);
    if (!target)
        return std::nullopt;
    FrameRenderer& frames = *m_state->frames;
    const FrameRect rect {0, 0, size, size};
    const auto record = [&] {
        if (steps)
            steps->push_back({frames.refinement(), target->readPixels()});
    };
    if (!frames.refine(
            preview, *scene, target->framebufferId(), rect, /*restart=*/true, drawSamples, error, 0, sliceMs))
        return std::nullopt;
    record();
    // A bound on the calls: the target's draws (fis: its levels', at most 4/3 of them), and more,
    // each in at most kMaxBands calls.
    const int calls = (2 * scene->sampling.samples + 8) * (sliceMs > 0.0 ? FrameRenderer::kMaxBands : 1);
    for (int call = 0; !frames.refinement().done() && call <= calls; ++call) {
        if (!frames.refine(
                preview, *scene, target->framebufferId(), rect, false, drawSamples, error, 0, sliceMs))
            return std::nullopt;
        while (bandsBetweenFrames && frames.refinement().bandsDrawn > 0)
            if (!frames.continueDraw(*scene, error))
                return std::nullopt;
        if (draws && frames.refinement().bandsDrawn == 0) // a draw is complete
            draws->push_back(frames.refinement().lastDrawSamples);
        record();
    }
    // A draw completed between frames is shown by the next refine() (the window's next paint).
    if (bandsBetweenFrames) {
        if (!frames.refine(
                preview, *scene, target->framebufferId(), rect, false, drawSamples, error, 0, sliceMs))
            return std::nullopt;
        record();
    }
    if (spread)
        *spread = frames.refinementSpread();
    return frames.refinement();
}

std::optional<Image> ReferenceViewRenderer::renderAsCommand(
    const Project& project, const std::string& preset, int size, std::string* error)
{
    const auto scene = prepareScene(project, preset, error);
    if (!scene)
        return std::nullopt;
    // A fresh surface renderer (the IBL results shared): every map and the mesh are uploaded in
    // this frame, as after opening a project.
    FrameRenderer fresh(m_state->frames->sharedPrecompute());
    return fresh.renderImage(*scene, size, size, FrameOutput::LinearRadiance, error);
}

} // namespace facet::test
