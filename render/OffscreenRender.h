#pragma once
// The GPU path from a RenderScene to an Image in memory, shared by `facet render` (which saves
// the image) and `facet bench` (which compares it with the ground truth), so that the benchmark
// measures exactly what the render command writes. Needs a current GL context (the headless
// commands use render/HeadlessGLContext).

#include <optional>
#include <string>

#include "core/Image.h"
#include "render/SceneFromProject.h"

namespace facet {

class Renderer;
struct IblSettings;
struct RenderScene;

enum class OffscreenOutput {
    LinearRadiance, // the HDR target as it is: scene radiance, no exposure, no tone mapping
    DisplayReferred, // the viewport's display transform (exposure, tone mapper, encoding), tagged sRGB
};

// Renders `scene` with `renderer` into a new width x height RGBA16F framebuffer and reads it back
// (top row first). On failure returns nullopt with `error` set by the step that failed
// ("Framebuffer::create: ...", "Renderer::render: ...").
std::optional<Image> renderOffscreen(Renderer& renderer, const RenderScene& scene, int width, int height,
    OffscreenOutput output, std::string* error);

// The SceneOptions that go with IBL `settings`: irradiance from the SH9 coefficients when the
// settings choose them, the irradiance cubemap otherwise.
SceneOptions sceneOptionsFor(const IblSettings& settings, bool referenceView);

} // namespace facet
