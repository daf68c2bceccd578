// The DamagedHelmet-like case of issue 8, "Fast with real maps": five 2048² 8-bit maps (base
// colour sRGB JPEG, normal PNG, packed metallic-roughness JPEG, grey occlusion JPEG, emissive
// JPEG; smooth noise written with OpenImageIO, so that the encoded sizes are realistic) on the
// sphere at 1280x720 on whatever OpenGL this machine has. Prints numbers; checks nothing
// (docs/benchmarks.md, "Texture maps", has the measured values and how they were taken).
//
//   texture_maps [--maps DIR] [--frames N]      headless part, then the window part in a child
//   texture_maps --window --maps DIR             the window part only (needs a display)
//
// Headless (surfaceless EGL): decode time and memory of each map (MapImage, and the float RGBA
// Image they used to be kept as), the upload of each (whole, and in the window's 20 ms slices),
// and full 1280x720 frames (render + tone map, glFinish) of the untextured sphere against the
// textured one at each anisotropy level.
// Window (a fresh process, so that its memory is the window's alone; run it under
// tests/with-display.sh): the main window opens the project of the five maps; printed are the
// time to the first frame that shows every map (full resolution, nothing held back), the
// longest event-loop stall while the set loads (a 1 ms timer's longest gap, with and without a
// frame drawn in it), the window's full-resolution frame times, and VmRSS / VmHWM. Twice: with
// an empty IBL disk cache, then with the cache it left.

// epoxy before any Qt GL header (ui/viewport/ViewportWidget.h brings Qt's): the two must not meet otherwise.
#include <epoxy/gl.h>

#include "BenchStats.h"
#include "core/image/Image.h"
#include "core/image/MapImage.h"
#include "core/image/MapImageCache.h"
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
#include "render/TextureCache.h"
#include "render/TextureFiltering.h"
#include "ui/MainWindow.h"
#include "ui/document/Document.h"
#include "ui/document/ProjectFileController.h"
#include "ui/viewport/MapUploadScheduler.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportWidget.h"

#include <OpenImageIO/imageio.h>

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <set>
#include <string>
#include <vector>

using namespace facet;
using facet::bench::median;

