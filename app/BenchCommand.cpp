#include "BenchCommand.h"

#include "CommandOptions.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <set>
#include <tuple>

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSysInfo>
#include <QTemporaryDir>
#include <QThread>

#include "BenchReport.h"
#include "GroundTruthCache.h"
#include "render/FrameRenderer.h"

#include "core/Environment.h"
#include "core/GroundTruth.h"
#include "core/Image.h"
#include "core/ImageMetrics.h"
#include "core/Project.h"
#include "core/ProjectAssets.h"
#include "core/ReferenceView.h"
#include "render/HeadlessGLContext.h"
#include "render/IblPrecompute.h"
#include "render/RenderScene.h"
#include "render/Renderer.h"
#include "render/SceneFromProject.h"

namespace facet {

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kMaxSize = 1024; // the reference view; a bigger one is a typo, not a benchmark
constexpr int kMaxSamplesPerPixel = 1 << 20;
constexpr int kMaxRepeats = 100;
constexpr int kMaxThreads = 1024;

// The CC0 maps of packaging/fetch-assets.sh the full run measures (issue 10's five): a
// high-contrast studio with small bright light boxes and dark walls (where SH9 and the
// prefilter's blur are worst), a city (mid contrast, broad sky), a sunset (a low sun: one very
// bright small source), a night street (dark, with small lamps: the largest dynamic range) and a
// forest (detailed, mid-frequency light through leaves).
const QStringList kDefaultEnvironments = {QStringLiteral("studio"), QStringLiteral("city"),
    QStringLiteral("sunset"), QStringLiteral("night"), QStringLiteral("forest")};
const std::vector<double> kDefaultRoughnesses = {0.05, 0.25, 0.5, 0.75, 1.0};
// --quick: a CI-sized run (one map, two roughness values, two configurations).
const std::vector<double> kQuickRoughnesses = {0.25, 0.75};
constexpr int kQuickSize = 32;
constexpr int kQuickSamplesPerPixel = 256;

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

struct Options {
    QCommandLineParser parser;
    QCommandLineOption help {
        {QStringLiteral("h"), QStringLiteral("help")}, QStringLiteral("Displays this help.")};
    QCommandLineOption env {QStringLiteral("env"),
        QStringLiteral(
            "Environments, comma-separated: a CC0 map name from packaging/fetch-assets.sh (city, "
            "studio, ...; $FACET_ASSETS_DIR/hdri/NAME.exr), builtin:studio or builtin:sky, "
            "uniform:VALUE, or an image path. Default: studio,city,sunset,night,forest (--quick: city)."),
        QStringLiteral("names")};
    QCommandLineOption size {QStringLiteral("size"),
        QStringLiteral("Reference view size N (N x N pixels). Default 64 (--quick: 32)."),
        QStringLiteral("N")};
    QCommandLineOption spp {QStringLiteral("spp"),
        QStringLiteral("Ground-truth samples per pixel. Default 1024 (--quick: 256)."), QStringLiteral("N")};
    QCommandLineOption roughness {QStringLiteral("roughness"),
        QStringLiteral("Perceptual roughness values, comma-separated, each in [0, 1]. Default "
                       "0.05,0.25,0.5,0.75,1 (--quick: 0.25,0.75)."),
        QStringLiteral("list")};
    QCommandLineOption sweep {QStringLiteral("sweep"),
        QStringLiteral("Configuration groups, comma-separated: %1. The split-sum groups time the IBL "
                       "precompute; reference (the converging GPU integrator, --ibl reference) times "
                       "the render at each sample count. Default: all (--quick: the draft and default "
                       "presets only).")
            .arg(BenchCommand::sweepGroups().join(QStringLiteral(", "))),
        QStringLiteral("groups")};
    QCommandLineOption iblSamples {QStringLiteral("ibl-samples"),
        QStringLiteral("Samples per pixel of the reference group, comma-separated, each from 1 to %1. "
                       "Default 16,64,256,1024,4096.")
            .arg(kMaxIblSamples),
        QStringLiteral("list")};
    QCommandLineOption repeat {QStringLiteral("repeat"),
        QStringLiteral("Run each IBL precompute N times and keep the fastest (the machine is shared). "
                       "Default 1."),
        QStringLiteral("N")};
    QCommandLineOption threads {QStringLiteral("threads"),
        QStringLiteral("CPU threads of the ground-truth integrator. Default: all cores."),
        QStringLiteral("N")};
    QCommandLineOption truthNoise {QStringLiteral("truth-noise"),
        QStringLiteral("Also measure the ground truth's own noise: a second truth per case with another "
                       "seed (cached too), compared with the first (relative RMSE / sqrt 2: each one's "
                       "noise). Reference errors at high samples are read against it.")};
    QCommandLineOption noTruthCache {QStringLiteral("no-truth-cache"),
        QStringLiteral("Recompute the ground-truth images instead of reading them from the disk cache "
                       "(they are stored again).")};
    QCommandLineOption quick {QStringLiteral("quick"),
        QStringLiteral(
            "A CI-sized run: one environment, two roughness values, two configurations, 32 x 32 at "
            "256 spp (explicit options still win).")};
    QCommandLineOption csv {QStringLiteral("csv"),
        QStringLiteral("Also write every measurement to this CSV file."), QStringLiteral("file")};

