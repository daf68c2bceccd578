// How long the converging GPU integrator (IblMethod::Reference, issue 10) takes to bring a
// 1280x720 view of the default project to 1% noise on whatever OpenGL this machine has (llvmpipe
// here). Prints numbers; checks nothing (docs/benchmarks.md, "IBL methods", has the measured
// values and how they were taken). Headless: a surfaceless EGL context, no display.
//
//   reference_convergence [--size WxH] [--target NOISE] [--max-samples N] [--max-seconds S]
//
// For spp = 16, 32, 64, ... it renders the view from scratch with FrameRenderer::renderConverged
// (draws of 64 samples, glFinish'ed) and prints spp, draws, seconds and the accumulator's noise
// estimate (relative RMSE of the mean, FrameAccumulator::noise) over the object's pixels, until
// the noise is at most --target (0.01), or --max-samples (4096) is reached, or the next doubling
// (about twice the last step's time) would end past --max-seconds (600) of rendering in all.
// Each step's time is the time to converge to its noise, start to finish; Msamples/s counts the
// object's pixels only (the background is one look-up).
//
// The object's pixels: those that do not change when the background colour does (two split-sum
// frames with a black and a bright solid background, one sample per pixel). The environment
// behind the object is looked up, not sampled, so it has no noise: counting it would dilute the
// estimate.

#include "core/project/Project.h"
#include "core/project/ProjectAssets.h"
#include "render/FrameRenderer.h"
#include "render/HeadlessGLContext.h"
#include "render/IblPrecompute.h"
#include "render/RenderScene.h"
#include "render/SceneFromProject.h"

#include <QCoreApplication>
#include <QStringList>

#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

using namespace facet;

