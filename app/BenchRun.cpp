// `facet bench`'s measurement (BenchCommand::run): the ground truths (cached), a fresh IBL
// precompute per configuration and environment, the reference view of each material and
// roughness rendered by the configuration's method and compared with its truth. BenchCommand.cpp
// parses the command line into the BenchRequest this runs.
#include "BenchCommand.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <set>
#include <tuple>

#include <QDateTime>
#include <QFile>
#include <QSysInfo>
#include <QTemporaryDir>
#include <QThread>

#include "BenchReport.h"
#include "GroundTruthCache.h"
#include "render/FrameRenderer.h"

#include "core/ibl/Environment.h"
#include "core/image/Image.h"
#include "core/image/ImageMetrics.h"
#include "core/project/Project.h"
#include "core/project/ProjectAssets.h"
#include "core/shading/GroundTruth.h"
#include "render/HeadlessGLContext.h"
#include "render/IblPrecompute.h"
#include "render/RenderScene.h"
#include "render/Renderer.h"
#include "render/SceneFromProject.h"

namespace facet {

namespace {

using Clock = std::chrono::steady_clock;

struct BenchMaterial {
    const char* name;
    glm::dvec3 baseColor;
    double metallic;
};

// A gold-like metal (glTF sample-model gold, linear) and a red dielectric with IOR 1.5 (F0 0.04):
// the metal is all specular (the prefiltered cube), the dielectric mostly diffuse (irradiance)
// with a weak specular coat, so together they cover both IBL lookups.
const BenchMaterial kMaterials[] = {
    {"metal", {1.0, 0.766, 0.336}, 1.0},
    {"dielectric", {0.8, 0.1, 0.1}, 0.0},
};

// "model name" of the first CPU in /proc/cpuinfo (Linux), for the report's machine line.
QString cpuModel()
{
    QFile cpuinfo(QStringLiteral("/proc/cpuinfo"));
    if (cpuinfo.open(QIODevice::ReadOnly | QIODevice::Text)) {
        const QList<QByteArray> lines = cpuinfo.readAll().split('\n');
        for (const QByteArray& line : lines)
            if (line.startsWith("model name")) {
                const int colon = line.indexOf(':');
                return QString::fromUtf8(line.mid(colon + 1)).trimmed();
            }
    }
    return QSysInfo::currentCpuArchitecture();
}

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct Scene {
    const BenchMaterial* material;
    double roughness;
    Project project; // the environment, the material at this roughness, the reference view
    Image truth;
    // --truth-noise: relativeRmse(truth, truth of another seed) / sqrt(2), the noise of each (two
    // independent estimates of one image: the difference's variance is twice either's); NaN if not
    // measured.
    double truthNoise = std::nan("");
};

// The project of one measurement: no lights (the benchmark measures image-based lighting only),
// environment unrotated at intensity 1, the reference sphere, the default (glTF) shading model.
Project benchProject(const BenchEnvironment& environment, const BenchMaterial& material, double roughness)
{
    Project project = Project::defaultProject();
    project.lights.clear();
    project.environment.source = environment.spec;
    project.environment.rotationDegrees = 0.0;
    project.environment.intensity = 1.0;
    project.view.mesh = "sphere";
    project.view.debugView = DebugView::None;
    project.material().name = material.name;
    project.material().setBaseColor(material.baseColor);
    project.material().setFactor(MapSlot::Metallic, material.metallic);
    project.material().setFactor(MapSlot::Roughness, roughness);
    project.material().ior = Material::kDefaultIor;
    return project;
}

class BenchRun {
public:
    explicit BenchRun(const BenchRequest& request)
        : m_request(request)
    {
    }

    int run();

private:
    bool prepareTruths(const BenchEnvironment& environment, std::vector<Scene>* scenes);
    bool measure(const BenchConfig& config, const BenchEnvironment& environment, const ProjectAssets& assets,
        const std::vector<Scene>& scenes);
    void fail(const std::string& message) const
    {
        std::fprintf(stderr, "facet bench: %s\n", message.c_str());
    }
    void printHeader(const GLInfo& gl) const;