    Options()
    {
        parser.setApplicationDescription(QStringLiteral(
            "Measures run time against error of the real-time renderer's IBL quality settings: for each\n"
            "configuration and environment, a fresh IBL precompute (no cache) is timed and the reference\n"
            "view of a metal and a dielectric at several roughness values is rendered on the GPU and\n"
            "compared with the CPU ground truth (relative RMSE over the sphere). The reference group\n"
            "(--ibl reference at several samples per pixel) times its converging render instead.\n"
            "Ground-truth images are cached on disk ($FACET_CACHE_DIR/ground-truth or the user cache\n"
            "directory)."));
        for (const QCommandLineOption* option : {&help, &env, &size, &spp, &roughness, &sweep, &iblSamples,
                 &repeat, &threads, &truthNoise, &noTruthCache, &quick, &csv})
            parser.addOption(*option);
    }
};

// A whole number in [low, high] for --flag; the message names the flag, the value and the range.
bool parseInteger(const QString& flag, const QString& text, int low, int high, int* out, QString* error)
{
    bool ok = false;
    const int value = text.trimmed().toInt(&ok);
    if (!ok || value < low || value > high) {
        *error = QStringLiteral("--%1: '%2' is not a whole number from %3 to %4")
                     .arg(flag, text)
                     .arg(low)
                     .arg(high);
        return false;
    }
    *out = value;
    return true;
}

// Where packaging/fetch-assets.sh puts the CC0 sample data (the same rule as the script).
QString assetsDirectory()
{
    const QString overridden = qEnvironmentVariable("FACET_ASSETS_DIR");
    if (!overridden.isEmpty())
        return overridden;
    QString dataHome = qEnvironmentVariable("XDG_DATA_HOME");
    if (dataHome.isEmpty())
        dataHome = QDir::homePath() + QStringLiteral("/.local/share");
    return dataHome + QStringLiteral("/facet/assets");
}

QStringList installedHdriNames()
{
    QStringList names;
    for (const QFileInfo& file : QDir(assetsDirectory() + QStringLiteral("/hdri"))
                                     .entryInfoList({QStringLiteral("*.exr")}, QDir::Files))
        names.append(file.completeBaseName());
    return names;
}

// One --env entry to a BenchEnvironment. A bare name is a CC0 map first (what the benchmark is
// about); the procedural built-ins need their builtin: prefix unless no CC0 map of that name is
// installed, which is then said in a warning, as the two "studio"s are very different maps.
std::optional<BenchEnvironment> resolveEnvironment(const QString& name, QStringList* warnings, QString* error)
{
    const QString trimmed = name.trimmed();
    if (trimmed.isEmpty()) {
        *error = QStringLiteral("--env: an empty environment name");
        return std::nullopt;
    }
    const QString builtinPrefix = QStringLiteral("builtin:");
    if (trimmed.startsWith(builtinPrefix)) {
        const QString builtin = trimmed.mid(builtinPrefix.size());
        if (!Environment::builtinFromName(builtin.toStdString())) {
            *error
                = QStringLiteral("--env: '%1': the built-in environments are builtin:studio and builtin:sky")
                      .arg(trimmed);
            return std::nullopt;
        }
        return BenchEnvironment {trimmed.toStdString(), builtin.toStdString()};
    }
    if (trimmed.startsWith(QStringLiteral("uniform:"))) {
        std::string problem;
        if (!Environment::fromSpec(trimmed.toStdString(), &problem)) {
            *error = QStringLiteral("--env: %1").arg(QString::fromStdString(problem));
            return std::nullopt;
        }
        return BenchEnvironment {trimmed.toStdString(), trimmed.toStdString()};
    }
    const QFileInfo file(trimmed);
    const bool looksLikePath = trimmed.contains(QLatin1Char('/')) || !file.suffix().isEmpty();
    if (looksLikePath) {
        if (!file.isFile()) {
            *error = QStringLiteral("--env: '%1' is not a file").arg(trimmed);
            return std::nullopt;
        }
        return BenchEnvironment {file.completeBaseName().toStdString(), trimmed.toStdString()};
    }
    const QString asset = assetsDirectory() + QStringLiteral("/hdri/") + trimmed + QStringLiteral(".exr");
    if (QFileInfo(asset).isFile())
        return BenchEnvironment {trimmed.toStdString(), asset.toStdString()};
    if (Environment::builtinFromName(trimmed.toStdString())) {
        warnings->append(
            QStringLiteral("--env %1: no CC0 map %2 (run packaging/fetch-assets.sh); measuring the "
                           "built-in '%1' instead")
                .arg(trimmed, asset));
        return BenchEnvironment {"builtin:" + trimmed.toStdString(), trimmed.toStdString()};
    }
    const QStringList installed = installedHdriNames();
    *error
        = QStringLiteral("--env: '%1' is not an installed CC0 map (%2), builtin:studio, builtin:sky, "
                         "uniform:VALUE or an image file")
              .arg(trimmed,
                  installed.isEmpty()
                      ? QStringLiteral("none under %1: run packaging/fetch-assets.sh").arg(assetsDirectory())
                      : installed.join(QStringLiteral(", ")));
    return std::nullopt;
}

IblSettings defaultSettings()
{
    return *IblSettings::preset("default");
}

BenchConfig variant(const char* group, const std::string& name, IblSettings settings)
{
    return BenchConfig {group, name, settings, IblMethod::SplitSum, 0};
}

} // namespace

