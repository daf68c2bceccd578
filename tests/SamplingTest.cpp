// Samplers of core/shading/Sampling.h and core/ibl/EnvironmentSampler.h: every pdf integrates to one and
// matches the histogram of the samples it claims to describe (a chi-square-style test, after
// Mitsuba's and PBRT's sampler tests).

#include <cmath>
#include <cstdint>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include <QtTest/QTest>

#include <glm/geometric.hpp>

#include "core/ibl/EnvironmentSampler.h"
#include "core/ibl/EnvironmentSamplingTables.h"
#include "core/shading/Sampling.h"

using namespace facet;
using namespace facet::sampling;

namespace {

constexpr double kPi = std::numbers::pi;

// Compares the histogram of `count` sampled directions over a (cos theta, phi) grid of the
// sphere with the expected counts from integrating `pdf` (solid angle) over each cell.
// Returns the largest deviation in standard deviations over cells expecting >= 20 samples,
// and the total probability the pdf assigns to the sphere.
template <typename Sample, typename Pdf>
std::pair<double, double> histogramDeviation(Sample sample, Pdf pdf, int count, int subdivisions = 12)
{
    constexpr int kThetaBins = 20;
    constexpr int kPhiBins = 40;
    std::vector<double> observed(kThetaBins * kPhiBins, 0.0);
    Pcg32 rng(1234);
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 d = sample(rng.next2D());
        if (!(std::abs(glm::length(d) - 1.0) < 1e-6))
            continue;
        const int t = std::clamp(int((d.z + 1.0) * 0.5 * kThetaBins), 0, kThetaBins - 1);
        double phi = std::atan2(d.y, d.x);
        if (phi < 0.0)
            phi += 2.0 * kPi;
        const int p = std::clamp(int(phi / (2.0 * kPi) * kPhiBins), 0, kPhiBins - 1);
        observed[t * kPhiBins + p] += 1.0;
    }
    double worst = 0.0;
    double total = 0.0;
    // Sub-cells per cell side for integrating the pdf: a pdf with sharp edges (an environment's
    // bright texels) needs more, or the expected counts, not the sampler, are off.
    const int kSub = subdivisions;
    for (int t = 0; t < kThetaBins; ++t)
        for (int p = 0; p < kPhiBins; ++p) {
            double integral = 0.0;
            for (int i = 0; i < kSub; ++i)
                for (int j = 0; j < kSub; ++j) {
                    const double z = -1.0 + 2.0 * (t + (i + 0.5) / kSub) / kThetaBins;
                    const double phi = 2.0 * kPi * (p + (j + 0.5) / kSub) / kPhiBins;
                    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
                    integral += pdf(glm::dvec3(r * std::cos(phi), r * std::sin(phi), z));
                }
            // Cell area in (z, phi) = solid angle: (2 / T) (2 pi / P), split into kSub^2 parts.
            integral *= (2.0 / kThetaBins) * (2.0 * kPi / kPhiBins) / (kSub * kSub);
            total += integral;
            const double expected = integral * count;
            if (expected >= 20.0)
                worst = std::max(worst, std::abs(observed[t * kPhiBins + p] - expected) / std::sqrt(expected));
        }
    return {worst, total};
}

// Whether points [first, first + 2^m) of the Sobol' sequence form a (0, m, 2)-net: for every
// split a + b = m, the 2^a x 2^b boxes of the unit square each hold exactly one point.
bool isNet(std::uint32_t first, int m, std::string* why)
{
    const std::uint32_t count = 1u << m;
    for (int a = 0; a <= m; ++a) {
        const int b = m - a;
        std::vector<int> hits(count, 0);
        for (std::uint32_t i = first; i < first + count; ++i) {
            const glm::uvec2 bits = sobol2DBits(i);
            const std::uint32_t bx = a == 0 ? 0u : bits.x >> (32 - a);
            const std::uint32_t by = b == 0 ? 0u : bits.y >> (32 - b);
            ++hits[std::size_t((bx << b) | by)];
        }
        for (std::size_t box = 0; box < hits.size(); ++box)
            if (hits[box] != 1) {
                *why = "points " + std::to_string(first) + ".." + std::to_string(first + count - 1)
                    + ", boxes 2^" + std::to_string(a) + " x 2^" + std::to_string(b) + ": box "
                    + std::to_string(box) + " holds " + std::to_string(hits[box]);
                return false;
            }
    }
    return true;
}

