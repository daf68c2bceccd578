#pragma once
// Counters that make skipped work observable (docs/architecture.md, "Skipping work"):
// rendering the same scene twice compiles no program and uploads nothing the second time, and a
// roughness change only sets uniforms. Renderer keeps one RenderStats for the last frame and
// one accumulated since creation.

#include <cstdint>

namespace facet {

struct RenderStats {
    int programsCompiled = 0; // surface variants + the fixed programs (background, tone map)
    int texturesUploaded = 0; // material maps (TextureCache misses)
    int meshesUploaded = 0;   // GpuMesh (re)uploads
    int drawCalls = 0;
    // Textured slots shaded with their factors alone: the material needed more texture units
    // than the driver has (Renderer::variantKeyFor).
    int mapsLeftOut = 0;
    std::uint64_t frameCount = 0; // render() calls (accumulated stats only)
    // Milliseconds per step, measured with glFinish() around the step when
    // Renderer::setTimingEnabled(true) (it stalls the pipeline, so it is off by default); 0 else.
    double uploadMs = 0.0;
    double backgroundMs = 0.0;
    double surfaceMs = 0.0;
    double resolveMs = 0.0;
    double toneMapMs = 0.0;

    void add(const RenderStats& frame)
    {
        programsCompiled += frame.programsCompiled;
        texturesUploaded += frame.texturesUploaded;
        meshesUploaded += frame.meshesUploaded;
        drawCalls += frame.drawCalls;
        mapsLeftOut += frame.mapsLeftOut;
        uploadMs += frame.uploadMs;
        backgroundMs += frame.backgroundMs;
        surfaceMs += frame.surfaceMs;
        resolveMs += frame.resolveMs;
        toneMapMs += frame.toneMapMs;
    }
};

} // namespace facet
