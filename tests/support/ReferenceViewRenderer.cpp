#include "ReferenceViewRenderer.h"

#include <QTemporaryDir>

#include "core/Project.h"
#include "core/ProjectAssets.h"
#include "render/Framebuffer.h"
#include "render/HeadlessGLContext.h"
#include "render/IblPrecompute.h"
#include "render/IblSettings.h"
#include "render/OffscreenRender.h"
#include "render/Renderer.h"
#include "render/SceneFromProject.h"

namespace facet::test {

// Members in construction order: destroyed in reverse, so the GL objects go while the context
// is still current.
struct ReferenceViewRenderer::State {
    std::optional<HeadlessGLContext> context;
    QTemporaryDir cacheDir;
    std::optional<IblPrecompute> ibl;
    std::optional<Renderer> renderer;
};

ReferenceViewRenderer::ReferenceViewRenderer() = default;

ReferenceViewRenderer::~ReferenceViewRenderer()
{
    if (m_state) {
        m_state->renderer.reset();
        m_state->ibl.reset();
    }
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
    m_state->ibl.emplace(m_state->cacheDir.path(), /*useDiskCache=*/false);
    m_state->renderer.emplace();
    return true;
}

std::optional<RenderScene> ReferenceViewRenderer::prepareScene(
    const Project& project, const std::string& preset, std::string* error)
{
    if (!m_state || !m_state->renderer) {
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
    const auto ibl = m_state->ibl->prepare(assets->environment, *settings, nullptr, error);
    if (!ibl)
        return std::nullopt;
    RenderScene scene = sceneFromProject(project, *assets, ibl, sceneOptionsFor(*settings, /*referenceView=*/true));
    if (!addDfgTables(*m_state->ibl, *settings, scene, nullptr, error))
        return std::nullopt;
    return scene;
}

std::optional<Image> ReferenceViewRenderer::render(
    const Project& project, const std::string& preset, int size, std::string* error)
{
    const auto scene = prepareScene(project, preset, error);
    if (!scene)
        return std::nullopt;
    auto target = Framebuffer::create(size, size, FramebufferFormat::RGBA32F, error);
    if (!target || !m_state->renderer->render(*scene, *target, error))
        return std::nullopt;
    return target->readPixels();
}

std::optional<Image> ReferenceViewRenderer::renderAsCommand(
    const Project& project, const std::string& preset, int size, std::string* error)
{
    const auto scene = prepareScene(project, preset, error);
    if (!scene)
        return std::nullopt;
    // A fresh renderer: every map and the mesh are uploaded in this frame, as after opening a project.
    Renderer renderer;
    return renderOffscreen(renderer, *scene, size, size, OffscreenOutput::LinearRadiance, error);
}

} // namespace facet::test