// Row-major weights for a Distribution2D, `height` rows of `width`.
struct WeightGrid {
    std::vector<double> weights;
    int width = 0;
    int height = 0;
};

} // namespace

class SamplingTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void lowDiscrepancy()
    {
        QCOMPARE(radicalInverse(0), 0.0);
        QCOMPARE(radicalInverse(1), 0.5);
        QCOMPARE(radicalInverse(2), 0.25);
        QCOMPARE(radicalInverse(3), 0.75);
        QCOMPARE(radicalInverse(6), 0.375);
        QCOMPARE(hammersley(3, 8), glm::dvec2(0.375, 0.75));
        // Deterministic and uniform-ish generator.
        Pcg32 a(42, 7);
        Pcg32 b(42, 7);
        Pcg32 c(42, 8);
        double mean = 0.0;
        bool differs = false;
        for (int i = 0; i < 100000; ++i) {
            const double x = a.nextDouble();
            QCOMPARE(x, b.nextDouble());
            differs = differs || x != c.nextDouble();
            QVERIFY(x >= 0.0 && x < 1.0);
            mean += x;
        }
        QVERIFY(differs);
        QVERIFY(std::abs(mean / 100000 - 0.5) < 0.005);
    }

    void orthonormalBasis()
    {
        Pcg32 rng(3);
        for (int i = 0; i < 1000; ++i) {
            glm::dvec3 n = sampleUniformSphere(rng.next2D());
            if (i == 0)
                n = {0.0, 0.0, -1.0}; // the singular case of naive constructions
            glm::dvec3 t;
            glm::dvec3 b;
            buildOrthonormalBasis(n, t, b);
            QVERIFY(std::abs(glm::dot(t, b)) < 1e-12 && std::abs(glm::dot(t, n)) < 1e-12 && std::abs(glm::dot(b, n)) < 1e-12);
            QVERIFY(std::abs(glm::length(t) - 1.0) < 1e-12 && std::abs(glm::length(b) - 1.0) < 1e-12);
            QVERIFY(glm::length(glm::cross(t, b) - n) < 1e-12); // right-handed
        }
    }

    void cosineHemisphere()
    {
        const auto [worst, total] = histogramDeviation([](glm::dvec2 u) { return sampleCosineHemisphere(u); },
                                                       [](glm::dvec3 d) { return pdfCosineHemisphere(d.z); }, 400000);
        QVERIFY2(std::abs(total - 1.0) < 1e-3, qPrintable(QString::number(total)));
        QVERIFY2(worst < 5.0, qPrintable(QString::number(worst)));
    }

    void uniformSphere()
    {
        const auto [worst, total] = histogramDeviation([](glm::dvec2 u) { return sampleUniformSphere(u); },
                                                       [](glm::dvec3) { return 1.0 / (4.0 * kPi); }, 400000);
        QVERIFY(std::abs(total - 1.0) < 1e-6);
        QVERIFY2(worst < 5.0, qPrintable(QString::number(worst)));
    }

    void ggxReflection_data()
    {
        QTest::addColumn<double>("alpha");
        QTest::addColumn<double>("NoV");
        QTest::addColumn<int>("sampler"); // 0: NDF, 1: VNDF (Heitz), 2: VNDF by spherical caps
        static const char* const kNames[] = {"NDF", "VNDF", "VNDF caps"};
        for (double alpha : {0.2, 0.5, 1.0})
            for (double NoV : {0.15, 0.6, 1.0})
                for (int sampler : {0, 1, 2})
                    QTest::addRow("%s alpha %g n.v %g", kNames[sampler], alpha, NoV)
                        << alpha << NoV << sampler;
    }
    // The reflected directions' histogram matches pdfGGXReflection / pdfVNDFReflection. Both
    // lose the samples that reflect below the horizon, so the pdf's total is the fraction kept.
    void ggxReflection()
    {
        QFETCH(double, alpha);
        QFETCH(double, NoV);
        QFETCH(int, sampler);
        const bool visible = sampler != 0;
        const glm::dvec3 v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
        const auto visibleNormal = [&](glm::dvec2 u) {
            return sampler == 2 ? importanceSampleVNDFSphericalCap(u, v, alpha)
                                : importanceSampleVNDF(u, v, alpha);
        };
        auto sample = [&](glm::dvec2 u) {
            const glm::dvec3 h = visible ? visibleNormal(u) : importanceSampleGGX(u, alpha);
            const glm::dvec3 l = reflectAbout(v, h);
            return (l.z > 0.0 && glm::dot(v, h) > 0.0) ? l : glm::dvec3(0.0); // rejected: not counted
        };
        auto pdf = [&](glm::dvec3 l) {
            if (l.z <= 0.0)
                return 0.0;
            const glm::dvec3 h = glm::normalize(v + l);
            return visible ? pdfVNDFReflection(NoV, h.z, alpha) : pdfGGXReflection(h.z, glm::dot(v, h), alpha);
        };
        const auto [worst, total] = histogramDeviation(sample, pdf, 400000);
        QVERIFY2(total <= 1.0 + 2e-3 && total > 0.3, qPrintable(QString::number(total)));
        QVERIFY2(worst < 5.0, qPrintable(QString::number(worst)));
        // From normal incidence a reflection stays above the horizon iff n.h > 1/sqrt(2): the
        // kept fraction is GGX's CDF at 45 degrees, 1 / (1 + alpha^2) (alpha = 1: exactly 1/2).
        if (NoV == 1.0)
            QVERIFY2(std::abs(total - 1.0 / (1.0 + alpha * alpha)) < 5e-3, qPrintable(QString::number(total)));
        // Visible-normal sampling never produces a back-facing microfacet.
        if (visible) {
            Pcg32 rng(5);
            for (int i = 0; i < 10000; ++i)
                QVERIFY(glm::dot(v, visibleNormal(rng.next2D())) >= 0.0);
        }
    }

    // Every prefix of 2^m points, and every aligned block of 2^m after it, is a (0, m, 2)-net: what
    // lets a pixel accumulate N samples over frames of any size and still hold a stratified set.
    void sobolNets_data()
    {
        QTest::addColumn<int>("m");
        for (int m = 1; m <= 10; ++m)
            QTest::addRow("m %d", m) << m;
    }
    void sobolNets()
    {
        QFETCH(int, m);
        std::string why;
        for (std::uint32_t block : {0u, 1u, 2u, 7u})
            QVERIFY2(isNet(block << m, m, &why), why.c_str());
        // Dimension 1 is the radical inverse; the doubles are the bits / 2^32, exactly.
        for (std::uint32_t i = 0; i < (1u << m); ++i) {
            QCOMPARE(sobol2D(i).x, radicalInverse(i));
            QCOMPARE(sobol2D(i).y, double(sobol2DBits(i).y) / 4294967296.0);
        }
    }

    void sobolFirstPoints()
    {
        // Dimension 2 of Sobol' (direction numbers 1/2, 3/4, 5/8, 15/16), indexed by s directly
        // (not in Gray-code order): s = 4 is v_3 = 0.101b, s = 5 is v_1 ^ v_3 = 0.001b.
        const double expected[8] = {0.0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
        for (std::uint32_t s = 0; s < 8; ++s)
            QCOMPARE(sobol2D(s).y, expected[s]);
        QCOMPARE(sobol2DBits(16).y, 0x88000000u); // v_5 = v_4 ^ (v_4 >> 1) = 0.10001b
    }

    // Golden values of the pcg hash, from the listing of Jarzynski & Olano 2020 evaluated
    // independently (Python integers, masked to 32 bits).
    void pcgHashGolden_data()
    {
        QTest::addColumn<quint32>("value");
        QTest::addColumn<quint32>("hash");
        QTest::newRow("0") << 0u << 129708002u;
        QTest::newRow("1") << 1u << 2831084092u;
        QTest::newRow("2") << 2u << 2055130248u;
        QTest::newRow("42") << 42u << 1223963391u;
        QTest::newRow("0xdeadbeef") << 0xdeadbeefu << 1730779506u;
        QTest::newRow("0xffffffff") << 0xffffffffu << 3861530882u;
    }
    void pcgHashGolden()
    {
        QFETCH(quint32, value);
        QFETCH(quint32, hash);
        QCOMPARE(pcgHash(value), hash);
    }

    // The per-pixel shift changes with each of its inputs, and the shifted points stay in [0, 1)
    // and equal frac(point + shift) to the 24 bits kept.
    void cranleyPattersonShifts()
    {
        const glm::uvec2 base = cranleyPattersonShift(3, 5, 7, 0);
        QVERIFY(base != cranleyPattersonShift(4, 5, 7, 0));
        QVERIFY(base != cranleyPattersonShift(3, 6, 7, 0));
        QVERIFY(base != cranleyPattersonShift(3, 5, 8, 0));
        QVERIFY(base != cranleyPattersonShift(3, 5, 7, 1));
        QVERIFY(base != cranleyPattersonShift(5, 3, 7, 0)); // x and y are not interchangeable
        QCOMPARE(base, cranleyPattersonShift(3, 5, 7, 0));
        std::set<std::uint64_t> seen;
        for (std::uint32_t y = 0; y < 64; ++y)
            for (std::uint32_t x = 0; x < 64; ++x) {
                const glm::uvec2 shift = cranleyPattersonShift(x, y, 1, 1);
                seen.insert((std::uint64_t(shift.x) << 32u) | shift.y);
            }
        QCOMPARE(int(seen.size()), 64 * 64);
        for (const glm::uvec2 shift : {glm::uvec2(0u), glm::uvec2(0xffffffffu), base})
            for (std::uint32_t s = 0; s < 64; ++s) {
                const glm::dvec2 u = shiftedSobol2D(s, shift);
                QVERIFY(u.x >= 0.0 && u.x < 1.0 && u.y >= 0.0 && u.y < 1.0);
                const glm::dvec2 exact = glm::fract(sobol2D(s) + glm::dvec2(shift) / 4294967296.0);
                const glm::dvec2 gap = glm::abs(u - exact);
                // Truncation to 24 bits: below by less than 2^-24 (or wrapped from just below 1).
                for (int c = 0; c < 2; ++c)
                    QVERIFY2(gap[c] < 5.9604644775390625e-8 || gap[c] > 1.0 - 5.9604644775390625e-8,
                        qPrintable(QString::number(gap[c])));
                QVERIFY(float(u.x) == u.x && float(u.y) == u.y); // exact floats, as the GPU has them
            }
        QVERIFY(shiftedSobol2D(0, glm::uvec2(0xffffffffu)).x < 1.0);
    }

    // The float tables and their search (the CPU twin of environment_sampling.glsl) land in the
    // cell Distribution2D lands in, with its pdf, for 1024 u; edge maps included.
    void sampleTablesMatchesDistribution_data()
    {
        QTest::addColumn<std::vector<double>>("weights");
        QTest::addColumn<int>("width");
        QTest::addColumn<int>("height");
        auto grid = [](int w, int h, auto f) {
            std::vector<double> weights(std::size_t(w) * std::size_t(h));
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    weights[std::size_t(y) * std::size_t(w) + std::size_t(x)] = f(x, y);
            return weights;
        };
        QTest::newRow("bright spot 64x32") << grid(64, 32, [](int x, int y) {
            return (x >= 10 && x < 14 && y >= 20 && y < 24) ? 5000.0 : 0.1 + 0.01 * x;
        }) << 64 << 32;
        // Eleven decades, as in an HDRI with a sun: dim cells whose float CDF steps are 0.
        QTest::newRow("dynamic range 1e-6..1e5") << grid(128, 64, [](int x, int y) {
            return std::pow(10.0, -6.0 + 11.0 * double((x * 7 + y * 13) % 97) / 96.0);
        }) << 128 << 64;
        QTest::newRow("all zero") << grid(16, 8, [](int, int) { return 0.0; }) << 16 << 8;
        QTest::newRow("a zero row") << grid(16, 8, [](int x, int y) { return y == 3 ? 0.0 : 1.0 + x; }) << 16
                                    << 8;
        QTest::newRow("first and last rows zero")
            << grid(16, 8, [](int x, int y) { return (y == 0 || y == 7) ? 0.0 : 1.0 + x * y; }) << 16 << 8;
        QTest::newRow("zero cells in a row")
            << grid(16, 8, [](int x, int) { return x % 3 == 0 ? 0.0 : 2.0; }) << 16 << 8;
        QTest::newRow("1x8") << grid(1, 8, [](int, int y) { return 1.0 + y * y; }) << 1 << 8;
        QTest::newRow("8x1") << grid(8, 1, [](int x, int) { return 1.0 + x * x; }) << 8 << 1;
        QTest::newRow("1x1") << grid(1, 1, [](int, int) { return 3.0; }) << 1 << 1;
        QTest::newRow("odd 37x19") << grid(37, 19, [](int x, int y) { return double((x * y) % 5); }) << 37
                                   << 19;
    }
    void sampleTablesMatchesDistribution()
    {
        QFETCH(std::vector<double>, weights);
        QFETCH(int, width);
        QFETCH(int, height);
        const Distribution2D distribution(weights, std::size_t(width), std::size_t(height));
        const EnvironmentSamplingTables tables = tablesFromDistribution(distribution);
        QCOMPARE(tables.width, width);
        QCOMPARE(tables.height, height);
        Pcg32 rng(17);
        double worstPdf = 0.0;
        double worstUv = 0.0;
        int onEdges = 0;
        for (int i = 0; i < 1024; ++i) {
            // Float u, as the GPU gets them (exactly representable in both).
            glm::vec2 u(float(rng.nextDouble()), float(rng.nextDouble()));
            if (i == 0)
                u = glm::vec2(0.0f);
            if (i == 1)
                u = glm::vec2(0.99999994f);
            double pdfRow = 0.0;
            double pdfColumn = 0.0;
            std::size_t row = 0;
            std::size_t column = 0;
            const double y = distribution.marginal().sampleContinuous(u.y, &pdfRow, &row);
            const double x = distribution.conditional(row).sampleContinuous(u.x, &pdfColumn, &column);
            double pdf = 0.0;
            QCOMPARE(distribution.sampleContinuous(glm::dvec2(u), &pdf), glm::dvec2(x, y));

            float tablePdf = 0.0f;
            glm::ivec2 cell;
            const glm::vec2 uv = sampleTables(tables, u, &tablePdf, &cell);
            const QByteArray where = QStringLiteral("u (%1, %2)")
                                         .arg(double(u.x), 0, 'g', 9)
                                         .arg(double(u.y), 0, 'g', 9)
                                         .toUtf8();
            QVERIFY2(cell == glm::ivec2(int(column), int(row)), where.constData());
            QVERIFY2(uv.x >= 0.0f && uv.x < 1.0f && uv.y >= 0.0f && uv.y < 1.0f, where.constData());
            QVERIFY2(pdf > 0.0, where.constData()); // never a cell of probability 0
            worstPdf = std::max(worstPdf, std::abs(double(tablePdf) - pdf) / pdf);
            // The float search's (u - cdf[i]) / width carries the CDF's rounding (2^-25 near 1)
            // divided by the cell's width: in units of the unit square, 1e-7 / pdf of that axis.
            const double boundX = 2e-7 / pdfColumn + 2e-7;
            const double boundY = 2e-7 / pdfRow + 2e-7;
            worstUv = std::max(
                {worstUv, std::abs(double(uv.x) - x) / boundX, std::abs(double(uv.y) - y) / boundY});
            // The density lookup of the point (environmentPdf) gives back the sample's own pdf,
            // unless (cell + du) / n rounded up onto the cell's upper edge (float: 1 in 2^24 of
            // its u), where the lookup reads the neighbour.
            if (tablesPdf(tables, uv) != tablePdf) {
                const bool onEdge
                    = float(cell.x + 1) / float(width) == uv.x || float(cell.y + 1) / float(height) == uv.y;
                QVERIFY2(onEdge, where.constData());
                ++onEdges;
            }
        }
        QVERIFY2(worstPdf < 1e-6, qPrintable(QString::number(worstPdf)));
        QVERIFY2(worstUv <= 1.0, qPrintable(QString::number(worstUv)));
        QVERIFY(onEdges <= 1); // u = 0.99999994 (i = 1) may end on the last nonzero cell's edge
        qInfo("worst pdf relative %.3g, worst uv / bound %.3g", worstPdf, worstUv);
    }

    void distribution2D()
    {
        const std::vector<double> weights = {0.0, 1.0, 2.0, 3.0, 4.0, 0.0, 1.0, 1.0, 8.0, 0.0, 0.5, 0.5};
        const Distribution2D d(weights, 4, 3);
        double sumWeights = 0.0;
        for (double w : weights)
            sumWeights += w;
        std::vector<double> counts(12, 0.0);
        Pcg32 rng(9);
        const int n = 200000;
        for (int i = 0; i < n; ++i) {
            double pdf = 0.0;
            const glm::dvec2 xy = d.sampleContinuous(rng.next2D(), &pdf);
            QVERIFY(xy.x >= 0.0 && xy.x < 1.0 && xy.y >= 0.0 && xy.y < 1.0);
            const int cx = int(xy.x * 4);
            const int cy = int(xy.y * 3);
            QVERIFY(std::abs(pdf - d.pdf(xy)) < 1e-12);
            QVERIFY(std::abs(pdf - weights[cy * 4 + cx] / sumWeights * 12.0) < 1e-12);
            counts[cy * 4 + cx] += 1.0;
        }
        for (int i = 0; i < 12; ++i) {
            const double expected = weights[i] / sumWeights * n;
            QVERIFY(std::abs(counts[i] - expected) <= 5.0 * std::sqrt(expected) + 1e-9);
        }
    }

    // Environment importance sampling: the pdf is a density over the sphere, the samples follow
    // it, and it prefers the bright part of the image.
    void environmentSampler()
    {
        Image image(64, 32, glm::vec4(0.1f, 0.1f, 0.1f, 1.0f));
        for (int y = 4; y < 8; ++y)
            for (int x = 10; x < 14; ++x)
                image.at(x, y) = glm::vec4(50.0f, 40.0f, 30.0f, 1.0f); // a "sun" in the upper half
        Environment environment(image, "test");
        environment.setRotationDegrees(30.0);
        const EnvironmentSampler sampler(environment);
        const auto [worst, total] = histogramDeviation(
            [&](glm::dvec2 u) {
                double pdf = 0.0;
                const glm::dvec3 d = sampler.sample(u, &pdf);
                if (!(std::abs(pdf - sampler.pdf(d)) <= 1e-6 * pdf))
                    return glm::dvec3(0.0); // inconsistent pdf: dropped, and the histogram fails
                return d;
            },
            [&](glm::dvec3 d) { return sampler.pdf(d); }, 400000, 48);
        QVERIFY2(std::abs(total - 1.0) < 5e-3, qPrintable(QString::number(total)));
        QVERIFY2(worst < 5.0, qPrintable(QString::number(worst)));
        // E[L / pdf] = integral of L over the sphere, which for this image is known in closed form
        // only approximately; check instead that sampling the sun direction is far more likely.
        const glm::dvec3 sun = environment.toWorldFrame(directionFromEquirectUv({11.5 / 64.0, 1.0 - 5.5 / 32.0}));
        const glm::dvec3 away = environment.toWorldFrame(directionFromEquirectUv({40.5 / 64.0, 1.0 - 20.5 / 32.0}));
        QVERIFY(sampler.pdf(sun) > 100.0 * sampler.pdf(away));
    }
};

QTEST_APPLESS_MAIN(SamplingTest)
#include "SamplingTest.moc"
