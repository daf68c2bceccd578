#pragma once
// The GPU side of the viewport (not a widget): owns the render::Renderer, the IBL precompute and
// the HDR target in the viewport's GL context, and draws the SceneController's snapshot into the
// widget's framebuffer. It runs the IBL precompute only when SceneController::iblKey() changed
// (a new environment image or quality; the disk cache makes a second start fast), fetches the
// split-sum DFG table of the material's visibility term when the frame needs one it has not
// made yet (IblPrecompute caches them per variant), and otherwise only renders. At a scale
// below 1 it renders and tone-maps a smaller image and stretches it onto the widget (the
// interactive preview; llvmpipe's cost is per pixel).
//
// Every call needs the viewport's context current; destroy it with the context current.

#include "render/IblPrecompute.h"
#include "render/RenderStats.h"

#include <QString>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace facet {

class Framebuffer;
class Renderer;
class SceneController;

// What the last frame cost, for the status bar and the View dock.
struct ViewportFrameStats {
    std::uint64_t frameNumber = 0; // frames drawn since the renderer was made (1 = the first)
    int width = 0; // rendered size in device pixels (smaller than the widget when reduced)
    int height = 0;
    bool reduced = false; // drawn at reduced resolution (an interaction is running)
    double frameMs = 0.0; // render + tone map + present, GPU finished (glFinish)
    double iblMs = 0.0; // the IBL precompute this frame ran (0: cached / not needed)
    IblStats ibl; // of the last precompute (kept until the next one)
    RenderStats render; // Renderer::lastFrameStats()

    // "1280×720 · 112 ms" (+ " (preview)" when reduced).
    QString summary() const;
};

class ViewportRenderer {
public:
    // Needs the context current. `cacheDirectory` empty: the IBL disk cache's default folder.
    explicit ViewportRenderer(const QString& cacheDirectory = {});
    ~ViewportRenderer();
    ViewportRenderer(const ViewportRenderer&) = delete;
    ViewportRenderer& operator=(const ViewportRenderer&) = delete;

    // Whether the next paint() runs the IBL precompute (the caller may say so first).
    bool needsIbl(const SceneController& scene) const;

    // Draws `scene` into `targetFramebuffer` (width x height device pixels) at `scale` in (0, 1]
    // of the resolution. False with *error ("ViewportRenderer::paint: ...") when the frame could
    // not be drawn; the target is then cleared to the empty viewport's grey.
    bool paint(const SceneController& scene, unsigned targetFramebuffer, int width, int height, double scale,
        std::string* error);

    const ViewportFrameStats& lastFrame() const { return m_stats; }

private:
    // (Re)makes `target` at width x height when its size differs.
    static bool ensureTarget(std::unique_ptr<Framebuffer>& target, int width, int height, std::string* error);

    std::unique_ptr<IblPrecompute> m_precompute;
    std::unique_ptr<Renderer> m_renderer;
    std::unique_ptr<Framebuffer> m_hdr; // the scene's linear radiance
    std::unique_ptr<Framebuffer> m_display; // tone-mapped, reduced frames only (then stretched)
    std::shared_ptr<const IblTextures> m_ibl;
    std::optional<std::uint64_t> m_iblKey; // SceneController::iblKey() of m_ibl
    std::string m_iblError; // the precompute failed for this key: do not retry every frame
    ViewportFrameStats m_stats;
};

} // namespace facet