QStringList BenchCommand::sweepGroups()
{
    return {QStringLiteral("presets"), QStringLiteral("samples"), QStringLiteral("cube"),
        QStringLiteral("prefilter-size"), QStringLiteral("irradiance"), QStringLiteral("reference")};
}

std::vector<int> BenchCommand::defaultReferenceSamples()
{
    return {16, 64, 256, 1024, 4096};
}

std::vector<BenchConfig> BenchCommand::configsFor(
    const QStringList& groups, const std::vector<int>& referenceSamples)
{
    std::vector<BenchConfig> configs;
    const IblSettings base = defaultSettings();
    for (const QString& group : sweepGroups()) {
        if (!groups.contains(group))
            continue;
        if (group == QStringLiteral("presets")) {
            for (const std::string& name : IblSettings::presetNames())
                configs.push_back(variant("presets", "preset=" + name, *IblSettings::preset(name)));
        } else if (group == QStringLiteral("samples")) {
            // GGX samples per prefiltered texel: the prefilter's cost is linear in them.
            for (int samples : {32, 64, 128, 256, 512, 1024}) {
                IblSettings s = base;
                s.prefilterSamples = samples;
                configs.push_back(variant("samples", "samples=" + std::to_string(samples), s));
            }
        } else if (group == QStringLiteral("cube")) {
            // The environment cube with the prefiltered cube at half its size, as in every preset.
            // The CC0 maps are 512 x 256: a cube face of 128 already holds one texel per source texel.
            for (int size : {64, 128, 256, 512}) {
                IblSettings s = base;
                s.cubeSize = size;
                s.prefilterSize = size / 2;
                configs.push_back(variant("cube", "cube=" + std::to_string(size), s.sanitized()));
            }
        } else if (group == QStringLiteral("prefilter-size")) {
            for (int size : {32, 64, 128, 256}) {
                IblSettings s = base;
                s.prefilterSize = size;
                configs.push_back(
                    variant("prefilter-size", "prefilter=" + std::to_string(size), s.sanitized()));
            }
        } else if (group == QStringLiteral("irradiance")) {
            // SH9 against the irradiance cubemap, and the map's source resolution (texels summed).
            IblSettings sh = base;
            sh.irradiance = IblSettings::Irradiance::SH;
            configs.push_back(variant("irradiance", "irradiance=sh9", sh));
            for (int samples : {384, 1536, 6144}) {
                IblSettings s = base;
                s.irradianceSamples = samples;
                configs.push_back(variant("irradiance", "irradiance=map/" + std::to_string(samples), s));
            }
        } else if (group == QStringLiteral("reference")) {
            // The converging integrator of core/GroundTruth on the GPU: it estimates the truth's
            // integral, so its error should be its noise plus the truth's, and the sweep is over
            // samples per pixel. The settings are the default preset's: they only draw the
            // background.
            for (int samples : referenceSamples)
                configs.push_back(BenchConfig {"reference", "reference=" + std::to_string(samples), base,
                    IblMethod::Reference, samples});
        }
    }
    return configs;
}

