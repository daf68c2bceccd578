#include "BenchReport.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

#include "core/support/AtomicFile.h"

namespace facet {

namespace {

using Columns = std::vector<std::pair<std::string, std::string>>;

std::string number(double value, const char* format = "%.6g")
{
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, format, value);
    return buffer;
}

// Every IblSettings field, by the name docs/ibl.md uses; header and rows both come from here so
// they cannot drift apart. A field added to IblSettings belongs here too.
Columns settingsColumns(const IblSettings& s)
{
    return {
        {"cube_size", std::to_string(s.cubeSize)},
        {"prefilter_size", std::to_string(s.prefilterSize)},
        {"prefilter_mip_levels", std::to_string(s.prefilterMipLevels)},
        {"prefilter_samples", std::to_string(s.prefilterSamples)},
        {"irradiance", s.irradiance == IblSettings::Irradiance::SH ? "sh" : "map"},
        {"irradiance_size", std::to_string(s.irradianceSize)},
        {"irradiance_samples", std::to_string(s.irradianceSamples)},
        {"dfg_size", std::to_string(s.dfgSize)},
        {"dfg_samples", std::to_string(s.dfgSamples)},
    };
}

// The relative RMSE of a configuration over every environment, material and roughness.
struct ConfigSummary {
    double mean = 0.0;
    double median = 0.0;
    double max = 0.0;
};

// Median of `values` (sorted here); NaN when any value is NaN or there is none, so a broken
// render shows instead of sorting somewhere (std::sort with NaN is undefined).
double medianOf(std::vector<double> values)
{
    if (values.empty() || std::any_of(values.begin(), values.end(), [](double v) { return std::isnan(v); }))
        return std::nan("");
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

ConfigSummary summarize(const std::vector<BenchRow>& rows, const std::string& config)
{
    std::vector<double> errors;
    for (const BenchRow& row : rows)
        if (row.config == config)
            errors.push_back(row.error.relativeRmse);
    ConfigSummary summary;
    if (errors.empty())
        return summary;
    double sum = 0.0;
    for (double e : errors) {
        sum += e;
        // NaN is the worst: it must show, not vanish in std::max.
        summary.max = std::isnan(e) || std::isnan(summary.max) ? std::nan("") : std::max(summary.max, e);
    }
    summary.mean = sum / double(errors.size());
    summary.median = medianOf(errors);
    return summary;
}

Columns rowColumns(const BenchRow& row, const ConfigSummary& summary)
{
    Columns columns = {
        {"group", row.group},
        {"config", row.config},
        {"method", toString(row.method)},
        {"ibl_samples", std::to_string(row.iblSamples)},
        {"environment", row.environment},
        {"material", row.material},
        {"roughness", number(row.roughness)},
        {"size", std::to_string(row.size)},
        {"truth_spp", std::to_string(row.truthSamplesPerPixel)},
    };
    for (auto& column : settingsColumns(row.settings))
        columns.push_back(std::move(column));
    const Columns measured = {
        {"ibl_ms", number(row.ibl.msTotal, "%.2f")},
        {"ibl_needed_ms", number(row.iblNeededMs, "%.2f")},
        {"ibl_median_ms", number(row.iblMedianMs, "%.2f")},
        {"ibl_repeats", std::to_string(row.iblRepeats)},
        {"ibl_equirect_to_cube_ms", number(row.ibl.msEquirectToCube, "%.2f")},
        {"ibl_prefilter_ms", number(row.ibl.msPrefilter, "%.2f")},
        {"ibl_irradiance_ms", number(row.ibl.msIrradiance, "%.2f")},
        {"ibl_dfg_ms", number(row.ibl.msDfg, "%.2f")},
        {"ibl_sh_ms", number(row.ibl.msSh, "%.2f")},
        {"ibl_source_ms", number(row.ibl.msSource, "%.2f")},
        {"render_ms", number(row.renderMs, "%.2f")},
        {"draws", std::to_string(row.draws)},
        {"noise", number(row.noise)},
        {"rel_rmse", number(row.error.relativeRmse)},
        {"max_rel_error", number(row.error.maxRelativeError)},
        {"mean_rel_error", number(row.error.meanRelativeError)},
        {"pixels", std::to_string(row.error.pixelCount)},
        {"truth_noise", number(row.truthNoise)},
        {"config_mean_rel_rmse", number(summary.mean)},
        {"config_median_rel_rmse", number(summary.median)},
        {"config_max_rel_rmse", number(summary.max)},
    };
    columns.insert(columns.end(), measured.begin(), measured.end());
    return columns;
}

// Names and labels are ours (no commas or quotes), but a user's file name as an environment
// label may hold anything: quote when needed (RFC 4180).
std::string csvField(const std::string& text)
{
    if (text.find_first_of(",\"\n\r") == std::string::npos)
        return text;
    std::string quoted = "\"";
    for (char c : text) {
        if (c == '"')
            quoted += '"';
        quoted += c;
    }
    return quoted + '"';
}

std::string joinCsv(const Columns& columns, bool names)
{
    std::string line;
    for (const auto& [name, value] : columns) {
        if (!line.empty())
            line += ',';
        line += csvField(names ? name : value);
    }
    return line;
}

// "256/128x6@128 map32/1536": cube / prefilter size x levels @ samples, irradiance; for a
// Reference row its samples per pixel ("reference 1024 spp"), for Fis its samples and the cube
// it reads ("fis 32 spp 256").
std::string settingsSummary(const BenchRow& row)
{
    if (row.method == IblMethod::Reference)
        return std::string(toString(row.method)) + " " + std::to_string(row.iblSamples) + " spp";
    if (row.method == IblMethod::Fis)
        return std::string(toString(row.method)) + " " + std::to_string(row.iblSamples) + " spp "
            + std::to_string(row.settings.cubeSize);
    const IblSettings& s = row.settings;
    const std::string irradiance = s.irradiance == IblSettings::Irradiance::SH
        ? std::string("sh9")
        : "map" + std::to_string(s.irradianceSize) + "/" + std::to_string(s.irradianceSamples);
    return std::to_string(s.cubeSize) + "/" + std::to_string(s.prefilterSize) + "x"
        + std::to_string(s.prefilterMipLevels) + "@" + std::to_string(s.prefilterSamples) + " " + irradiance;
}

// Configurations in the order they first appear (the order they ran).
std::vector<std::string> configOrder(const std::vector<BenchRow>& rows)
{
    std::vector<std::string> order;
    for (const BenchRow& row : rows)
        if (std::find(order.begin(), order.end(), row.config) == order.end())
            order.push_back(row.config);
    return order;
}

template <typename T, typename Key> std::vector<T> distinct(const std::vector<BenchRow>& rows, Key key)
{
    std::vector<T> values;
    for (const BenchRow& row : rows)
        if (std::find(values.begin(), values.end(), key(row)) == values.end())
            values.push_back(key(row));
    return values;
}

struct Mean {
    double sum = 0.0;
    int count = 0;
    void add(double value)
    {
        sum += value;
        ++count;
    }
    double value() const { return count ? sum / count : std::nan(""); }
};

std::string percent(double fraction)
{
    return std::isfinite(fraction) ? number(100.0 * fraction, "%.2f") : std::string("n/a");
}

} // namespace

std::string benchCsvHeader()
{
    return joinCsv(rowColumns(BenchRow {}, ConfigSummary {}), true);
}

bool writeBenchCsv(const QString& path, const std::vector<BenchRow>& rows, std::string* error)
{
    std::string text = benchCsvHeader() + "\n";
    std::map<std::string, ConfigSummary> summaries;
    for (const std::string& config : configOrder(rows))
        summaries[config] = summarize(rows, config);
    for (const BenchRow& row : rows)
        text += joinCsv(rowColumns(row, summaries[row.config]), false) + "\n";
    std::string reason;
    if (!writeFileAtomically(path.toStdString(), text, &reason)) {
        if (error)
            *error = "facet bench: --csv " + path.toStdString() + ": " + reason;
        return false;
    }
    return true;
}

void printBenchTables(std::FILE* out, const std::vector<BenchRow>& rows)
{
    if (rows.empty())
        return;
    const std::vector<std::string> configs = configOrder(rows);
    const auto roughnesses = distinct<double>(rows, [](const BenchRow& r) { return r.roughness; });
    const auto environments = distinct<std::string>(rows, [](const BenchRow& r) { return r.environment; });

    std::fprintf(out,
        "Time against error per configuration. Times in ms, the median over the environments (the\n"
        "precompute's cost does not depend on the map's content; the median drops a run a neighbour\n"
        "slowed): ibl = a fresh IBL precompute (no cache), needed = without the passes the configuration\n"
        "does not use (reference: its source textures and DFG table; fis: those, the environment\n"
        "cube and irradiance), then its prefilter and irradiance passes; render = one %dx%d frame,\n"
        "the mean over the cases (fis, reference: every draw of its samples, the method's cost); noise = "
        "reference's own noise estimate, in %%.\n"
        "Errors: relative RMSE over the sphere against the ground truth (%d spp), in %%: the mean per\n"
        "material, the mean, median and max over all. The CSV has every row and the per-pixel errors.\n\n",
        rows.front().size, rows.front().size, rows.front().truthSamplesPerPixel);
    std::fprintf(out, "%-20s %-26s %8s %8s %8s %8s %8s %6s %7s %7s %7s %7s %7s\n", "config", "settings",
        "ibl", "needed", "prefilt", "irrad", "render", "noise", "metal", "dielec", "mean", "median", "max");
    for (const std::string& config : configs) {
        Mean metal, dielectric, render, noise;
        std::map<std::string, const BenchRow*> byEnvironment; // the precompute is per (config, environment)
        const BenchRow* first = nullptr;
        for (const BenchRow& row : rows) {
            if (row.config != config)
                continue;
            first = first ? first : &row;
            const double e = row.error.relativeRmse;
            (row.material == "metal" ? metal : dielectric).add(e);
            render.add(row.renderMs);
            if (std::isfinite(row.noise)) // Reference after two draws or more
                noise.add(row.noise);
            byEnvironment[row.environment] = &row;
        }
        auto median = [&](auto field) {
            std::vector<double> values;
            for (const auto& [environment, row] : byEnvironment)
                values.push_back(field(*row));
            return medianOf(values);
        };
        const ConfigSummary summary = summarize(rows, config);
        std::fprintf(out, "%-20s %-26s %8.1f %8.1f %8.1f %8.1f %8.1f %6s %7s %7s %7s %7s %7s\n",
            config.c_str(), settingsSummary(*first).c_str(),
            median([](const BenchRow& r) { return r.ibl.msTotal; }),
            median([](const BenchRow& r) { return r.iblNeededMs; }),
            median([](const BenchRow& r) { return r.ibl.msPrefilter; }),
            median([](const BenchRow& r) { return r.ibl.msIrradiance; }), render.value(),
            noise.count ? number(100.0 * noise.value(), "%.2f").c_str() : "-", percent(metal.value()).c_str(),
            percent(dielectric.value()).c_str(), percent(summary.mean).c_str(),
            percent(summary.median).c_str(), percent(summary.max).c_str());
    }

    // Pivot: mean relative RMSE (%) per configuration and column value.
    auto pivot = [&](const char* title, const std::vector<std::string>& headers, auto column) {
        std::fprintf(out, "\n%s\n%-20s", title, "config");
        for (const std::string& header : headers)
            std::fprintf(out, " %9s", header.c_str());
        std::fprintf(out, "\n");
        for (const std::string& config : configs) {
            std::fprintf(out, "%-20s", config.c_str());
            for (std::size_t i = 0; i < headers.size(); ++i) {
                Mean mean;
                for (const BenchRow& row : rows)
                    if (row.config == config && column(row) == i)
                        mean.add(row.error.relativeRmse);
                std::fprintf(out, " %9s", percent(mean.value()).c_str());
            }
            std::fprintf(out, "\n");
        }
    };
    std::vector<std::string> roughnessHeaders;
    for (double r : roughnesses)
        roughnessHeaders.push_back("r=" + number(r, "%.2f"));
    pivot("Relative RMSE (%) by roughness, mean over environments and materials:", roughnessHeaders,
        [&](const BenchRow& row) {
            return std::size_t(
                std::find(roughnesses.begin(), roughnesses.end(), row.roughness) - roughnesses.begin());
        });
    std::vector<std::string> environmentHeaders;
    for (const std::string& e : environments)
        environmentHeaders.push_back(e.substr(0, 9));
    pivot("Relative RMSE (%) by environment, mean over materials and roughness:", environmentHeaders,
        [&](const BenchRow& row) {
            return std::size_t(
                std::find(environments.begin(), environments.end(), row.environment) - environments.begin());
        });

    // --truth-noise: once per case (every configuration's rows share their case's truth).
    std::map<std::tuple<std::string, std::string, double>, double> truthNoise;
    for (const BenchRow& row : rows)
        if (!std::isnan(row.truthNoise))
            truthNoise[{row.environment, row.material, row.roughness}] = row.truthNoise;
    if (truthNoise.empty())
        return;
    std::vector<double> all;
    for (const auto& [ignored, noise] : truthNoise)
        all.push_back(noise);
    std::fprintf(out,
        "\nThe ground truth's own noise (relative RMSE against a truth of another seed / sqrt 2), in %%:\n"
        "median %s, max %s over %zu cases; by roughness (max over environments and materials):",
        percent(medianOf(all)).c_str(), percent(*std::max_element(all.begin(), all.end())).c_str(),
        all.size());
    for (double r : roughnesses) {
        double worst = 0.0;
        for (const auto& [key, noise] : truthNoise)
            if (std::get<2>(key) == r)
                worst = std::max(worst, noise);
        std::fprintf(out, " r=%s %s", number(r, "%.2f").c_str(), percent(worst).c_str());
    }
    std::fprintf(out, "\n");
}

} // namespace facet
