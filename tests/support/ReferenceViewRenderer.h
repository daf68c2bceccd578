#pragma once
// For GL tests that render docs/architecture.md's reference view of a project on the GPU, as `facet render
// --reference-view` does, through the same render/FrameRenderer: one surfaceless EGL context and
// one FrameRenderer with its memory cache only (each environment is prepared once per test
// executable, never read from or written to the user's disk cache), torn down in the right order.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/image/Image.h"
#include "render/FrameRenderer.h"
#include "render/RenderScene.h"

namespace facet {
struct Project;
}

namespace facet::test {

class ReferenceViewRenderer {
public:
    ReferenceViewRenderer();
    ~ReferenceViewRenderer();
    ReferenceViewRenderer(const ReferenceViewRenderer&) = delete;
    ReferenceViewRenderer& operator=(const ReferenceViewRenderer&) = delete;

    // Makes the context, the precompute and the renderer; false with *error if there is no GL.
    bool initialize(std::string* error);

    // Linear radiance (RGBA32F read back) of `project`'s reference view, size x size, with the IBL
    // preset `preset` ("draft", "default", "high"), by the project's IBL method at its samples
    // (FrameRenderer::renderConverged). `noise` (optional): the accumulation's noise estimate over
    // the interior sphere pixels (unset for the split sum). nullopt with *error on any failure.
    // `jittered`: the draws are offset within the pixel (RenderScene::subpixelJitter) as outside
    // the reference view, instead of through pixel centres.
    std::optional<Image> render(const Project& project, const std::string& preset, int size, std::string* error,
                                std::optional<double>* noise = nullptr, bool jittered = false);
    // The same through `facet render --reference-view`'s own path: a fresh surface renderer (every
    // map and the mesh uploaded in this frame, as after opening a project), an RGBA16F target
    // read back by FrameRenderer::renderImage.
    std::optional<Image> renderAsCommand(
        const Project& project, const std::string& preset, int size, std::string* error);
    // The window's refinement of `project`'s reference view (FrameRenderer::refine, draws of
    // `drawSamples`, bands of about `sliceMs` when > 0) into a size x size target, called until
    // done: its state then, and (optional) the accumulation's mean and variance, each complete
    // draw's samples, and after each call its state and the target as shown (display-referred, top
    // row first). `bandsBetweenFrames`: a draw's later bands through continueDraw, as the window
    // draws them (no step recorded for them), else each through refine(). nullopt with *error on any failure.
    struct RefineStep {
        FrameRenderer::Refinement state;
        Image shown;
    };
    std::optional<FrameRenderer::Refinement> refine(const Project& project, const std::string& preset,
        int size, int drawSamples, std::string* error,
        std::optional<FrameAccumulator::Spread>* spread = nullptr, std::vector<int>* draws = nullptr,
        std::vector<RefineStep>* steps = nullptr, double sliceMs = 0.0, bool bandsBetweenFrames = false);

    // The split sum's sharp-lobe samples of the scenes rendered from now on
    // (IblSampling::sharpLobeSamples; 0: the prefiltered lookup only).
    void setSharpLobeSamples(int samples);

private:
    std::optional<RenderScene> prepareScene(const Project& project, const std::string& preset, std::string* error);
    struct State;
    std::unique_ptr<State> m_state;
};

} // namespace facet::test
