#pragma once
// An environment's importance-sampling distribution (core/ibl/EnvironmentSampler.h) as the GPU reads
// it: float tables that render/EnvironmentSource uploads as R32F textures, and the CPU twin of the
// search that resources/shaders/environment_sampling.glsl runs over them. docs/ibl.md
// ("Environment sampling tables") has the layout and the conventions.
//
// Row order is the distribution's, not the image's: row r covers v in [r/H, (r+1)/H), which is
// image row H - 1 - r (v = 1 is the image's top row, docs/architecture.md). Columns are u, texel c
// covering [c/W, (c+1)/W).

#include <glm/vec2.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace facet {

struct EnvironmentSamplingTables {
    int width = 0; // W: texels per row of the environment image the distribution was built on
    int height = 0; // H
    // H rows of W + 1 entries: the normalised CDF of u within each row, 0 first, exactly 1 last.
    std::vector<float> conditionalCdf;
    // H + 1 entries: the normalised CDF of the rows (v), 0 first, exactly 1 last.
    std::vector<float> marginalCdf;
    // H rows of W: the density of (u, v) over the unit square in each cell, computed in double
    // from the distribution (Distribution2D::pdf at the cell's centre) and then rounded. NOT the
    // difference of neighbouring CDF entries: near 1 a float CDF resolves about 6e-8, while a dim
    // cell's probability can be 1e-9, so the difference would be 0 or off by orders of magnitude.
    std::vector<float> pdfUv;

    std::span<const float> conditionalRow(int row) const
    {
        return std::span<const float>(conditionalCdf)
            .subspan(std::size_t(row) * std::size_t(width + 1), std::size_t(width) + 1);
    }
    float pdfAt(int column, int row) const
    {
        return pdfUv[std::size_t(row) * std::size_t(width) + std::size_t(column)];
    }
    // Bytes of the three tables as R32F textures.
    std::size_t bytes() const
    {
        return (conditionalCdf.size() + marginalCdf.size() + pdfUv.size()) * sizeof(float);
    }
};

namespace sampling {

class Distribution2D;

// The float tables of a distribution: its conditional and marginal CDFs rounded to float, and
// pdfUv[r][c] = float(distribution.pdf(cell centre)) computed in double. EnvironmentSampler::tables()
// is this over the environment's distribution.
EnvironmentSamplingTables tablesFromDistribution(const Distribution2D& distribution);

// The largest i in [0, cdf.size() - 1) with cdf[i] <= u (0 when there is none), by the
// fixed-step bisection of environment_sampling.glsl: ceil(log2(n)) probes for n cells, the same
// for every u, so neighbouring GPU invocations do not diverge. cdf is non-decreasing, cdf[0] = 0.
// Taking the LARGEST such i skips cells of zero width, as Distribution1D does (upper_bound - 1).
int searchCdf(std::span<const float> cdf, float u);

// A continuous sample of one CDF, in float as the GLSL computes it: x = (i + du) / n with
// du = (u - cdf[i]) / (cdf[i+1] - cdf[i]) (0.5 for a zero-width cell), clamped below 1: the
// float twin of Distribution1D::sampleContinuous. `cell` receives i.
float sampleCdf(std::span<const float> cdf, float u, int* cell);

// The CPU twin of environment_sampling.glsl sampleEnvironmentUv: v from the marginal with u.y,
// then u from row v's conditional with u.x (the order of Distribution2D::sampleContinuous).
// Returns (u, v) in [0, 1)^2; *pdfUv gets the table's density of the cell it fell in (w.r.t. area
// of the unit square), *cell the (column, row) in distribution order. With the tables of an
// EnvironmentSampler it lands in the cell Distribution2D::sampleContinuous lands in, up to float
// rounding of the CDF (tests/SamplingTest.cpp). When (i + du) / n rounds up in float the sample
// sits on its cell's upper edge, and tablesPdf of that point reads the neighbour (1 in 2^24 of
// the cell's u); the sample's own pdf is *pdfUv.
glm::vec2 sampleTables(
    const EnvironmentSamplingTables& tables, const glm::vec2& u, float* pdfUv, glm::ivec2* cell = nullptr);
// The table's density at (u, v) in [0, 1]^2 (clamped to the last cell at 1): environmentPdf's
// lookup before the change to solid angle.
float tablesPdf(const EnvironmentSamplingTables& tables, const glm::vec2& uv);

} // namespace sampling

} // namespace facet
