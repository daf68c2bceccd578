#pragma once
// What `facet bench` measured, one row per (configuration, environment, material, roughness),
// and the two ways it is reported: readable tables (time and error side by side, docs/architecture.md "Every
// approximation is measured") and a CSV with every number, for plots and for docs/benchmarks.md.

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <QString>

#include "core/image/ImageMetrics.h"
#include "core/project/Project.h"
#include "render/IblPrecompute.h"
#include "render/IblSettings.h"

namespace facet {

struct BenchRow {
    std::string group; // BenchConfig
    std::string config;
    IblSettings settings;
    IblMethod method = IblMethod::SplitSum;
    int iblSamples = 0; // per pixel of a Fis or Reference render; 0 for the split sum
    std::string environment; // BenchEnvironment::label
    std::string material; // "metal" or "dielectric"
    double roughness = 0.0;
    int size = 0; // reference view size x size
    int truthSamplesPerPixel = 0;
    // The fastest of the precompute runs of this configuration under this environment (cache
    // bypassed), with its per-pass times; the same for every row of the pair.
    IblStats ibl;
    // The median of the repeats' precompute totals (ibl.msTotal is their minimum), and how many
    // there were: on a shared machine the spread says how far to trust one row against another.
    double iblMedianMs = 0.0;
    int iblRepeats = 0;
    // ibl.msTotal less the passes the configuration does not use (the irradiance cubemap when
    // irradiance comes from SH: IblPrecompute computes both today); for Reference, the source
    // textures and its DFG table only (the cubes draw the background, not the sphere).
    double iblNeededMs = 0.0;
    // Draw + read-back of the size x size image; for Reference every draw of its iblSamples
    // (FrameRenderer::renderConverged), which is that method's cost.
    double renderMs = 0.0;
    int draws = 0; // renderConverged's draws (1 for the split sum)
    double noise = 0.0; // Reference: FrameAccumulator's noise estimate over the interior sphere; else NaN
    ImageErrorStats error; // GPU image against the ground truth
    // The truth's own noise (--truth-noise: relative RMSE against a truth of another seed / sqrt 2);
    // NaN when not measured.
    double truthNoise = std::nan("");
};

// The CSV header, comma-separated, no trailing newline: settings, times, errors, then the
// configuration's summary over all its rows (config_median_rel_rmse, ...; the same on each).
std::string benchCsvHeader();
// Writes the header and one line per row through writeFileAtomically (core/support/AtomicFile.h). False with
// `error`
// ("facet bench: --csv <path>: <reason>") when it cannot.
bool writeBenchCsv(const QString& path, const std::vector<BenchRow>& rows, std::string* error);

// The tables: per configuration, time against mean/median/max error (over every environment,
// material and roughness); then the mean error per roughness and per environment. Errors in percent.
void printBenchTables(std::FILE* out, const std::vector<BenchRow>& rows);

} // namespace facet
