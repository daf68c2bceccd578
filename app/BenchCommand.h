#pragma once
// `facet bench`: run time against error of the real-time renderer's quality settings
// (DESIGN.md, "Fast and accurate, measured"). For each IBL configuration (the quality presets and
// sweeps around the default one) and each environment, it times a fresh IBL precompute (no cache)
// and renders the reference view of a metal and a dielectric at several roughness values, and
// compares each image with the CPU ground truth (core/GroundTruth.h) by relative RMSE over the
// sphere (core/ImageMetrics.h). It prints tables (time and error side by side) and writes a CSV.
//
//   facet bench [--env NAME[,NAME...]] [--size N] [--spp N] [--roughness R[,R...]]
//       [--sweep GROUP[,GROUP...]] [--repeat N] [--threads N] [--no-truth-cache] [--quick]
//       [--csv OUT.csv]
//
// Ground-truth images are cached on disk (app/GroundTruthCache.h), so a second run only pays for
// the GPU side. docs/benchmarks.md has a measured table and how to read it.

#include <optional>
#include <string>
#include <vector>

#include <QString>
#include <QStringList>

#include "render/IblSettings.h"

namespace facet {

// One environment to measure under: `label` names it in tables and the CSV, `spec` is what
// Environment::fromSpec() loads (a path, a built-in name or uniform:VALUE).
struct BenchEnvironment {
    std::string label;
    std::string spec;
};

// One IBL configuration: `group` is the sweep it belongs to ("preset", "samples", ...), `name`
// says what differs from the default preset (e.g. "samples=512").
struct BenchConfig {
    std::string group;
    std::string name;
    IblSettings settings;
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
    // The configurations of the given groups (IblSettings::presetNames() for "preset"; the other
    // groups vary one setting of the default preset). Duplicates of an earlier configuration's
    // settings are kept (each sweep reads on its own) but measured once.
    static std::vector<BenchConfig> configsFor(const QStringList& groups);
};

} // namespace facet