namespace {

struct Options {
    int width = 1280;
    int height = 720;
    double target = 0.01;
    int maxSamples = 4096;
    double maxSeconds = 600.0;
};

std::optional<Options> parse(const QStringList& arguments)
{
    Options o;
    for (qsizetype i = 1; i < arguments.size(); ++i) {
        const QString& flag = arguments[i];
        if (i + 1 >= arguments.size())
            return std::nullopt;
        const QString value = arguments[++i];
        bool ok = false;
        if (flag == QStringLiteral("--size")) {
            const QStringList parts = value.split(QLatin1Char('x'));
            bool okW = false, okH = false;
            if (parts.size() != 2)
                return std::nullopt;
            o.width = parts[0].toInt(&okW);
            o.height = parts[1].toInt(&okH);
            ok = okW && okH && o.width > 0 && o.height > 0 && o.width <= 8192 && o.height <= 8192;
        } else if (flag == QStringLiteral("--target")) {
            o.target = value.toDouble(&ok);
            ok = ok && o.target > 0.0;
        } else if (flag == QStringLiteral("--max-samples")) {
            o.maxSamples = value.toInt(&ok);
            ok = ok && o.maxSamples >= 1 && o.maxSamples <= kMaxIblSamples;
        } else if (flag == QStringLiteral("--max-seconds")) {
            o.maxSeconds = value.toDouble(&ok);
            ok = ok && o.maxSeconds > 0.0;
        }
        if (!ok)
            return std::nullopt;
    }
    return o;
}

// 1 where the object covers the pixel centre: the pixels two split-sum frames with different solid
// backgrounds agree on.
std::optional<std::vector<std::uint8_t>> objectMask(
    FrameRenderer& frames, RenderScene scene, int width, int height, std::string* error)
{
    scene.sampling.method = IblMethod::SplitSum;
    scene.view.msaaSamples = 1;
    scene.view.background = BackgroundMode::Color;
    scene.view.backgroundColor = glm::dvec3(0.0);
    const auto dark = frames.renderImage(
        scene, width, height, FrameOutput::LinearRadiance, error, FramebufferFormat::RGBA32F);
    scene.view.backgroundColor = glm::dvec3(1000.0);
    const auto bright = frames.renderImage(
        scene, width, height, FrameOutput::LinearRadiance, error, FramebufferFormat::RGBA32F);
    if (!dark || !bright)
        return std::nullopt;
    std::vector<std::uint8_t> mask(std::size_t(width) * std::size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            mask[std::size_t(y) * std::size_t(width) + std::size_t(x)]
                = glm::vec3(dark->at(x, y)) == glm::vec3(bright->at(x, y)) ? 1 : 0;
    return mask;
}

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    const std::optional<Options> options = parse(app.arguments());
    if (!options) {
        std::fprintf(stderr,
            "usage: reference_convergence [--size WxH] [--target NOISE] [--max-samples N] [--max-seconds "
            "S]\n");
        return 2;
    }
    const int width = options->width;
    const int height = options->height;

    std::string error;
    std::string warning;
    const Project project = Project::defaultProject();
    const auto assets = loadProjectAssets(project, &error, &warning);
    if (!warning.empty())
        std::fprintf(stderr, "reference_convergence: %s\n", warning.c_str());
    if (!assets) {
        std::fprintf(stderr, "reference_convergence: %s\n", error.c_str());
        return 1;
    }
    auto context = HeadlessGLContext::create(&error);
    if (!context) {
        std::fprintf(stderr, "reference_convergence: %s\n", error.c_str());
        return 1;
    }
    int exitCode = 0;
    {
        FrameRenderer frames;
        const IblSettings settings = IblSettings::preset(project.environment.quality);
        SceneOptions sceneOptions = sceneOptionsFor(settings, /*referenceView=*/false);
        sceneOptions.iblMethod = IblMethod::Reference;
        const auto scene = frames.prepare(project, *assets, settings, sceneOptions, nullptr, &error);
        const auto mask = scene ? objectMask(frames, *scene, width, height, &error) : std::nullopt;
        // The reference variant compiles (and llvmpipe JITs it) on its first draw: not a step's cost.
        if (!scene || !mask
            || !frames.renderConverged(*scene, width, height, FrameOutput::LinearRadiance, 1, &error)) {
            std::fprintf(stderr, "reference_convergence: %s\n", error.c_str());
            return 1;
        }
        std::size_t covered = 0;
        for (std::uint8_t m : *mask)
            covered += m;
        const GLInfo& gl = context->info();
        std::printf("reference_convergence: %dx%d, default project (%s, %s), object %zu pixels (%.1f%%)\n",
            width, height, project.view.mesh.c_str(), project.environment.source.c_str(), covered,
            100.0 * double(covered) / double(mask->size()));
        std::printf("gl: %s; %s\n", gl.renderer.c_str(), gl.version.c_str());
        std::printf("stops at noise <= %.2f%%, %d spp, or past %.0f s of rendering\n\n",
            100.0 * options->target, options->maxSamples, options->maxSeconds);
        std::printf("%8s %6s %10s %12s %9s\n", "spp", "draws", "seconds", "Msamples/s", "noise%");
        std::fflush(stdout);

        double total = 0.0;
        double lastSeconds = 0.0;
        bool converged = false;
        for (int spp = 16; spp <= options->maxSamples; spp *= 2) {
            if (lastSeconds > 0.0 && total + 2.0 * lastSeconds > options->maxSeconds) {
                std::printf("(stopped: %d spp would take about %.0f s more)\n", spp, 2.0 * lastSeconds);
                break;
            }
            FrameRenderer::ConvergedStats stats;
            if (!frames.renderConverged(
                    *scene, width, height, FrameOutput::LinearRadiance, spp, &error, &stats, *mask)) {
                std::fprintf(stderr, "reference_convergence: %s\n", error.c_str());
                exitCode = 1;
                break;
            }
            lastSeconds = stats.seconds;
            total += stats.seconds;
            const double noise = stats.noise.value_or(-1.0);
            // No estimate from one draw (it needs both half-buffers).
            const std::string noiseText = stats.noise ? std::to_string(100.0 * noise).substr(0, 6) : "n/a";
            std::printf("%8d %6d %10.2f %12.2f %9s\n", stats.samples, stats.draws, stats.seconds,
                double(covered) * double(stats.samples) / stats.seconds * 1e-6, noiseText.c_str());
            std::fflush(stdout);
            if (stats.noise && noise <= options->target) {
                std::printf("\nconverged: %d spp, %.2f%% noise in %.2f s\n", stats.samples, 100.0 * noise,
                    stats.seconds);
                converged = true;
                break;
            }
        }
        if (!converged && exitCode == 0)
            std::printf("\nnot converged to %.2f%% within the caps\n", 100.0 * options->target);
        std::printf("rendering in all: %.1f s\n", total);
    }
    return exitCode;
}
