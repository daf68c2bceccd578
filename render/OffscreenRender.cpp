#include "render/OffscreenRender.h"

#include "render/Framebuffer.h"
#include "render/IblSettings.h"
#include "render/RenderScene.h"
#include "render/Renderer.h"

namespace facet {

std::optional<Image> renderOffscreen(Renderer& renderer, const RenderScene& scene, int width, int height,
    OffscreenOutput output, std::string* error)
{
    auto hdr = Framebuffer::create(width, height, FramebufferFormat::RGBA16F, error);
    if (!hdr || !renderer.render(scene, *hdr, error))
        return std::nullopt;
    if (output == OffscreenOutput::LinearRadiance)
        return hdr->readPixels();
    // The viewport's own display transform, on the GPU.
    auto display = Framebuffer::create(width, height, FramebufferFormat::RGBA16F, error);
    if (!display || !renderer.toneMap(*hdr, *display, scene.view, error))
        return std::nullopt;
    Image image = display->readPixels();
    image.setEncoding(ColorEncoding::SRGB);
    return image;
}

SceneOptions sceneOptionsFor(const IblSettings& settings, bool referenceView)
{
    SceneOptions options;
    options.referenceView = referenceView;
    options.irradianceFromSH = settings.irradiance == IblSettings::Irradiance::SH;
    return options;
}

} // namespace facet
