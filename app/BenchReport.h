#pragma once
// What `facet bench` measured, one row per (configuration, environment, material, roughness),
// and the two ways it is reported: readable tables (time and error side by side, STYLE.md) and
// a CSV with every number, for plots and for docs/benchmarks.md.

#include <cstdio>
#include <string>
#include <vector>

#include <QString>

#include "core/ImageMetrics.h"
#include "render/IblPrecompute.h"
#include "render/IblSettings.h"

namespace facet {

struct BenchRow {
    std::string group; // BenchConfig
    std::string config;
    IblSettings settings;
    std::string environment; // BenchEnvironment::label
    std::string material; // "metal" or "dielectric"
    double roughness = 0.0;
    int size = 0; // reference view size x size
    int truthSamplesPerPixel = 0;
    // The fastest of the precompute runs of this configuration under this environment (cache
    // bypassed), with its per-pass times; the same for every row of the pair.
    IblStats ibl;
    // ibl.msTotal less the passes the configuration does not use (the irradiance cubemap when
    // irradiance comes from SH: IblPrecompute computes both today).
    double iblNeededMs = 0.0;
    double renderMs = 0.0; // draw + read-back of the size x size image
    ImageErrorStats error; // GPU image against the ground truth
};

// The CSV header, comma-separated, no trailing newline: settings, times, errors.
std::string benchCsvHeader();
// Writes the header and one line per row through writeFileAtomically (core/AtomicFile.h). False with `error`
// ("facet bench: --csv <path>: <reason>") when it cannot.
bool writeBenchCsv(const QString& path, const std::vector<BenchRow>& rows, std::string* error);

// The tables: per configuration, time against mean/max error (over every environment, material
// and roughness); then the mean error per roughness and per environment. Errors in percent.
void printBenchTables(std::FILE* out, const std::vector<BenchRow>& rows);

} // namespace facet