QString BenchCommand::helpText()
{
    Options options;
    return commandHelpText(options.parser, QStringLiteral("facet bench"));
}

std::optional<BenchRequest> BenchCommand::parse(const QStringList& arguments, QString* error, int* exitCode)
{
    Options o;
    if (!parseCommandOptions(o, arguments, QStringLiteral("facet bench"), kExitUsage, error, exitCode))
        return std::nullopt;
    if (!o.parser.positionalArguments().isEmpty()) {
        *error = QStringLiteral("unexpected argument '%1' (bench takes options only)")
                     .arg(o.parser.positionalArguments().first());
        return std::nullopt;
    }

    BenchRequest request;
    const bool quick = o.parser.isSet(o.quick);
    request.size = quick ? kQuickSize : request.size;
    request.samplesPerPixel = quick ? kQuickSamplesPerPixel : request.samplesPerPixel;
    if (o.parser.isSet(o.size)
        && !parseInteger(QStringLiteral("size"), o.parser.value(o.size), 8, kMaxSize, &request.size, error))
        return std::nullopt;
    if (o.parser.isSet(o.spp)
        && !parseInteger(QStringLiteral("spp"), o.parser.value(o.spp), 1, kMaxSamplesPerPixel,
            &request.samplesPerPixel, error))
        return std::nullopt;
    if (o.parser.isSet(o.repeat)
        && !parseInteger(
            QStringLiteral("repeat"), o.parser.value(o.repeat), 1, kMaxRepeats, &request.repeats, error))
        return std::nullopt;
    if (o.parser.isSet(o.threads)
        && !parseInteger(
            QStringLiteral("threads"), o.parser.value(o.threads), 1, kMaxThreads, &request.threads, error))
        return std::nullopt;
    request.truthCache = !o.parser.isSet(o.noTruthCache);
    request.truthNoise = o.parser.isSet(o.truthNoise);

    request.roughnesses = quick ? kQuickRoughnesses : kDefaultRoughnesses;
    if (o.parser.isSet(o.roughness)) {
        request.roughnesses.clear();
        for (const QString& part : o.parser.value(o.roughness).split(QLatin1Char(','))) {
            bool ok = false;
            const double value = part.trimmed().toDouble(&ok);
            if (!ok || !std::isfinite(value) || value < 0.0 || value > 1.0) {
                *error = QStringLiteral("--roughness: '%1' is not a number in [0, 1]").arg(part);
                return std::nullopt;
            }
            if (std::find(request.roughnesses.begin(), request.roughnesses.end(), value)
                == request.roughnesses.end())
                request.roughnesses.push_back(value);
        }
    }

    QStringList groups = sweepGroups();
    if (quick)
        groups = {QStringLiteral("presets")};
    if (o.parser.isSet(o.sweep)) {
        groups = o.parser.value(o.sweep).split(QLatin1Char(','));
        for (QString& group : groups) {
            group = group.trimmed();
            if (!sweepGroups().contains(group)) {
                *error = QStringLiteral("--sweep: '%1' is not one of %2")
                             .arg(group, sweepGroups().join(QStringLiteral(", ")));
                return std::nullopt;
            }
        }
    }
    std::vector<int> referenceSamples = defaultReferenceSamples();
    if (o.parser.isSet(o.iblSamples)) {
        if (!groups.contains(QStringLiteral("reference"))) {
            *error = QStringLiteral("--ibl-samples: the sample counts of the reference group, which --sweep "
                                    "leaves out (add --sweep reference)");
            return std::nullopt;
        }
        referenceSamples.clear();
        for (const QString& part : o.parser.value(o.iblSamples).split(QLatin1Char(','))) {
            int samples = 0;
            if (!parseInteger(QStringLiteral("ibl-samples"), part, 1, kMaxIblSamples, &samples, error))
                return std::nullopt;
            if (std::find(referenceSamples.begin(), referenceSamples.end(), samples)
                == referenceSamples.end())
                referenceSamples.push_back(samples);
        }
    }
    request.configs = configsFor(groups, referenceSamples);
    if (quick && !o.parser.isSet(o.sweep)) {
        // Two configurations: the cheapest preset and the default one.
        std::erase_if(request.configs, [](const BenchConfig& c) { return c.name == "preset=high"; });
    }

    const QStringList names = o.parser.isSet(o.env)
        ? o.parser.value(o.env).split(QLatin1Char(','))
        : (quick ? QStringList {QStringLiteral("city")} : kDefaultEnvironments);
    for (const QString& name : names) {
        auto environment = resolveEnvironment(name, &request.warnings, error);
        if (!environment)
            return std::nullopt;
        request.environments.push_back(std::move(*environment));
    }

    if (o.parser.isSet(o.csv)) {
        request.csvPath = o.parser.value(o.csv);
        const QFileInfo csv(request.csvPath);
        if (request.csvPath.isEmpty() || csv.isDir()) {
            *error = QStringLiteral("--csv '%1': expected a file name").arg(request.csvPath);
            return std::nullopt;
        }
        if (!csv.absoluteDir().exists()) {
            *error = QStringLiteral("--csv '%1': the folder %2 does not exist")
                         .arg(request.csvPath, csv.absoluteDir().path());
            return std::nullopt;
        }
    }
    *exitCode = 0;
    return request;
}