namespace {

constexpr int kMapSize = 2048;
constexpr int kWidth = 1280;
constexpr int kHeight = 720;

// Smooth value noise in [0, 1]: octaves of bilinearly interpolated (smoothstep) lattice values,
// periods 512 down to 16 texels, tileable, plus a little per-texel grain as photographs have.
struct Noise {
    std::uint32_t seed;
    static std::uint32_t hash(std::uint32_t x)
    {
        x ^= x >> 16;
        x *= 0x7feb352dU;
        x ^= x >> 15;
        x *= 0x846ca68bU;
        x ^= x >> 16;
        return x;
    }
    double lattice(int x, int y, int period) const
    {
        const int cells = kMapSize / period;
        x = ((x % cells) + cells) % cells;
        y = ((y % cells) + cells) % cells;
        return double(hash(seed
                   ^ hash(
                       std::uint32_t(x) * 73856093U ^ std::uint32_t(y) * 19349663U ^ std::uint32_t(period))))
            / 4294967295.0;
    }
    double at(int x, int y) const
    {
        double sum = 0.0;
        double weight = 0.5;
        double total = 0.0;
        for (int period = 512; period >= 16; period /= 2) {
            const double fx = double(x) / period;
            const double fy = double(y) / period;
            const int x0 = int(std::floor(fx));
            const int y0 = int(std::floor(fy));
            const auto smooth = [](double t) { return t * t * (3.0 - 2.0 * t); };
            const double tx = smooth(fx - x0);
            const double ty = smooth(fy - y0);
            const double a = lattice(x0, y0, period) * (1 - tx) + lattice(x0 + 1, y0, period) * tx;
            const double b = lattice(x0, y0 + 1, period) * (1 - tx) + lattice(x0 + 1, y0 + 1, period) * tx;
            sum += weight * (a * (1 - ty) + b * ty);
            total += weight;
            weight *= 0.6;
        }
        const double grain
            = (double(hash(seed ^ std::uint32_t(y * kMapSize + x))) / 4294967295.0 - 0.5) * 0.03;
        return std::clamp(sum / total + grain, 0.0, 1.0);
    }
};

bool writeMap(const std::string& path, int channels, const std::function<glm::dvec4(int, int)>& texel)
{
    std::vector<unsigned char> pixels(std::size_t(kMapSize) * kMapSize * std::size_t(channels));
    for (int y = 0; y < kMapSize; ++y)
        for (int x = 0; x < kMapSize; ++x) {
            const glm::dvec4 v = texel(x, y);
            for (int c = 0; c < channels; ++c)
                pixels[(std::size_t(y) * kMapSize + std::size_t(x)) * std::size_t(channels) + std::size_t(c)]
                    = static_cast<unsigned char>(std::lround(std::clamp(v[c], 0.0, 1.0) * 255.0));
        }
    auto output = OIIO::ImageOutput::create(path);
    if (!output)
        return false;
    OIIO::ImageSpec spec(kMapSize, kMapSize, channels, OIIO::TypeDesc::UINT8);
    spec.attribute("Compression", "jpeg:90");
    return output->open(path, spec) && output->write_image(OIIO::TypeDesc::UINT8, pixels.data())
        && output->close();
}

struct MapFile {
    const char* name;
    MapSlot slot;
    MapChannel channel;
    ColorEncoding colorSpace;
};
const std::vector<MapFile>& mapFiles()
{
    static const std::vector<MapFile> files = {
        {"helmet_basecolor.jpg", MapSlot::BaseColor, MapChannel::Rgb, ColorEncoding::SRGB},
        {"helmet_normal.png", MapSlot::Normal, MapChannel::Rgb, ColorEncoding::Linear},
        {"helmet_metalRoughness.jpg", MapSlot::Roughness, MapChannel::G, ColorEncoding::Linear},
        {"helmet_metalRoughness.jpg", MapSlot::Metallic, MapChannel::B, ColorEncoding::Linear},
        {"helmet_ao.jpg", MapSlot::Occlusion, MapChannel::R, ColorEncoding::Linear},
        {"helmet_emissive.jpg", MapSlot::Emissive, MapChannel::Rgb, ColorEncoding::SRGB},
    };
    return files;
}

bool writeMaps(const QString& folder)
{
    const auto path
        = [&](const char* name) { return (folder + QLatin1Char('/') + QLatin1String(name)).toStdString(); };
    const Noise a {1}, b {2}, c {3}, d {4};
    bool ok = writeMap(path("helmet_basecolor.jpg"), 3, [&](int x, int y) {
        const double t = a.at(x, y);
        return glm::dvec4(0.25 + 0.6 * t, 0.2 + 0.5 * b.at(x, y), 0.15 + 0.4 * t * c.at(x, y), 1.0);
    });
    ok = ok && writeMap(path("helmet_normal.png"), 3, [&](int x, int y) {
        const double dx = d.at(x + 1, y) - d.at(x - 1, y);
        const double dy = d.at(x, y + 1) - d.at(x, y - 1);
        const glm::dvec3 n = glm::normalize(glm::dvec3(-dx * 20.0, -dy * 20.0, 1.0));
        return glm::dvec4(n * 0.5 + 0.5, 1.0);
    });
    ok = ok && writeMap(path("helmet_metalRoughness.jpg"), 3, [&](int x, int y) {
        return glm::dvec4(0.0, 0.2 + 0.7 * b.at(x, y), c.at(x, y) > 0.5 ? 1.0 : 0.0, 1.0);
    });
    ok = ok && writeMap(path("helmet_ao.jpg"), 1, [&](int x, int y) {
        return glm::dvec4(0.6 + 0.4 * a.at(x, y));
    });
    ok = ok && writeMap(path("helmet_emissive.jpg"), 3, [&](int x, int y) {
        const double glow = std::max(0.0, d.at(x, y) - 0.62) * 4.0;
        return glm::dvec4(glow, glow * 0.8, glow * 0.3, 1.0);
    });
    return ok;
}

Project helmetProject(const QString& folder, bool textured)
{
    Project project = Project::defaultProject();
    project.view.mesh = "sphere";
    if (!textured)
        return project;
    Material& material = project.material();
    for (const MapFile& file : mapFiles()) {
        MaterialMap& map = material.map(file.slot);
        map.path = (folder + QLatin1Char('/') + QLatin1String(file.name)).toStdString();
        map.channel = file.channel;
        map.colorSpace = file.colorSpace;
    }
    material.setBaseColor(glm::dvec3(1.0));
    material.setFactor(MapSlot::Metallic, 1.0);
    material.setFactor(MapSlot::Roughness, 1.0);
    material.map(MapSlot::Emissive).factor = glm::dvec4(1.0);
    return project;
}

double msSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// CPU time of the whole process (every thread: llvmpipe rasterises on its own), in ms. Less
// disturbed than the wall clock by other work on a shared machine.
double cpuMilliseconds()
{
    timespec t {};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

std::string statusField(const char* field)
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return "?";
    for (const QByteArray& line : status.readAll().split('\n'))
        if (line.startsWith(field))
            return line.mid(int(std::strlen(field))).trimmed().toStdString();
    return "?";
}

int runHeadless(const QString& folder, int frames)
{
    std::string error;
    std::printf("maps: five 2048x2048 8-bit files in %s\n\n", qPrintable(folder));
    std::printf("| file | bytes on disk | MapImage | in memory | load ms (min of 3) | float RGBA Image | in "
                "memory | load ms |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    std::vector<std::string> seen;
    for (const MapFile& file : mapFiles()) {
        const std::string path = (folder + QLatin1Char('/') + QLatin1String(file.name)).toStdString();
        if (std::find(seen.begin(), seen.end(), path) != seen.end())
            continue;
        seen.push_back(path);
        double mapMs = 1e9;
        double imageMs = 1e9;
        std::optional<MapImage> map;
        std::optional<Image> image;
        for (int i = 0; i < 3; ++i) {
            auto start = std::chrono::steady_clock::now();
            map = MapImage::load(path, &error);
            mapMs = std::min(mapMs, msSince(start));
            if (!map) {
                std::fprintf(stderr, "texture_maps: %s\n", error.c_str());
                return 1;
            }
            start = std::chrono::steady_clock::now();
            image = Image::load(path, &error);
            imageMs = std::min(imageMs, msSince(start));
        }
        std::printf("| %s | %lld | %s %s | %.1f MiB | %.1f | RGBA32F | %.1f MiB | %.1f |\n", file.name,
            (long long)QFileInfo(QString::fromStdString(path)).size(), toString(map->sampleType()),
            toString(map->layout()), double(map->byteSize()) / 1048576.0, mapMs,
            double(image->pixelCount() * sizeof(glm::vec4)) / 1048576.0, imageMs);
    }

    auto context = HeadlessGLContext::create(&error);
    if (!context) {
        std::fprintf(stderr, "texture_maps: %s\n", error.c_str());
        return 1;
    }
    const GLInfo info = queryCurrentGLInfo();
    std::printf("\nGL: %s (software rasteriser: %s, max anisotropy %.0f)\n", info.summary().c_str(),
        info.softwareRasterizer ? "yes" : "no", double(info.maxAnisotropy));

    const Project textured = helmetProject(folder, true);
    const auto assets = loadProjectAssets(textured, &error);
    if (!assets) {
        std::fprintf(stderr, "texture_maps: %s\n", error.c_str());
        return 1;
    }

    // Uploads: each distinct texture whole (get), then in 20 ms slices as the window does.
    {
        std::printf("\n| texture | GL format | whole upload + mipmaps ms | in 20 ms slices: slices | longest "
                    "ms | total ms |\n");
        std::printf("|---|---|---|---|---|---|\n");
        Renderer renderer; // (owns a TextureCache; its construction needs the context)
        TextureCache& cache = renderer.textureCache();
        for (const MapFile& file : mapFiles()) {
            if (file.slot == MapSlot::Metallic)
                continue; // the same texture as roughness
            const LoadedMapImage& loaded = assets->maps[0][std::size_t(file.slot)];
            glFinish();
            auto start = std::chrono::steady_clock::now();
            bool uploaded = false;
            cache.get(loaded.image, loaded.path + "#whole", 1, file.colorSpace, &uploaded);
            glFinish();
            const double wholeMs = msSince(start);
            cache.request(loaded.image, loaded.path + "#sliced", 1, file.colorSpace);
            int slices = 0;
            double longest = 0.0;
            double total = 0.0;
            while (cache.hasPendingUploads()) {
                const TextureCache::SliceResult slice = cache.uploadSlice(20.0);
                ++slices;
                longest = std::max(longest, slice.milliseconds);
                total += slice.milliseconds;
            }
            const MapTextureFormat format
                = MapTextureFormat::of(loaded.image->layout(), loaded.image->sampleType(), file.colorSpace);
            std::printf("| %s | %s | %.1f | %d | %.1f | %.1f |\n", file.name, format.name, wholeMs, slices,
                longest, total);
        }
    }

    // Frames: untextured sphere against the textured one, at each anisotropy level. Every
    // configuration has its own FrameRenderer (its own textures), all sharing one precompute.
    const auto precompute = std::make_shared<IblPrecompute>();
    FrameRenderer lightingSource(precompute);
    const auto settings = IblSettings::preset("default");
    IblStats iblStats;
    const auto ibl = lightingSource.lighting(assets->environment, *settings, &iblStats, &error);
    if (!ibl) {
        std::fprintf(stderr, "texture_maps: %s\n", error.c_str());
        return 1;
    }
    auto display = Framebuffer::create(kWidth, kHeight, FramebufferFormat::RGBA16F, &error);
    if (!display) {
        std::fprintf(stderr, "texture_maps: %s\n", error.c_str());
        return 1;
    }
    // Every configuration has its own renderer (its textures uploaded in the warm-up frames); the
    // configurations take turns, frame by frame, so that a neighbour's load on the machine falls
    // on all of them alike. Printed: the fastest and the median frame of each.
    struct Config {
        std::string name;
        float anisotropy = 1.0f;
        std::unique_ptr<FrameRenderer> frames;
        bool trilinear = true;
        RenderScene scene;
        std::vector<double> times;
        std::vector<double> cpu; // process CPU time (llvmpipe's threads included) per frame
    };
    const float defaultLevel = TextureFiltering::setting(info);
    std::vector<Config> configs;
    const auto addConfig = [&](const std::string& name, const Project& project, float anisotropy) {
        const auto projectAssets = loadProjectAssets(project, &error);
        if (!projectAssets)
            return false;
        Config config {name, anisotropy, std::make_unique<FrameRenderer>(precompute), true, {}, {}, {}};
        config.trilinear = TextureFiltering::trilinear(info);
        auto scene = config.frames->prepare(
            project, *projectAssets, *settings, sceneOptionsFor(*settings, false), nullptr, &error);
        if (!scene)
            return false;
        config.scene = std::move(*scene);
        configs.push_back(std::move(config));
        return true;
    };
    bool ok = addConfig("untextured sphere", helmetProject(folder, false), 1.0f);
    // The same shader with 4 x 4 maps: what the textured variant's shading costs without the
    // fetches from large textures.
    ok = ok && addConfig("five 4x4 maps", textured, 1.0f);
    if (ok)
        for (RenderMapImage& map : configs.back().scene.materials[0].maps)
            if (map.image) {
                auto tiny = std::make_shared<MapImage>(4, 4, map.image->layout(), map.image->sampleType());
                for (int y = 0; y < 4; ++y)
                    for (int x = 0; x < 4; ++x)
                        for (int c = 0; c < tiny->channels(); ++c)
                            tiny->setSample(x, y, c, map.image->sample(x * 512, y * 512, c));
                map.image = tiny;
                map.path += "#4x4";
            }
    // Each map alone (its 2K file, default filtering): what each fetch costs.
    for (const MapFile& file : mapFiles()) {
        if (!ok)
            break;
        Project one = helmetProject(folder, true);
        for (int i = 0; i < kMapSlotCount; ++i)
            if (MapSlot(i) != file.slot)
                one.material().map(MapSlot(i)).path.clear();
        ok = addConfig(std::string("only ") + toString(file.slot), one, defaultLevel);
    }
    for (float level : {1.0f, 2.0f, 4.0f, 8.0f, 16.0f})
        if (level <= info.maxAnisotropy)
            ok = ok && addConfig("five 2K maps", textured, level);
    // The defaults but the other mip filter, and the packed metallic-roughness file fetched once
    // per slot (a copy of it for roughness) instead of once for both.
    ok = ok && addConfig("five 2K maps", textured, defaultLevel);
    if (ok)
        configs.back().trilinear = !configs.back().trilinear;
    // What packing occlusion into the metallic-roughness texture would give: four fetches.
    ok = ok
        && addConfig("five 2K maps, occlusion read from the metallic-roughness file", textured, defaultLevel);
    if (ok) {
        RenderMaterial& material = configs.back().scene.materials[0];
        const auto metallic = std::size_t(MapSlot::Metallic);
        const auto occlusion = std::size_t(MapSlot::Occlusion);
        material.maps[occlusion] = material.maps[metallic];
        material.material.maps[occlusion].path = material.material.maps[metallic].path;
        material.material.maps[occlusion].channel = MapChannel::R;
    }
    ok = ok && addConfig("five 2K maps, metallic and roughness fetched apart", textured, defaultLevel);
    if (ok) {
        RenderMapImage& roughness = configs.back().scene.materials[0].maps[std::size_t(MapSlot::Roughness)];
        roughness.image = std::make_shared<MapImage>(*roughness.image);
        roughness.path += "#copy";
    }
    for (int round = 0; ok && round < frames + 2; ++round)
        for (Config& config : configs) {
            config.frames->textureCache().setMaxAnisotropy(config.anisotropy);
            config.frames->textureCache().setTrilinear(config.trilinear);
            glFinish();
            const auto start = std::chrono::steady_clock::now();
            const double cpuStart = cpuMilliseconds();
            ok = ok
                && config.frames->present(
                    config.scene, display->framebufferId(), FrameRect {0, 0, kWidth, kHeight}, 1.0, &error);
            glFinish();
            if (round >= 2) { // the first frames compile and upload
                config.times.push_back(msSince(start));
                config.cpu.push_back(cpuMilliseconds() - cpuStart);
            }
        }
    if (!ok) {
        std::fprintf(stderr, "texture_maps: %s\n", error.c_str());
        return 1;
    }
    std::printf("\nfull frames %dx%d (render + tone map, glFinish), %d each, taking turns:\n\n", kWidth,
        kHeight, frames);
    std::printf(
        "| scene | filtering | fastest ms | median ms | / untextured | median CPU ms | / untextured |\n"
        "|---|---|---|---|---|---|---|\n");
    const double untextured = median(configs[0].times);
    const double untexturedCpu = median(configs[0].cpu);
    const bool defaultTrilinear = TextureFiltering::trilinear(info);
    for (const Config& config : configs) {
        const bool isDefault = config.anisotropy == defaultLevel && config.trilinear == defaultTrilinear;
        const std::string filtering = config.name == "untextured sphere"
            ? std::string("-")
            : std::to_string(int(config.anisotropy)) + "x, "
                + (config.trilinear ? "trilinear" : "nearest mip") + (isDefault ? " (default here)" : "");
        std::printf("| %s | %s | %.1f | %.1f | %.2f | %.1f | %.2f |\n", config.name.c_str(),
            filtering.c_str(), bench::fastest(config.times), median(config.times),
            median(config.times) / untextured, median(config.cpu), median(config.cpu) / untexturedCpu);
    }
    return 0;
}

void pump(int milliseconds)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < milliseconds)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 5);
}

