// Prints what the IBL presets' passes and one frame cost on this machine's GL, for docs/ibl.md
// and docs/rendering.md (these were IblGLTest::presetTimings and RendererGLTest::timings: a
// timing belongs in a benchmark, not in a test that cannot fail on it). Runs take turns (every
// preset once, then again, N times), so that a neighbour's load on the machine falls on all of them
// alike; the fastest and the median of each are printed. A fresh precompute each run, no disk
// cache; the programs are compiled once, before the first timed run.
// Usage: gl_timings [repeats]   (default 5; surfaceless EGL, no display needed)

#include "BenchStats.h"
#include "core/ibl/Environment.h"
#include "core/project/Light.h"
#include "core/project/Project.h"
#include "core/project/ProjectAssets.h"
#include "render/FrameRenderer.h"
#include "render/Framebuffer.h"
#include "render/GLInfo.h"
#include "render/HeadlessGLContext.h"
#include "render/IblPrecompute.h"
#include "render/IblSettings.h"
#include "render/Renderer.h"
#include "render/SceneFromProject.h"

#include <QCoreApplication>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <tuple>
#include <vector>

using namespace facet;

namespace {

struct Series {
    std::vector<double> values;
    void add(double value) { values.push_back(value); }
    double fastest() const { return bench::fastest(values); }
    double median() const { return bench::median(values); }
};

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
    std::string error;
    auto context = HeadlessGLContext::create(&error);
    if (!context) {
        std::fprintf(stderr, "gl_timings: %s\n", error.c_str());
        return 1;
    }
    std::printf("GL: %s; %d runs each, taking turns\n\n", queryCurrentGLInfo().summary().c_str(), repeats);

    // 1. The presets' passes on the built-in studio at 512x256.
    const Environment studio = Environment::builtin(Environment::Builtin::Studio, 512);
    const std::vector<std::string> names = IblSettings::presetNames();
    std::map<std::string, std::map<std::string, Series>> passes;
    for (int run = -1; run < repeats; ++run) { // run -1 compiles and warms; not printed
        for (const std::string& name : names) {
            IblPrecompute ibl(QString(), false);
            const IblSettings settings = *IblSettings::preset(name);
            IblStats stats;
            IblStats dfgStats;
            if (!ibl.prepare(studio, settings, &stats, &error)
                || !ibl.dfgTable(settings, Visibility::SmithGGXCorrelated, &dfgStats, &error)) {
                std::fprintf(stderr, "gl_timings: %s: %s\n", name.c_str(), error.c_str());
                return 1;
            }
            if (run < 0)
                continue;
            std::map<std::string, Series>& row = passes[name];
            row["equirect->cube"].add(stats.msEquirectToCube);
            row["prefilter"].add(stats.msPrefilter);
            row["irradiance"].add(stats.msIrradiance);
            row["SH9"].add(stats.msSh);
            row["environment total"].add(stats.msTotal);
            row["DFG"].add(dfgStats.msDfg);
        }
    }
    std::printf(
        "| preset | equirect->cube | prefilter | irradiance | SH9 | environment total | DFG (once) |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    for (const std::string& name : names) {
        std::map<std::string, Series>& row = passes[name];
        std::printf("| %s |", name.c_str());
        for (const char* column :
            {"equirect->cube", "prefilter", "irradiance", "SH9", "environment total", "DFG"})
            std::printf(" %.1f / %.1f |", row[column].fastest(), row[column].median());
        std::printf("\n");
    }
    std::printf("(ms, fastest / median)\n\n");

    // 2. One frame of the default project (two directional lights), per size and MSAA.
    FrameRenderer frames(QString(), false);
    Project project = Project::defaultProject();
    project.lights = {Light::defaultDirectional(), Light::defaultDirectional()};
    const auto assets = loadProjectAssets(project, &error);
    const IblSettings settings = *IblSettings::preset("default");
    const auto scene = assets
        ? frames.prepare(project, *assets, settings, sceneOptionsFor(settings, false), nullptr, &error)
        : std::nullopt;
    if (!scene) {
        std::fprintf(stderr, "gl_timings: %s\n", error.c_str());
        return 1;
    }
    struct Size {
        int width, height, samples;
        std::map<std::string, Series> stages;
    };
    std::vector<Size> sizes = {{640, 360, 1, {}}, {640, 360, 4, {}}, {1280, 720, 1, {}}, {1280, 720, 4, {}}};
    Renderer& renderer = frames.renderer();
    for (int run = -1; run < repeats; ++run) {
        for (Size& size : sizes) {
            RenderScene draw = *scene;
            draw.view.msaaSamples = size.samples;
            auto hdr = Framebuffer::create(size.width, size.height, FramebufferFormat::RGBA16F, &error);
            auto display = Framebuffer::create(size.width, size.height, FramebufferFormat::RGBA16F, &error);
            renderer.setTimingEnabled(true);
            if (!hdr || !display || !renderer.render(draw, *hdr, &error)
                || !renderer.toneMap(*hdr, *display, draw.view, &error)) {
                std::fprintf(stderr, "gl_timings: %s\n", error.c_str());
                return 1;
            }
            renderer.setTimingEnabled(false);
            if (run < 0)
                continue; // the first frame compiles
            const RenderStats& s = renderer.lastFrameStats();
            size.stages["background"].add(s.backgroundMs);
            size.stages["surface"].add(s.surfaceMs);
            size.stages["resolve"].add(s.resolveMs);
            size.stages["tone map"].add(s.toneMapMs);
        }
    }
    std::printf("| frame, 2 lights | background | surface | resolve | tone map |\n|---|---|---|---|---|\n");
    for (Size& size : sizes) {
        std::printf("| %dx%d MSAA %dx |", size.width, size.height, size.samples);
        for (const char* column : {"background", "surface", "resolve", "tone map"})
            std::printf(" %.1f / %.1f |", size.stages[column].fastest(), size.stages[column].median());
        std::printf("\n");
    }
    std::printf("(ms, fastest / median)\n");
    return 0;
}