namespace {

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
    project.view.debugView = "none";
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
    // The DFG table the method's frames read: the split sum's own, or for Reference the ground
    // truth's albedo table (dfgSettingsFor).
    const IblSettings dfgSettings = dfgSettingsFor(config.settings, config.method);
    // A fresh precompute every time: the memory cache is dropped (the disk cache is off), so
    // every pass, the DFG LUT and Reference's source textures included, runs and is timed. The
    // fastest of the repeats counts: on a shared machine the slow runs measure the neighbours.
    IblStats best;
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
        // Reference reads the source equirect and its sampling tables (EnvironmentSourceTextures).
        if (reference && !m_frames->precompute().source(assets.environment, &stats, &error)) {
            fail(error);
            return false;
        }
        if (i == 0 || stats.msTotal < best.msTotal)
            best = stats;
    }
    BenchRow base;
    base.group = config.group;
    base.config = config.name;
    base.settings = config.settings.sanitized();
    base.method = config.method;
    base.iblSamples = reference ? config.samples : 0;
    base.environment = environment.label;
    base.size = m_request.size;
    base.truthSamplesPerPixel = m_request.samplesPerPixel;
    base.ibl = best;
    // What the sphere's shading needs: for the split sum every pass but the irradiance cubemap
    // when irradiance comes from SH (IblPrecompute computes both today); for Reference the
    // source textures and its DFG table (the cubes only draw the background).
    base.iblNeededMs = reference ? best.msSource + best.msDfg
                                 : best.msTotal
            - (config.settings.irradiance == IblSettings::Irradiance::SH ? best.msIrradiance : 0.0);

    SceneOptions options = sceneOptionsFor(config.settings, /*referenceView=*/true);
    options.iblMethod = config.method;
    // The noise estimate covers the pixels the error reads: the interior sphere pixels.
    std::vector<std::uint8_t> noiseMask(std::size_t(m_request.size) * std::size_t(m_request.size));
    for (int y = 0; y < m_request.size; ++y)
        for (int x = 0; x < m_request.size; ++x)
            noiseMask[std::size_t(y) * std::size_t(m_request.size) + std::size_t(x)]
                = referenceview::isInteriorSpherePixel(x, y, m_request.size, m_request.size) ? 1 : 0;
    bool warmedUp = false;
    for (const Scene& scene : scenes) {
        RenderScene renderScene = sceneFromProject(scene.project, assets, ibl, options);
        // Memory hits: the tables and the source were made above.
        if (!m_frames->addDfgTables(config.settings, renderScene, nullptr, &error)
            || !m_frames->addEnvironmentSource(assets.environment, renderScene, nullptr, &error)) {
            fail(error);
            return false;
        }
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
    // One surfaceless EGL context for the whole run: no display server needed (shared/PLATFORM.md).
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