// The window part: see the top of the file. `openAtStart`: the project is opened as the window
// is made (`facet helmet.json`, the new user's case; the clock runs from the process start);
// otherwise the window first shows the default project, settles, and then opens it (File > Open).
int runWindow(const QString& projectPath, bool openAtStart, const QElapsedTimer& processClock)
{
    MainWindow window(nullptr, QDir::temp().filePath(QStringLiteral("facet-bench-recovery")));
    window.resize(1600, 1000);
    ViewportWidget* viewport = window.viewport();

    // The event loop's longest stall: the gaps between a 1 ms timer's ticks, and whether a frame
    // was drawn within the gap.
    struct Gap {
        double ms = 0.0;
        bool frame = false;
    };
    std::vector<Gap> gaps;
    QElapsedTimer ticks;
    std::uint64_t framesAtTick = 0;
    QTimer monitor;
    monitor.setTimerType(Qt::PreciseTimer);
    monitor.setInterval(1);
    QObject::connect(&monitor, &QTimer::timeout, [&] {
        const double ms = double(ticks.nsecsElapsed()) / 1e6;
        ticks.start();
        gaps.push_back(Gap {ms, viewport->frameCount() != framesAtTick});
        framesAtTick = viewport->frameCount();
    });

    double firstLitMs = -1.0;
    std::uint64_t firstLitFrame = 0;
    std::vector<double> loadFrames;
    bool opened = false;
    QElapsedTimer sinceOpen;
    QObject::connect(viewport, &ViewportWidget::frameRendered, [&] {
        if (!opened || firstLitMs >= 0.0)
            return;
        const ViewportFrameStats& stats = viewport->lastFrameStats();
        loadFrames.push_back(stats.frameMs + stats.iblMs);
        const SceneController* scene = window.sceneController();
        bool allMaps = scene->pendingMapLoads() == 0 && !scene->assets().maps.empty();
        for (const MapFile& file : mapFiles())
            allMaps = allMaps && scene->assets().maps[0][std::size_t(file.slot)].image != nullptr;
        if (allMaps && stats.mapsHeldBack == 0 && !stats.reduced) {
            firstLitMs = double(sinceOpen.nsecsElapsed()) / 1e6;
            firstLitFrame = stats.frameNumber;
        }
    });

    double openReturnedMs = 0.0;
    int pendingAtReturn = 0;
    const auto open = [&] {
        ticks.start();
        framesAtTick = viewport->frameCount();
        monitor.start();
        sinceOpen.start();
        opened = true;
        if (!window.projectFiles()->openFile(projectPath))
            return false;
        openReturnedMs = double(sinceOpen.nsecsElapsed()) / 1e6;
        pendingAtReturn = window.sceneController()->pendingMapLoads();
        return true;
    };
    if (openAtStart) {
        if (!open()) {
            std::fprintf(stderr, "texture_maps: could not open %s\n", qPrintable(projectPath));
            return 1;
        }
        window.show();
    } else {
        window.show();
        QElapsedTimer clock;
        clock.start();
        while (viewport->frameCount() == 0 && clock.elapsed() < 120000)
            QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
        std::printf("  the default project's first frame %lld ms after the process started\n",
            (long long)processClock.elapsed());
        pump(1500);
        std::printf("  memory with the default project shown: VmRSS %s, VmHWM %s\n",
            statusField("VmRSS:").c_str(), statusField("VmHWM:").c_str());
        if (!open()) {
            std::fprintf(stderr, "texture_maps: could not open %s\n", qPrintable(projectPath));
            return 1;
        }
    }
    while (firstLitMs < 0.0 && sinceOpen.elapsed() < 120000)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 5);
    pump(300); // what follows the first lit frame (nothing: frames are drawn on demand)
    monitor.stop();
    if (firstLitMs < 0.0) {
        std::fprintf(stderr, "texture_maps: the maps never showed\n");
        return 1;
    }
    double longest = 0.0;
    double longestWithoutFrame = 0.0;
    for (const Gap& gap : gaps) {
        longest = std::max(longest, gap.ms);
        if (!gap.frame)
            longestWithoutFrame = std::max(longestWithoutFrame, gap.ms);
    }
    std::printf(
        "  open returned after %.1f ms with %d map files still decoding\n", openReturnedMs, pendingAtReturn);
    if (openAtStart)
        std::printf("  first lit frame (every map shown, full resolution): %.0f ms after the process started "
                    "(%.0f ms after the open), frame %llu\n",
            double(processClock.nsecsElapsed()) / 1e6 - (double(sinceOpen.nsecsElapsed()) / 1e6 - firstLitMs),
            firstLitMs, (unsigned long long)firstLitFrame);
    else
        std::printf(
            "  first lit frame (every map shown, full resolution): %.0f ms after the open, frame %llu\n",
            firstLitMs, (unsigned long long)firstLitFrame);
    std::printf("  frames until then: %zu (ms each, IBL included:", loadFrames.size());
    for (double ms : loadFrames)
        std::printf(" %.0f", ms);
    std::printf(")\n");
    std::printf("  longest event-loop stall from the open to the first lit frame + 300 ms: %.1f ms; "
                "without a frame drawn in it: %.1f ms\n",
        longest, longestWithoutFrame);
    std::printf("  map uploads: %d slices, the longest %.1f ms\n", viewport->mapUploads()->slices(),
        viewport->mapUploads()->longestSliceMs());
    std::printf("  stalls over 50 ms (ms from the open: length, F = a frame in it):");
    double at = 0.0;
    for (const Gap& gap : gaps) {
        at += gap.ms;
        if (gap.ms > 50.0)
            std::printf(" %.0f: %.0f%s", at - gap.ms, gap.ms, gap.frame ? " F" : "");
    }
    std::printf("\n");

    // Full-resolution frames of the loaded set in the window.
    std::vector<double> full;
    for (int i = 0; i < 5; ++i) {
        const std::uint64_t before = viewport->frameCount();
        viewport->update();
        while (viewport->frameCount() == before)
            QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 5);
        full.push_back(viewport->lastFrameStats().frameMs);
    }
    std::printf("  window full frames %dx%d, anisotropy %.0fx: median %.1f ms\n",
        viewport->lastFrameStats().width, viewport->lastFrameStats().height,
        double(viewport->lastFrameStats().anisotropy), median(full));
    std::set<std::string> files;
    for (const MapFile& file : mapFiles())
        files.insert(file.name);
    std::printf("  map decodes: %llu (%zu slots, %zu files)\n",
        (unsigned long long)MapImageCache::shared().decodeCount(), mapFiles().size(), files.size());
    std::printf(
        "  memory: VmRSS %s, VmHWM %s\n", statusField("VmRSS:").c_str(), statusField("VmHWM:").c_str());
    window.document()->newProject(); // nothing to ask about on close
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    QStringList args;
    for (int i = 1; i < argc; ++i)
        args << QString::fromLocal8Bit(argv[i]);
    const auto value = [&](const char* name) {
        const int at = int(args.indexOf(QLatin1String(name)));
        return at >= 0 && at + 1 < args.size() ? args[at + 1] : QString();
    };
    if (args.contains(QStringLiteral("--window"))) {
        QElapsedTimer processClock;
        processClock.start();
        QStandardPaths::setTestModeEnabled(true);
        installViewportSurfaceFormat();
        QApplication app(argc, argv);
        return runWindow(value("--maps") + QStringLiteral("/helmet.json"),
            args.contains(QStringLiteral("--open-at-start")), processClock);
    }

    QCoreApplication app(argc, argv);
    QTemporaryDir temporary;
    QString folder = value("--maps");
    if (folder.isEmpty())
        folder = temporary.path();
    QDir().mkpath(folder);
    if (!QFileInfo::exists(folder + QStringLiteral("/helmet_basecolor.jpg"))) {
        const auto start = std::chrono::steady_clock::now();
        if (!writeMaps(folder)) {
            std::fprintf(stderr, "texture_maps: could not write the maps into %s\n", qPrintable(folder));
            return 1;
        }
        std::printf("wrote the maps in %.0f ms\n", msSince(start));
    }
    std::string error;
    if (!helmetProject(folder, true).save((folder + QStringLiteral("/helmet.json")).toStdString(), &error)) {
        std::fprintf(stderr, "texture_maps: %s\n", error.c_str());
        return 1;
    }
    const int frames = std::max(1, value("--frames").toInt() > 0 ? value("--frames").toInt() : 5);
    // The IBL disk cache of this run only: the window's first run starts cold.
    QTemporaryDir cache;
    qputenv("FACET_CACHE_DIR", cache.path().toLocal8Bit());
    if (const int code = runHeadless(folder, frames); code != 0)
        return code;
    std::fflush(stdout);
    if (args.contains(QStringLiteral("--headless")))
        return 0;

    struct WindowRun {
        const char* title;
        bool emptyCache;
        bool openAtStart;
    };
    for (const WindowRun& run :
        {WindowRun {"window opened on the project (facet helmet.json), empty IBL disk cache", true, true},
            WindowRun {"window opened on the project, warm IBL disk cache", false, true},
            WindowRun {"project opened in a running window (File > Open), warm cache", false, false}}) {
        if (run.emptyCache)
            QDir(cache.path()).removeRecursively();
        std::printf("\n%s:\n", run.title);
        std::fflush(stdout);
        QProcess child;
        child.setProcessChannelMode(QProcess::ForwardedChannels);
        QStringList childArgs {QStringLiteral("--window"), QStringLiteral("--maps"), folder};
        if (run.openAtStart)
            childArgs << QStringLiteral("--open-at-start");
        child.start(QCoreApplication::applicationFilePath(), childArgs);
        if (!child.waitForFinished(300000) || child.exitCode() != 0) {
            std::fprintf(stderr, "texture_maps: the window part failed\n");
            return 1;
        }
    }
    return 0;
}
