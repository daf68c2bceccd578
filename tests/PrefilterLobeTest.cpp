// The prefiltered levels' samples (core/ibl/Prefilter.h prefilterLobeSamples), which the GPU pass reads
// as a table and prefilteredRadiance rotates about R: each sample is a GGX reflection above the
// horizon with its own pdf, the samples are the Hammersley points in order with only those below
// the horizon left out, and a lobe of roughness 1 (D = 1 / pi: l uniform over the sphere) keeps
// half of them with a mean n.l of 1/4. One row per roughness x sample count, the presets' counts
// among them.

#include <cmath>

#include <QtTest/QTest>

#include <glm/geometric.hpp>

#include "core/ibl/Prefilter.h"
#include "core/shading/Brdf.h"
#include "core/shading/Sampling.h"

using namespace facet;

class PrefilterLobeTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void samplesAreTheLobesReflections_data()
    {
        QTest::addColumn<double>("roughness");
        QTest::addColumn<int>("samples");
        for (const double roughness : {0.045, 0.11, 0.23, 0.55, 1.0})
            for (const int samples : {1, 7, 64, 128, 256, 2048})
                QTest::addRow("r %.3f, %d samples", roughness, samples) << roughness << samples;
    }

    void samplesAreTheLobesReflections()
    {
        QFETCH(double, roughness);
        QFETCH(int, samples);
        const double alpha = shading::alphaFromRoughness(roughness);
        const std::vector<PrefilterLobeSample> lobe = prefilterLobeSamples(roughness, samples);
        QVERIFY(!lobe.empty()); // the first point, u = (0, 0), is the lobe's peak: l = n
        QVERIFY(int(lobe.size()) <= samples);

        // The points in order, those below the horizon skipped: walk them alongside.
        const glm::dvec3 n(0.0, 0.0, 1.0);
        std::size_t next = 0;
        for (std::uint32_t i = 0; i < std::uint32_t(samples); ++i) {
            const glm::dvec3 h
                = sampling::importanceSampleGGX(sampling::hammersley(i, std::uint32_t(samples)), alpha);
            const glm::dvec3 l = sampling::reflectAbout(n, h);
            if (l.z <= 0.0)
                continue;
            QVERIFY2(next < lobe.size(), qPrintable(QStringLiteral("point %1 is missing").arg(i)));
            const PrefilterLobeSample& sample = lobe[next++];
            QVERIFY(sample.l.z > 0.0);
            QVERIFY(std::abs(glm::length(sample.l) - 1.0) < 1e-12);
            QVERIFY(glm::length(sample.l - l) < 1e-12);
            // The pdf of l with v = n, Walter's D (n.h) / (4 v.h): D / 4 here.
            const glm::dvec3 half = glm::normalize(sample.l + n);
            const double pdf = sampling::pdfGGXReflection(half.z, half.z, alpha);
            QVERIFY2(std::abs(sample.pdf - pdf) <= 1e-9 * pdf,
                qPrintable(QStringLiteral("point %1: pdf %2, expected %3").arg(i).arg(sample.pdf).arg(pdf)));
        }
        QCOMPARE(next, lobe.size());
    }

    void roughestLobeIsTheWholeSphere()
    {
        // alpha 1: D = 1 / pi, h cosine-distributed, l = reflect(n, h) uniform over the sphere
        // (pdf 1 / (4 pi)): half the points are above the horizon, their mean n.l is 1/2, and
        // over all N points the kept n.l sum to N / 4.
        const int samples = 4096;
        const std::vector<PrefilterLobeSample> lobe = prefilterLobeSamples(1.0, samples);
        double weight = 0.0;
        for (const PrefilterLobeSample& sample : lobe) {
            QVERIFY(std::abs(sample.pdf - 0.25 * shading::kInvPi) < 1e-12);
            weight += sample.l.z;
        }
        const double kept = double(lobe.size()) / samples;
        const double meanWeight = weight / samples;
        qInfo("roughness 1, %d points: %.4f kept, sum n.l / N = %.4f", samples, kept, meanWeight);
        QVERIFY(std::abs(kept - 0.5) < 2e-3);
        QVERIFY(std::abs(meanWeight - 0.25) < 2e-3);
    }
};

QTEST_APPLESS_MAIN(PrefilterLobeTest)
#include "PrefilterLobeTest.moc"
