#include "RenderCommand.h"

#include "CommandInputs.h"
#include "CommandOptions.h"
#include "MaterialFlags.h"
#include "RenderScenario.h"
#include "SceneFlags.h"
#include "render/FrameRenderer.h"

#include <cmath>
#include <cstdio>

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>

#include <chrono>

#include "core/image/Image.h"
#include "core/image/ImageMetrics.h"
#include "core/image/ToneMap.h"
#include "core/image/VideoEncoder.h"
#include "core/material/MaterialPresets.h"
#include "core/project/AssetProject.h"
#include "core/project/ProjectAssets.h"
#include "core/shading/Brdf.h"
#include "core/shading/DfgTable.h"
#include "core/shading/GroundTruth.h"
#include "core/shading/MaterialBrdf.h"
#include "render/HeadlessGLContext.h"
#include "render/IblSettings.h"
#include "render/RenderScene.h"
#include "render/Renderer.h"
#include "render/SceneFromProject.h"
#include "render/ShaderVariant.h"

namespace facet {

namespace {

constexpr int kMaxImageSide = 16384;
constexpr int kMaxSamplesPerPixel = 1 << 20;
constexpr int kMaxTurntableFrames = 3600;

struct Options {
    QCommandLineParser parser;
    QCommandLineOption help {
        {QStringLiteral("h"), QStringLiteral("help")}, QStringLiteral("Displays this help.")};
    QCommandLineOption env {QStringLiteral("env"),
        QStringLiteral("Environment: an image path, a built-in name (studio, sky), an installed "
                       "CC0 sample's name (night: library:installed/hdri/night.exr), a library "
                       "reference or uniform:VALUE / uniform:R,G,B."),
        QStringLiteral("spec")};
    QCommandLineOption material {QStringLiteral("material"),
        QStringLiteral("A built-in material preset (e.g. gold)."), QStringLiteral("preset")};
    QCommandLineOption brdf {QStringLiteral("brdf"), QStringLiteral("BRDF composition: gltf or learnopengl."),
        QStringLiteral("name")};
    QCommandLineOption multiScatter {QStringLiteral("multiscatter"),
        QStringLiteral("Multiple-scattering energy compensation: on or off."), QStringLiteral("on|off")};
    QCommandLineOption mesh {QStringLiteral("mesh"), QStringLiteral("A built-in mesh name or a mesh file."),
        QStringLiteral("name|path")};
    QCommandLineOption view {QStringLiteral("view"),
        QStringLiteral("Debug view: %1.").arg(QString::fromStdString(debugViewNameList())),
        QStringLiteral("name")};
    QCommandLineOption size {
        QStringLiteral("size"), QStringLiteral("Image size, e.g. 512x512."), QStringLiteral("WxH")};
    QCommandLineOption referenceView {QStringLiteral("reference-view"),
        QStringLiteral("Use the reference view of docs/architecture.md (unit sphere, camera at "
                       "(0,0,3), 45 degree FOV).")};
    QCommandLineOption spp {QStringLiteral("spp"),
        QStringLiteral("Render with the CPU ground-truth integrator at N samples per pixel."),
        QStringLiteral("N")};
    QCommandLineOption quality {QStringLiteral("quality"),
        QStringLiteral("IBL quality preset: draft, default, high."), QStringLiteral("preset")};
    QCommandLineOption ibl {QStringLiteral("ibl"),
        QStringLiteral("How the surface integrates the environment: split-sum (real time), fis "
                       "(filtered importance sampling of each pixel's lobe) or reference (Monte "
                       "Carlo on the GPU, converging; see --ibl-samples)."),
        QStringLiteral("method")};
    QCommandLineOption iblSamples {QStringLiteral("ibl-samples"),
        QStringLiteral("Samples per pixel for --ibl fis (default %1) or reference (default %2).")
            .arg(kDefaultFisSamples)
            .arg(defaultIblSamples(IblMethod::Reference)),
        QStringLiteral("N")};
    QCommandLineOption stats {QStringLiteral("stats"), QStringLiteral("Print timings and work counters.")};
    QCommandLineOption scenario {QStringLiteral("scenario"),
        QStringLiteral("Render a glTF render-fidelity harness scenario: the JSON its offline renderers get, "
                       "{\"scenario\": {name, model, lighting, dimensions, target, orbit, verticalFoV, "
                       "renderSkybox}, \"outputFile\": PATH} (docs/fidelity.md). It gives the model, camera, "
                       "size, background, tone mapping and output."),
        QStringLiteral("json")};
    QCommandLineOption output {{QStringLiteral("o"), QStringLiteral("output")},
        QStringLiteral("Output image: .exr (linear radiance) or .png (display-referred); with --turntable "
                       "also a video, .mp4 or .webm (needs ffmpeg)."),
        QStringLiteral("file")};
    QCommandLineOption turntable {QStringLiteral("turntable"),
        QStringLiteral("Render N frames of a full turn (2 to %1): OUT_0000.png ... (a run of # in the name "
                       "is replaced by the frame number), or a video for a .mp4 or .webm output.")
            .arg(kMaxTurntableFrames),
        QStringLiteral("N")};
    QCommandLineOption turntableSubject {QStringLiteral("turntable-subject"),
        QStringLiteral("What turns: object (under fixed lighting and camera; the default) or environment."),
        QStringLiteral("what")};
    QCommandLineOption fps {QStringLiteral("fps"),
        QStringLiteral("Frames per second of a turntable video (1 to 120, default 30)."),
        QStringLiteral("F")};
    MaterialFlags materialFlags;
    SceneFlags scene;

