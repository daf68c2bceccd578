// `facet bench`: the command line (BenchCommand::parse, the sweep groups and their
// configurations); BenchRun.cpp runs what it parses.
#include "BenchCommand.h"

#include "CommandOptions.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QDir>
#include <QFile>
#include <QFileInfo>

#include "core/ibl/Environment.h"
#include "core/project/Project.h"

namespace facet {

namespace {

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
                       "precompute; fis (--ibl fis) and reference (the converging GPU integrator, --ibl "
                       "reference) time the render at each sample count. Default: all (--quick: the draft and default "
                       "presets only).")
            .arg(BenchCommand::sweepGroups().join(QStringLiteral(", "))),
        QStringLiteral("groups")};
    QCommandLineOption iblSamples {QStringLiteral("ibl-samples"),
        QStringLiteral("Samples per pixel of the fis and reference groups, comma-separated, each from 1 "
                       "to %1. Default fis 4,8,16,32,64,128,256; reference 16,64,256,1024,4096.")
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
        QStringLiteral("prefilter-size"), QStringLiteral("irradiance"), QStringLiteral("fis"),
        QStringLiteral("reference")};
}

std::vector<int> BenchCommand::defaultFisSamples()
{
    return {4, 8, 16, 32, 64, 128, 256};
}

std::vector<int> BenchCommand::defaultReferenceSamples()
{
    return {16, 64, 256, 1024, 4096};
}

std::vector<BenchConfig> BenchCommand::configsFor(
    const QStringList& groups, const std::vector<int>& referenceSamples, const std::vector<int>& fisSamples)
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
        } else if (group == QStringLiteral("fis")) {
            // Filtered importance sampling of each pixel's lobe: the sweep is over its samples per
            // pixel, with the default preset's environment cube and irradiance.
            for (int samples : fisSamples)
                configs.push_back(
                    BenchConfig {"fis", "fis=" + std::to_string(samples), base, IblMethod::Fis, samples});
        } else if (group == QStringLiteral("reference")) {
            // The converging integrator of core/shading/GroundTruth on the GPU: it estimates the truth's
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
    std::vector<int> fisSamples = defaultFisSamples();
    if (o.parser.isSet(o.iblSamples)) {
        if (!groups.contains(QStringLiteral("reference")) && !groups.contains(QStringLiteral("fis"))) {
            *error = QStringLiteral("--ibl-samples: the sample counts of the fis and reference groups, which --sweep "
                                    "leaves out (add --sweep fis or --sweep reference)");
            return std::nullopt;
        }
        std::vector<int> listed;
        for (const QString& part : o.parser.value(o.iblSamples).split(QLatin1Char(','))) {
            int samples = 0;
            if (!parseInteger(QStringLiteral("ibl-samples"), part, 1, kMaxIblSamples, &samples, error))
                return std::nullopt;
            if (std::find(listed.begin(), listed.end(), samples) == listed.end())
                listed.push_back(samples);
        }
        referenceSamples = fisSamples = listed;
    }
    request.configs = configsFor(groups, referenceSamples, fisSamples);
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

} // namespace facet
