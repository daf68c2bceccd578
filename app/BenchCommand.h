#pragma once
// `facet bench`: run time against error of the real-time renderer's quality settings
// (docs/architecture.md, "Accuracy"). For each IBL configuration (the quality presets and
// sweeps around the default one) and each environment, it times a fresh IBL precompute (no cache)
// and renders the reference view of a metal and a dielectric at several roughness values, and
// compares each image with the CPU ground truth (core/shading/GroundTruth.h) by relative RMSE over the
// sphere (core/image/ImageMetrics.h). It prints tables (time and error side by side) and writes a CSV.
//
//   facet bench [--env NAME[,NAME...]] [--size N] [--spp N] [--roughness R[,R...]]
//       [--sweep GROUP[,GROUP...]] [--ibl-samples N[,N...]] [--repeat N] [--threads N]
//       [--truth-noise] [--no-truth-cache] [--quick] [--csv OUT.csv]
//
// The split-sum groups time the precompute (the frame is one cheap draw); the `reference` group
// (IblMethod::Reference at several samples per pixel) times the converging render, which is its
// cost.
//
// Ground-truth images are cached on disk (app/GroundTruthCache.h), so a second run only pays for
// the GPU side. docs/benchmarks.md has a measured table and how to read it.

#include <optional>
#include <string>
#include <vector>

#include <QString>
#include <QStringList>

#include "core/project/Project.h"
#include "render/IblSettings.h"

namespace facet {

// One environment to measure under: `label` names it in tables and the CSV, `spec` is what
// Environment::fromSpec() loads (a path, a built-in name or uniform:VALUE).
struct BenchEnvironment {
    std::string label;
    std::string spec;
};

// One IBL configuration: `group` is the sweep it belongs to ("preset", "samples", ...), `name`
// says what differs from the default preset (e.g. "samples=512", "reference=1024").
struct BenchConfig {
    std::string group;
    std::string name;
    IblSettings settings; // the split sum's; a reference frame draws only its background with them
    IblMethod method = IblMethod::SplitSum;
    int samples = 0; // per pixel, for a sampled method (Fis, Reference); 0 for the split sum
};

struct BenchRequest {
    std::vector<BenchEnvironment> environments;
    std::vector<double> roughnesses;
    std::vector<BenchConfig> configs;
    int size = 64; // the reference view is size x size
    int samplesPerPixel = 1024; // of the ground truth
    int threads = 0; // of the ground truth; 0: all cores
    int repeats = 1; // precompute runs per configuration and environment; the fastest counts
    bool truthCache = true;
    bool truthNoise = false; // also a second truth per case (another seed): its own noise
    QString csvPath; // empty: no CSV
    QStringList warnings; // resolved at parse time (e.g. a built-in used for a missing CC0 map)
};

class BenchCommand {
public:
    static constexpr int kExitFailure = 1; // a valid request that failed (no GL, unreadable map, write error)
    static constexpr int kExitUsage = 2; // the command line is wrong

    // `arguments` are what follows "bench". On failure returns nullopt, `exitCode` says 0 (--help:
    // `error` holds the help text), 1 or 2, and `error` the message (without "facet bench: ").
    static std::optional<BenchRequest> parse(const QStringList& arguments, QString* error, int* exitCode);
    static QString helpText();
    // Runs the benchmark: tables to stdout, progress and warnings to stderr.
    static int run(const BenchRequest& request);

    // The sweep groups --sweep accepts, in the order they run.
    static QStringList sweepGroups();
    // The samples per pixel the `reference` group renders at unless --ibl-samples says otherwise:
    // 16 ... 4096 (issue 10), each a multiple of FrameRenderer::kSamplesPerDraw or below it.
    static std::vector<int> defaultReferenceSamples();
    // The fis group's samples per pixel unless --ibl-samples says otherwise: 4 ... 256 (issue 10).
    static std::vector<int> defaultFisSamples();
    // The configurations of the given groups (IblSettings::presetNames() for "preset"; the
    // split-sum groups vary one setting of the default preset; "fis" is IblMethod::Fis at each
    // of `fisSamples`, "reference" IblMethod::Reference at each of `referenceSamples`). Duplicates of an earlier
    // configuration (same method, samples and settings) are kept (each sweep reads on its own)
    // but measured once.
    static std::vector<BenchConfig> configsFor(
        const QStringList& groups, const std::vector<int>& referenceSamples = defaultReferenceSamples(),
        const std::vector<int>& fisSamples = defaultFisSamples());
};

} // namespace facet
