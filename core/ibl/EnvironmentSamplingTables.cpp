#include "core/ibl/EnvironmentSamplingTables.h"

#include "core/shading/Sampling.h"

#include <algorithm>
#include <cmath>

namespace facet::sampling {

EnvironmentSamplingTables tablesFromDistribution(const Distribution2D& distribution)
{
    EnvironmentSamplingTables t;
    t.width = int(distribution.width());
    t.height = int(distribution.height());
    const auto w = std::size_t(t.width);
    const auto h = std::size_t(t.height);
    t.conditionalCdf.reserve(h * (w + 1));
    t.pdfUv.reserve(h * w);
    for (std::size_t row = 0; row < h; ++row) {
        for (double c : distribution.conditional(row).cdf())
            t.conditionalCdf.push_back(float(c));
        // In double, then rounded once (EnvironmentSamplingTables::pdfUv says why not from the CDF).
        for (std::size_t column = 0; column < w; ++column)
            t.pdfUv.push_back(float(
                distribution.pdf({(double(column) + 0.5) / double(w), (double(row) + 0.5) / double(h)})));
    }
    for (double c : distribution.marginal().cdf())
        t.marginalCdf.push_back(float(c));
    return t;
}

int searchCdf(std::span<const float> cdf, float u)
{
    // Invariant: the answer is in [first, first + length). cdf[0] = 0 <= u for any u >= 0, and
    // each probe halves the range, keeping the upper half when its first entry is still <= u.
    const int cells = int(cdf.size()) - 1;
    int first = 0;
    int length = std::max(cells, 1);
    while (length > 1) {
        const int half = length / 2;
        if (cdf[std::size_t(first + half)] <= u)
            first += half;
        length -= half;
    }
    return first;
}

float sampleCdf(std::span<const float> cdf, float u, int* cellOut)
{
    const int cells = int(cdf.size()) - 1;
    const int cell = searchCdf(cdf, u);
    const float lower = cdf[std::size_t(cell)];
    const float width = cdf[std::size_t(cell) + 1] - lower;
    const float du = width > 0.0f ? (u - lower) / width : 0.5f;
    if (cellOut)
        *cellOut = cell;
    // The largest float below 1 (1 - 2^-24), as Distribution1D clamps to nextafter(1, 0).
    return std::min((float(cell) + std::clamp(du, 0.0f, 1.0f)) / float(cells), 0.99999994f);
}

glm::vec2 sampleTables(
    const EnvironmentSamplingTables& tables, const glm::vec2& u, float* pdfUv, glm::ivec2* cellOut)
{
    int row = 0;
    int column = 0;
    const float v = sampleCdf(tables.marginalCdf, u.y, &row);
    const float x = sampleCdf(tables.conditionalRow(row), u.x, &column);
    if (pdfUv)
        *pdfUv = tables.pdfAt(column, row);
    if (cellOut)
        *cellOut = {column, row};
    return {x, v};
}

float tablesPdf(const EnvironmentSamplingTables& tables, const glm::vec2& uv)
{
    const int column = std::clamp(int(std::max(uv.x, 0.0f) * float(tables.width)), 0, tables.width - 1);
    const int row = std::clamp(int(std::max(uv.y, 0.0f) * float(tables.height)), 0, tables.height - 1);
    return tables.pdfAt(column, row);
}

} // namespace facet::sampling
