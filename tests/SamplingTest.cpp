// Samplers of core/Sampling.h and core/EnvironmentSampler.h: every pdf integrates to one and
// matches the histogram of the samples it claims to describe (a chi-square-style test, after
// Mitsuba's and PBRT's sampler tests).

#include <cmath>
#include <numbers>
#include <vector>

#include <QtTest/QTest>

#include <glm/geometric.hpp>

#include "core/EnvironmentSampler.h"
#include "core/Sampling.h"

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
        QTest::addColumn<bool>("visible");
        for (double alpha : {0.2, 0.5, 1.0})
            for (double NoV : {0.15, 0.6, 1.0})
                for (bool visible : {false, true})
                    QTest::addRow("%s alpha %g n.v %g", visible ? "VNDF" : "NDF", alpha, NoV) << alpha << NoV << visible;
    }
    // The reflected directions' histogram matches pdfGGXReflection / pdfVNDFReflection. Both
    // lose the samples that reflect below the horizon, so the pdf's total is the fraction kept.
    void ggxReflection()
    {
        QFETCH(double, alpha);
        QFETCH(double, NoV);
        QFETCH(bool, visible);
        const glm::dvec3 v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
        auto sample = [&](glm::dvec2 u) {
            const glm::dvec3 h = visible ? importanceSampleVNDF(u, v, alpha) : importanceSampleGGX(u, alpha);
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
                QVERIFY(glm::dot(v, importanceSampleVNDF(rng.next2D(), v, alpha)) >= 0.0);
        }
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