    Options()
    {
        parser.setApplicationDescription(QStringLiteral(
            "Renders a project (or the built-in default) without a window or display server.\n"
            "EXR output is linear scene radiance with no tone mapping; PNG goes through the project's "
            "view transform. With --spp the CPU ground truth renders the reference view instead."));
        for (const QCommandLineOption* option : {&help, &env, &material})
            parser.addOption(*option);
        materialFlags.addTo(parser);
        for (const QCommandLineOption* option :
            {&brdf, &multiScatter, &mesh, &view, &size, &referenceView, &spp, &quality, &ibl, &iblSamples,
                &stats, &output, &scenario, &turntable, &turntableSubject, &fps})
            parser.addOption(*option);
        scene.addTo(parser);
        parser.addPositionalArgument(QStringLiteral("input"),
            QStringLiteral("A project file (JSON) or a glTF asset (.gltf, .glb) with its materials."),
            QStringLiteral("[PROJECT.json|ASSET.glb|ASSET.gltf]"));
    }
};

} // namespace

QString RenderCommand::helpText()
{
    Options options;
    return commandHelpText(options.parser, QStringLiteral("facet render"));
}

std::optional<RenderRequest> RenderCommand::parse(const QStringList& arguments, QString* error, int* exitCode)
{
    Options o;
    if (!parseCommandOptions(o, arguments, QStringLiteral("facet render"), kExitUsage, error, exitCode))
        return std::nullopt;

    RenderRequest request;
    const QStringList positional = o.parser.positionalArguments();
    if (!checkOneInput(positional, error))
        return std::nullopt;
    if (o.parser.isSet(o.scenario)) {
        // The scenario says what these would: one source for each.
        for (const QString& name :
            {QStringLiteral("output"), QStringLiteral("size"), QStringLiteral("reference-view"),
                QStringLiteral("spp"), QStringLiteral("camera-position"), QStringLiteral("camera-target"),
                QStringLiteral("fov"), QStringLiteral("keep-units"), QStringLiteral("turntable")})
            if (o.parser.isSet(name)) {
                *error = QStringLiteral("--scenario gives the model, camera, size and output: leave out --%1")
                             .arg(name);
                return std::nullopt;
            }
        if (!positional.isEmpty()) {
            *error = QStringLiteral("--scenario gives the model: leave out '%1'").arg(positional.first());
            return std::nullopt;
        }
        std::optional<RenderScenario> scenario = readRenderScenario(o.parser.value(o.scenario), error);
        if (!scenario)
            return std::nullopt;
        request.outputPath = scenario->outputPath;
        request.width = scenario->width;
        request.height = scenario->height;
        request.project = std::move(scenario->project);
    } else {
        const QString video = o.parser.value(o.output);
        if (o.parser.isSet(o.output) && isVideoPath(video.toStdString())) {
            if (!o.parser.isSet(o.turntable)) {
                *error = QStringLiteral("-o '%1': a video is a turntable's: add --turntable N").arg(video);
                return std::nullopt;
            }
            request.outputPath = video.toStdString();
        } else {
            const auto output = exrOrPngOutput(o.parser.isSet(o.output), o.parser.value(o.output),
                QStringLiteral("-o OUT.exr or -o OUT.png is required"),
                o.parser.isSet(o.turntable)
                    ? QStringLiteral(
                        "the output must be .exr, .png (numbered frames) or .mp4, .webm (a video)")
                    : QStringLiteral("the output must be .exr (linear radiance) or .png (display-referred)"),
                error);
            if (!output)
                return std::nullopt;
            request.outputPath = *output;
        }
        // The project: the file (a project, or a glTF asset with its own materials), or the
        // built-in default.
        auto input = commandInputProject(positional, QStringLiteral("render"), error);
        if (!input) {
            *exitCode = kExitFailure;
            return std::nullopt;
        }
        request.project = std::move(*input);
    }
    Project& project = request.project;
    // --material and the factor flags override every material of the project or asset.
    const auto everyMaterial = [&project](const auto& edit) {
        for (Material& material : project.materials)
            edit(material);
    };

    if (o.parser.isSet(o.env))
        project.environment.source = expandInstalledName(o.parser.value(o.env)).toStdString();
    if (o.parser.isSet(o.material)) {
        const QString id = o.parser.value(o.material);
        const MaterialPreset* preset = findPreset(id.toStdString());
        if (!preset) {
            QStringList ids;
            for (const MaterialPreset& p : builtinPresets())
                ids.append(QString::fromStdString(p.id));
            *error = QStringLiteral("--material: no preset '%1' (built-in: %2)")
                         .arg(id, ids.join(QStringLiteral(", ")));
            return std::nullopt;
        }
        everyMaterial([preset](Material& material) {
            const ShadingModel shading = material.shading;
            material = preset->material;
            material.shading = shading;
        });
    }
    std::vector<Material*> materials;
    for (Material& material : project.materials)
        materials.push_back(&material);
    if (!o.materialFlags.apply(o.parser, materials, error))
        return std::nullopt;
    if (o.parser.isSet(o.brdf)) {
        const QString name = o.parser.value(o.brdf);
        if (name != QStringLiteral("gltf") && name != QStringLiteral("learnopengl")) {
            *error = QStringLiteral("--brdf: '%1' is not gltf or learnopengl").arg(name);
            return std::nullopt;
        }
        const ShadingModel model
            = name == QStringLiteral("gltf") ? ShadingModel {} : ShadingModel::learnOpenGL();
        everyMaterial([&model](Material& material) {
            const bool multiScatter = material.shading.multiScatter;
            material.shading = model;
            material.shading.multiScatter = multiScatter;
        });
    }
    if (o.parser.isSet(o.multiScatter)) {
        const QString state = o.parser.value(o.multiScatter);
        if (state != QStringLiteral("on") && state != QStringLiteral("off")) {
            *error = QStringLiteral("--multiscatter: '%1' is not on or off").arg(state);
            return std::nullopt;
        }
        const bool on = state == QStringLiteral("on");
        everyMaterial([on](Material& material) { material.shading.multiScatter = on; });
    }
    if (o.parser.isSet(o.mesh))
        project.view.mesh = o.parser.value(o.mesh).toStdString();
    if (o.parser.isSet(o.view)) {
        const QString name = o.parser.value(o.view);
        const std::optional<DebugView> view = debugViewFromString(name.toStdString());
        if (!view) {
            *error = QStringLiteral("--view: unknown debug view '%1' (expected one of: %2)")
                         .arg(name, QString::fromStdString(debugViewNameList()));
            *exitCode = kExitUsage;
            return std::nullopt;
        }
        project.view.debugView = *view;
    }
    if (o.parser.isSet(o.quality)) {
        const auto quality = iblQualityFromString(o.parser.value(o.quality).toStdString());
        if (!quality) {
            *error = QStringLiteral("--quality: '%1' is not draft, default or high")
                         .arg(o.parser.value(o.quality));
            return std::nullopt;
        }
        project.environment.quality = *quality;
    }
    if (o.parser.isSet(o.ibl) || o.parser.isSet(o.iblSamples)) {
        if (o.parser.isSet(o.spp)) {
            *error = QStringLiteral(
                "--spp renders with the CPU ground truth; --ibl and --ibl-samples choose the GPU's "
                "method: give one or the other");
            return std::nullopt;
        }
        const QString method = o.parser.value(o.ibl);
        const QString samples = o.parser.value(o.iblSamples);
        if (!applyIblOptions(o.parser.isSet(o.ibl) ? &method : nullptr,
                o.parser.isSet(o.iblSamples) ? &samples : nullptr, project.environment, error))
            return std::nullopt;
    }
    if (o.parser.isSet(o.size)
        && !parseImageSize(QStringLiteral("size"), o.parser.value(o.size), 1, kMaxImageSide, &request.width,
            &request.height, error))
        return std::nullopt;
    request.referenceView = o.parser.isSet(o.referenceView);
    if (o.parser.isSet(o.spp)) {
        bool ok = false;
        const int spp = o.parser.value(o.spp).toInt(&ok);
        if (!ok || spp < 1 || spp > kMaxSamplesPerPixel) {
            *error = QStringLiteral("--spp: '%1' is not a whole number from 1 to %2")
                         .arg(o.parser.value(o.spp))
                         .arg(kMaxSamplesPerPixel);
            return std::nullopt;
        }
        request.samplesPerPixel = spp;
    }
    request.printStats = o.parser.isSet(o.stats);
    if (o.parser.isSet(o.turntable)) {
        if (request.samplesPerPixel > 0) {
            *error = QStringLiteral("--turntable renders with the GPU renderer: leave out --spp");
            return std::nullopt;
        }
        bool ok = false;
        request.turntableFrames = o.parser.value(o.turntable).toInt(&ok);
        if (!ok || request.turntableFrames < 2 || request.turntableFrames > kMaxTurntableFrames) {
            *error = QStringLiteral("--turntable: '%1' is not a whole number from 2 to %2")
                         .arg(o.parser.value(o.turntable))
                         .arg(kMaxTurntableFrames);
            return std::nullopt;
        }
    } else {
        for (const QCommandLineOption* option : {&o.turntableSubject, &o.fps})
            if (o.parser.isSet(*option)) {
                *error = QStringLiteral("--%1 belongs to a turntable: add --turntable N")
                             .arg(option->names().first());
                return std::nullopt;
            }
    }
    if (o.parser.isSet(o.turntableSubject)) {
        const auto subject = turntableSubjectFromString(o.parser.value(o.turntableSubject).toStdString());
        if (!subject) {
            *error = QStringLiteral("--turntable-subject: '%1' is not object or environment")
                         .arg(o.parser.value(o.turntableSubject));
            return std::nullopt;
        }
        request.turntableSubject = *subject;
    }
    if (o.parser.isSet(o.fps)) {
        bool ok = false;
        request.fps = o.parser.value(o.fps).toInt(&ok);
        if (!ok || request.fps < 1 || request.fps > 120) {
            *error = QStringLiteral("--fps: '%1' is not a whole number from 1 to 120")
                         .arg(o.parser.value(o.fps));
            return std::nullopt;
        }
    }
    if (!o.scene.apply(o.parser, project, {}, error))
        return std::nullopt;
    request.saveProjectPath = o.scene.saveProjectPath(o.parser).toStdString();

    std::string problem;
    if (!project.validate(&problem)) {
        *error = QString::fromStdString(problem);
        return std::nullopt;
    }
    *exitCode = 0;
    return request;
}

namespace {

// Whether the output keeps an alpha channel: over a transparent background, alpha is the object's
// coverage (EXR: premultiplied radiance, as OpenEXR stores it; PNG: straight, as PNG does).
bool keepsAlpha(const RenderRequest& request)
{
    return request.project.view.background == BackgroundMode::Transparent;
}

// Writes linear radiance as EXR, or the display transform of it as PNG.
bool writeOutput(const Image& radiance, const RenderRequest& request, std::string* error)
{
    const bool png
        = QFileInfo(QString::fromStdString(request.outputPath)).suffix().toLower() == QStringLiteral("png");
    if (!png)
        return radiance.save(request.outputPath, error, keepsAlpha(request));
    Image display(radiance.width(), radiance.height());
    for (int y = 0; y < radiance.height(); ++y)
        for (int x = 0; x < radiance.width(); ++x) {
            const glm::vec4 pixel = radiance.at(x, y);
            const float alpha = keepsAlpha(request) ? pixel.a : 1.0f;
            const glm::dvec3 straight
                = alpha > 0.0f ? glm::dvec3(glm::vec3(pixel)) / double(alpha) : glm::dvec3(0.0);
            const glm::dvec3 c = tonemap::displayTransform(straight, request.project.view);
            display.at(x, y) = glm::vec4(glm::vec3(c), alpha);
        }
    display.setEncoding(ColorEncoding::SRGB);
    return display.save(request.outputPath, error, keepsAlpha(request));
}

int runGroundTruth(const RenderRequest& request)
{
    const Project& project = request.project;
    if (project.view.mesh != "sphere") {
        std::fprintf(stderr, "facet render: --spp renders the reference sphere only, not mesh '%s'\n",
            project.view.mesh.c_str());
        return RenderCommand::kExitUsage;
    }
    if (project.view.debugView != DebugView::None) {
        std::fprintf(stderr, "facet render: --spp renders the shaded image only, not debug view '%s'\n",
            toString(project.view.debugView));
        return RenderCommand::kExitUsage;
    }
    std::string error;
    std::string warning;
    auto scene = groundTruthSceneFromProject(project, &error, &warning);
    if (!warning.empty())
        std::fprintf(stderr, "facet render: %s\n", warning.c_str());
    if (!scene) {
        std::fprintf(stderr, "facet render: %s\n", error.c_str());
        return RenderCommand::kExitFailure;
    }
    GroundTruthSettings settings;
    settings.width = request.width;
    settings.height = request.height;
    settings.samplesPerPixel = request.samplesPerPixel;
    GroundTruthStats stats;
    const Image image = renderGroundTruth(*scene, settings, &stats);
    if (!writeOutput(image, request, &error)) {
        std::fprintf(stderr, "facet render: %s\n", error.c_str());
        return RenderCommand::kExitFailure;
    }
    if (request.printStats)
        std::printf("renderer: ground truth (CPU)\nsize: %dx%d\nspp: %d\nsamples: %llu\ntime_ms: %.1f\n",
            request.width, request.height, request.samplesPerPixel,
            static_cast<unsigned long long>(stats.samples), stats.seconds * 1000.0);
    return 0;
}

// --turntable N: each frame the prepared scene turned (render/Turntable.h), written as numbered
// files, or for a video as PNG frames in a temporary folder that ffmpeg encodes.
int renderTurntable(FrameRenderer& frames, const RenderScene& scene, const RenderRequest& request)
{
    const bool png = isVideoPath(request.outputPath)
        || QFileInfo(QString::fromStdString(request.outputPath)).suffix().toLower() == QStringLiteral("png");
    std::string error;
    const std::optional<TurntableWrite> written = writeTurntable(
        request.outputPath, request.turntableFrames, request.fps, keepsAlpha(request),
        [&](int, double degrees, std::string* frameError) {
            RenderScene turned = scene;
            applyTurntable(turned, request.turntableSubject, degrees);
            return frames.renderConverged(turned, request.width, request.height,
                png ? FrameOutput::DisplayReferred : FrameOutput::LinearRadiance, turned.sampling.samples,
                frameError);
        },
        &error);
    if (!written) {
        std::fprintf(stderr, "facet render: %s\n", error.c_str());
        return RenderCommand::kExitFailure;
    }
    if (request.printStats)
        std::printf(
            "turntable: %d frames, %s turning, %dx%d\nturntable_ms: %.1f a frame, render %.1f, encode %.1f\n",
            request.turntableFrames, toString(request.turntableSubject), request.width, request.height,
            written->renderSeconds * 1000.0 / double(request.turntableFrames),
            written->renderSeconds * 1000.0, written->encodeSeconds * 1000.0);
    return 0;
}

int runGpu(const RenderRequest& request)
{
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const Project& project = request.project;
    std::string error;
    std::string warning;
    // A video needs ffmpeg: said before any work.
    if (request.turntableFrames > 0 && isVideoPath(request.outputPath) && findFfmpeg().empty()) {
        const QFileInfo video(QString::fromStdString(request.outputPath));
        const std::string frames = "-o "
            + video.dir().filePath(video.completeBaseName() + QStringLiteral("_####.png")).toStdString();
        std::fprintf(stderr, "facet render: %s\n", missingFfmpegAdvice(request.outputPath, frames).c_str());
        return RenderCommand::kExitFailure;
    }
    auto assets = loadProjectAssets(project, &error, &warning);
    if (!warning.empty())
        std::fprintf(stderr, "facet render: %s\n", warning.c_str());
    if (!assets) {
        std::fprintf(stderr, "facet render: %s\n", error.c_str());
        return RenderCommand::kExitFailure;
    }
    const auto loaded = Clock::now();

    // A surfaceless EGL context: no display server needed (docs/architecture.md, "OpenGL without a display").
    auto context = HeadlessGLContext::create(&error);
    if (!context) {
        std::fprintf(stderr, "facet render: %s\n", error.c_str());
        return RenderCommand::kExitFailure;
    }
    const auto contextMade = Clock::now();
    const IblSettings settings = IblSettings::preset(project.environment.quality);
    int exitCode = 0;
    {
        FrameRenderer frames;
        IblStats iblStats;
        const std::optional<RenderScene> scene = frames.prepare(
            project, *assets, settings, sceneOptionsFor(settings, request.referenceView), &iblStats, &error);
        if (!scene) {
            std::fprintf(stderr, "facet render: %s\n", error.c_str());
            return RenderCommand::kExitFailure;
        }
        if (!frames.precompute().lastWarning().empty())
            std::fprintf(stderr, "facet render: %s\n", frames.precompute().lastWarning().c_str());
        const auto prepared = Clock::now();

        if (request.turntableFrames > 0)
            return renderTurntable(frames, *scene, request);
        Renderer& renderer = frames.renderer();
        renderer.setTimingEnabled(request.printStats);
        const bool png = QFileInfo(QString::fromStdString(request.outputPath)).suffix().toLower()
            == QStringLiteral("png");
        // The noise estimate of a reference render covers the interior sphere pixels in the
        // reference view (the pixels the accuracy metric reads), else every pixel.
        const PixelMask noiseMask
            = request.referenceView ? sphereMask(request.width, request.height) : PixelMask {};
        FrameRenderer::ConvergedStats converged;
        const std::optional<Image> image = frames.renderConverged(*scene, request.width, request.height,
            png ? FrameOutput::DisplayReferred : FrameOutput::LinearRadiance, scene->sampling.samples, &error,
            &converged, noiseMask);
        if (!image) {
            std::fprintf(stderr, "facet render: %s\n", error.c_str());
            return RenderCommand::kExitFailure;
        }
        const auto rendered = Clock::now();
        if (!image->save(request.outputPath, &error, keepsAlpha(request))) {
            std::fprintf(stderr, "facet render: %s\n", error.c_str());
            exitCode = RenderCommand::kExitFailure;
        }
        const auto written = Clock::now();
        if (const std::vector<MapSlot>& leftOut = renderer.lastFrameMapsLeftOut(); !leftOut.empty()) {
            std::string names;
            for (const MapSlot slot : leftOut)
                names += (names.empty() ? "" : ", ") + std::string(toString(slot));
            std::fprintf(stderr,
                "facet render: warning: the GPU's texture units (%d for maps) hold too few of the "
                "material's textures: %s shaded by %s factor alone (docs/limits.md)\n",
                renderer.mapUnits(), names.c_str(), leftOut.size() == 1 ? "its" : "their");
        }
        if (request.printStats) {
            const RenderStats& frame = renderer.lastFrameStats();
            const GLInfo& gl = context->info();
            std::printf("renderer: gpu\ngl: %s\ngl_renderer: %s\nsize: %dx%d\nquality: %s\n",
                gl.version.c_str(), gl.renderer.c_str(), request.width, request.height,
                toString(project.environment.quality));
            std::printf("ibl_method: %s\n", toString(project.environment.method));
            if (project.environment.method != IblMethod::SplitSum) {
                std::printf("ibl_samples: %d\ndraws: %d\nconverge_ms: %.1f\n", converged.samples,
                    converged.draws, converged.seconds * 1000.0);
                if (converged.noise)
                    std::printf("noise: %.5f\n", *converged.noise);
            }
            std::printf("load_ms: %.1f\n", std::chrono::duration<double, std::milli>(loaded - start).count());
            std::printf("ibl_passes_run: %d\nibl_cache_hits_memory: %d\nibl_cache_hits_disk: %d\n"
                        "ibl_dfg_shipped: %d\n",
                iblStats.passesRun, iblStats.cacheHitsMemory, iblStats.cacheHitsDisk, iblStats.dfgShipped);
            std::printf(
                "ibl_ms: %.1f (equirect_to_cube %.1f, prefilter %.1f, irradiance %.1f, dfg %.1f, sh %.1f)\n",
                iblStats.msTotal, iblStats.msEquirectToCube, iblStats.msPrefilter, iblStats.msIrradiance,
                iblStats.msDfg, iblStats.msSh);
            std::printf("programs_compiled: %d\ntextures_uploaded: %d\nmeshes_uploaded: %d\ndraw_calls: %d\n",
                frame.programsCompiled, frame.texturesUploaded, frame.meshesUploaded, frame.drawCalls);
            std::printf("frame_ms: upload %.1f, surface %.1f, background %.1f, resolve %.1f, tone_map %.1f\n",
                frame.uploadMs, frame.surfaceMs, frame.backgroundMs, frame.resolveMs, frame.toneMapMs);
            // Where the command's time went, in order: reading the project and its files, making the
            // GL context, preparing the scene (IBL, shaders, uploads), drawing with the read-back and
            // the display transform, encoding and writing the file.
            const auto ms = [](Clock::time_point from, Clock::time_point to) {
                return std::chrono::duration<double, std::milli>(to - from).count();
            };
            std::printf("stages_ms: load %.1f, context %.1f, prepare %.1f, render %.1f, write %.1f\n",
                ms(start, loaded), ms(loaded, contextMade), ms(contextMade, prepared), ms(prepared, rendered),
                ms(rendered, written));
            std::printf(
                "total_ms: %.1f\n", std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        }
    }
    return exitCode;
}

} // namespace

int RenderCommand::run(const RenderRequest& request)
{
    if (!request.saveProjectPath.empty()) {
        std::string error;
        if (!request.project.save(request.saveProjectPath, &error)) {
            std::fprintf(stderr, "facet render: --save-project: %s\n", error.c_str());
            return kExitFailure;
        }
    }
    if (request.samplesPerPixel > 0)
        return runGroundTruth(request);
    return runGpu(request);
}

} // namespace facet