    const BenchRequest& m_request;
    GroundTruthCache m_truthCache;
    // GL objects: created once the context is current, destroyed before it goes.
    std::unique_ptr<FrameRenderer> m_frames;
    std::vector<BenchRow> m_rows;
    int m_truthsComputed = 0;
    int m_truthsCached = 0;
    double m_truthSeconds = 0.0;
};

bool BenchRun::prepareTruths(const BenchEnvironment& environment, std::vector<Scene>* scenes)
{
    GroundTruthSettings settings;
    settings.width = m_request.size;
    settings.height = m_request.size;
    settings.samplesPerPixel = m_request.samplesPerPixel;
    settings.threads = m_request.threads;
    for (const BenchMaterial& material : kMaterials)
        for (double roughness : m_request.roughnesses) {
            Scene scene {&material, roughness, benchProject(environment, material, roughness), {}};
            std::string error;
            std::string warning; // sanitised pixels: loadProjectAssets says it once already
            const auto truthScene = groundTruthSceneFromProject(scene.project, &error, &warning);
            if (!truthScene) {
                fail(error);
                return false;
            }
            const auto truth = [&](const GroundTruthSettings& truthSettings) {
                std::optional<Image> cached;
                if (m_request.truthCache) {
                    std::string cacheWarning;
                    cached = m_truthCache.load(*truthScene, truthSettings, &cacheWarning);
                    if (cached)
                        ++m_truthsCached;
                    else if (!cacheWarning.empty())
                        fail(cacheWarning);
                }
                if (cached)
                    return std::move(*cached);
                std::fprintf(stderr, "facet bench: ground truth %s %s r=%.2f (%dx%d, %d spp, seed %llu)...",
                    environment.label.c_str(), material.name, roughness, truthSettings.width,
                    truthSettings.height, truthSettings.samplesPerPixel,
                    static_cast<unsigned long long>(truthSettings.seed));
                std::fflush(stderr);
                GroundTruthStats stats;
                Image image = renderGroundTruth(*truthScene, truthSettings, &stats);
                std::fprintf(stderr, " %.1f s\n", stats.seconds);
                m_truthSeconds += stats.seconds;
                ++m_truthsComputed;
                std::string storeError;
                if (!m_truthCache.store(*truthScene, truthSettings, image, &storeError))
                    fail(storeError + " (continuing without caching it)");
                return image;
            };
            scene.truth = truth(settings);
            if (m_request.truthNoise) {
                GroundTruthSettings other = settings;
                other.seed = settings.seed + 1;
                scene.truthNoise = sphereErrorStats(truth(other), scene.truth).relativeRmse / std::sqrt(2.0);
            }
            scenes->push_back(std::move(scene));
        }
    return true;
}

bool BenchRun::measure(const BenchConfig& config, const BenchEnvironment& environment,
    const ProjectAssets& assets, const std::vector<Scene>& scenes)
{
    const bool reference = config.method == IblMethod::Reference;
    const bool sampled = config.method != IblMethod::SplitSum; // Fis or Reference
    // The DFG table the method's frames read: the split sum's own, or for Reference the ground
    // truth's albedo table (dfgSettingsFor).
    const IblSettings dfgSettings = dfgSettingsFor(config.settings, config.method);
    // A fresh precompute every time: the memory cache is dropped (the disk cache is off), so
    // every pass, the DFG LUT and Reference's source textures included, runs and is timed. The
    // fastest of the repeats counts: on a shared machine the slow runs measure the neighbours.
    IblStats best;
    std::vector<double> totals; // every repeat's msTotal, for the median
    std::shared_ptr<const IblTextures> ibl;
    std::string error;
    for (int i = 0; i < m_request.repeats; ++i) {
        ibl.reset();
        m_frames->precompute().clearMemoryCache();
        IblStats stats;
        ibl = m_frames->lighting(assets.environment, config.settings, &stats, &error);
        if (!ibl) {
            fail(error);
            return false;
        }
        // The DFG table of each visibility term the scenes use, timed with the passes above.
        std::set<Visibility> visibilities;
        for (const Scene& scene : scenes)
            visibilities.insert(scene.project.material().shading.visibility);
        for (Visibility visibility : visibilities)
            if (!m_frames->precompute().dfgTable(dfgSettings, visibility, &stats, &error)) {
                fail(error);
                return false;
            }
        // Fis and Reference read the source equirect (EnvironmentSourceTextures).
        if (sampled && !m_frames->precompute().source(assets.environment, &stats, &error)) {
            fail(error);
            return false;
        }
        totals.push_back(stats.msTotal);
        if (i == 0 || stats.msTotal < best.msTotal)
            best = stats;
    }
    std::sort(totals.begin(), totals.end());
    const std::size_t middle = totals.size() / 2;
    const double medianMs = totals.size() % 2 ? totals[middle] : 0.5 * (totals[middle - 1] + totals[middle]);
    BenchRow base;
    base.group = config.group;
    base.config = config.name;
    // What ran: the requested settings as the precompute fits them to this map (a 512 cube on a
    // 512-wide map runs at 256; IblPrecompute uses forImage too).
    base.settings = config.settings.forImage(assets.environment.width());
    base.method = config.method;
    base.iblSamples = sampled ? config.samples : 0;
    base.environment = environment.label;
    base.size = m_request.size;
    base.truthSamplesPerPixel = m_request.samplesPerPixel;
    base.ibl = best;
    base.iblMedianMs = medianMs;
    base.iblRepeats = int(totals.size());
    // What the sphere's shading needs: for the split sum every pass but the irradiance cubemap
    // when irradiance comes from SH (IblPrecompute computes both today); for Reference the
    // source textures and its DFG table (the cubes only draw the background); for Fis those, the
    // environment cube and the irradiance (not the prefiltered cube).
    const double irradianceMs
        = config.settings.irradiance == IblSettings::Irradiance::SH ? best.msSh : best.msIrradiance;
    base.iblNeededMs = reference ? best.msSource + best.msDfg
        : sampled                ? best.msSource + best.msDfg + best.msEquirectToCube + irradianceMs
                                 : best.msTotal
            - (config.settings.irradiance == IblSettings::Irradiance::SH ? best.msIrradiance : 0.0);

    SceneOptions options = sceneOptionsFor(config.settings, /*referenceView=*/true);
    options.iblMethod = config.method;
    // The noise estimate covers the pixels the error reads: the interior sphere pixels.
    const PixelMask noiseMask = sphereMask(m_request.size, m_request.size);
    bool warmedUp = false;
    for (const Scene& scene : scenes) {
        // Memory hits: the tables and the source were made above.
        std::optional<RenderScene> prepared
            = m_frames->prepare(scene.project, assets, config.settings, options, nullptr, &error, ibl);
        if (!prepared) {
            fail(error);
            return false;
        }
        const RenderScene& renderScene = *prepared;
        if (!warmedUp) {
            // The first frame of a shader variant compiles it (and llvmpipe JITs it): not a frame's
            // cost. One sample is enough for that.
            if (!m_frames->renderConverged(
                    renderScene, m_request.size, m_request.size, FrameOutput::LinearRadiance, 1, &error)) {
                fail(error);
                return false;
            }
            warmedUp = true;
        }
        FrameRenderer::ConvergedStats converged;
        const Clock::time_point start = Clock::now();
        const std::optional<Image> image = m_frames->renderConverged(renderScene, m_request.size,
            m_request.size, FrameOutput::LinearRadiance, base.iblSamples, &error, &converged, noiseMask);
        if (!image) {
            fail(error);
            return false;
        }
        BenchRow row = base;
        // Read-back included: it waits for the frame (for Reference every draw) to finish.
        row.renderMs = msSince(start);
        row.draws = converged.draws;
        row.noise = converged.noise.value_or(std::nan(""));
        row.material = scene.material->name;
        row.roughness = scene.roughness;
        row.error = sphereErrorStats(*image, scene.truth);
        row.truthNoise = scene.truthNoise;
        m_rows.push_back(std::move(row));
    }
    return true;
}

void BenchRun::printHeader(const GLInfo& gl) const
{
    std::printf("facet bench, %s\n", qPrintable(QDateTime::currentDateTime().toString(Qt::ISODate)));
    std::printf("machine: %s, %d hardware threads, %s\n", qPrintable(cpuModel()), QThread::idealThreadCount(),
        qPrintable(QSysInfo::prettyProductName()));
    std::printf("gl: %s; %s\n", gl.renderer.c_str(), gl.version.c_str());
    std::printf("reference view %dx%d, ground truth %d spp, precompute repeats %d (fastest kept)\n",
        m_request.size, m_request.size, m_request.samplesPerPixel, m_request.repeats);
    std::string environments;
    for (const BenchEnvironment& e : m_request.environments)
        environments += (environments.empty() ? "" : ", ") + e.label + " (" + e.spec + ")";
    std::printf("environments: %s\n", environments.c_str());
    std::string roughness;
    for (double r : m_request.roughnesses)
        roughness += (roughness.empty() ? "" : ", ") + std::to_string(r).substr(0, 4);
    std::printf("materials: ");
    for (const BenchMaterial& m : kMaterials)
        std::printf("%s (base %.3g,%.3g,%.3g metallic %g) ", m.name, m.baseColor.r, m.baseColor.g,
            m.baseColor.b, m.metallic);
    std::printf("at roughness %s\n\n", roughness.c_str());
}

int BenchRun::run()
{
    std::string error;
    // One surfaceless EGL context for the whole run: no display server needed (docs/architecture.md, "OpenGL
    // without a display").
    auto context = HeadlessGLContext::create(&error);
    if (!context) {
        fail(error);
        return BenchCommand::kExitFailure;
    }
    // The precompute never touches the user's IBL cache: no disk cache, and a private directory
    // in case a future version writes one anyway.
    QTemporaryDir scratch;
    m_frames = std::make_unique<FrameRenderer>(scratch.path(), /*useDiskCache=*/false);
    printHeader(context->info());
    std::fflush(stdout);

    bool ok = true;
    bool warmedUp = false;
    for (const BenchEnvironment& environment : m_request.environments) {
        std::string warning;
        const auto assets
            = loadProjectAssets(benchProject(environment, kMaterials[0], 0.5), &error, &warning);
        if (!warning.empty())
            fail(warning);
        if (!assets) {
            fail(error);
            ok = false;
            break;
        }
        std::vector<Scene> scenes;
        if (!prepareTruths(environment, &scenes)) {
            ok = false;
            break;
        }
        if (!warmedUp) {
            // The first prepare() compiles the precompute's programs and llvmpipe JITs them: a
            // one-off of the process, not of a configuration.
            IblSettings tiny = *IblSettings::preset("draft");
            tiny.cubeSize = 16;
            tiny.prefilterSize = 8;
            if (!m_frames->lighting(assets->environment, tiny, nullptr, &error)) {
                fail(error);
                ok = false;
                break;
            }
            // The DFG programs compile on first use, one per visibility term.
            for (const Scene& scene : scenes)
                if (!m_frames->precompute().dfgTable(
                        tiny, scene.project.material().shading.visibility, nullptr, &error)) {
                    fail(error);
                    ok = false;
                    break;
                }
            if (!ok)
                break;
            warmedUp = true;
        }
        // Configurations with the same method, samples and settings (the default preset appears
        // in every split-sum sweep) are measured once and reported under each name.
        using Key = std::tuple<IblMethod, int, std::uint64_t>;
        std::map<Key, std::size_t> measured; // -> first row of its block
        for (const BenchConfig& config : m_request.configs) {
            const Key key {config.method, config.method == IblMethod::SplitSum ? 0 : config.samples,
                config.settings.sanitized().hash()};
            if (const auto it = measured.find(key); it != measured.end()) {
                const std::size_t first = it->second;
                const std::size_t count = scenes.size();
                for (std::size_t i = 0; i < count; ++i) {
                    BenchRow row = m_rows[first + i];
                    row.group = config.group;
                    row.config = config.name;
                    m_rows.push_back(std::move(row));
                }
                continue;
            }
            std::fprintf(
                stderr, "facet bench: %s under %s\n", config.name.c_str(), environment.label.c_str());
            measured[key] = m_rows.size();
            if (!measure(config, environment, *assets, scenes)) {
                ok = false;
                break;
            }
        }
        if (!ok)
            break;
    }
    // GL objects go while the context is current.
    m_frames.reset();
    if (!ok)
        return BenchCommand::kExitFailure;

    // Rows in configuration order (they were measured environment by environment).
    std::stable_sort(m_rows.begin(), m_rows.end(), [&](const BenchRow& a, const BenchRow& b) {
        auto index = [&](const BenchRow& row) {
            for (std::size_t i = 0; i < m_request.configs.size(); ++i)
                if (m_request.configs[i].name == row.config)
                    return i;
            return m_request.configs.size();
        };
        return index(a) < index(b);
    });
    printBenchTables(stdout, m_rows);
    std::printf("\nground truth: %d images computed (%.1f s), %d from the cache (%s)\n", m_truthsComputed,
        m_truthSeconds, m_truthsCached, qPrintable(m_truthCache.directory()));
    if (!m_request.csvPath.isEmpty()) {
        if (!writeBenchCsv(m_request.csvPath, m_rows, &error)) {
            std::fprintf(stderr, "%s\n", error.c_str());
            return BenchCommand::kExitFailure;
        }
        std::printf("csv: %s (%zu rows)\n", qPrintable(m_request.csvPath), m_rows.size());
    }
    return 0;
}

} // namespace

int BenchCommand::run(const BenchRequest& request)
{
    for (const QString& warning : request.warnings)
        std::fprintf(stderr, "facet bench: %s\n", qPrintable(warning));
    BenchRun bench(request);
    return bench.run();
}

} // namespace facet
