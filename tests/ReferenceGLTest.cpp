// IblMethod::Reference on the GPU (ibl_reference.glsl, FrameRenderer::renderConverged) against the
// CPU ground truth (core/shading/GroundTruth, `facet render --spp`): the same rendering equation, so the
// two must agree within their noise, for every BRDF composition, under a rotated environment and
// a CC0 map, with lights, in a furnace, and under extreme radiance. docs/architecture.md's reference view,
// relative RMSE over the interior sphere pixels (core/image/ImageMetrics).
//
// The bound of an agreement row is statistical: rmse(GPU, CPU) < 3 sqrt(nG^2 + nC^2) + 2e-3, where
// nG is the GPU's own noise estimate (FrameAccumulator's two half-buffers) and nC the CPU's,
// relativeRmse of two CPU renders with different seeds over sqrt 2, plus 2e-3 for float
// arithmetic. The GPU shades the analytic sphere in the reference view, as the CPU does
// (RenderScene::analyticSphere): with the 64 x 32 mesh's interpolated normals (about 1e-3 rad
// off) the smooth metal row measured 2.0% against a bound of 1.7%; with it, 0.29%. A broken term
// (a lobe, a weight, a pdf) shows as a bias far above the noise.

#include "core/image/ImageMetrics.h"
#include "core/project/Project.h"
#include "core/shading/GroundTruth.h"
#include "core/shading/ReferenceView.h"

#include "IblMethodCase.h"
#include "ReferenceViewRenderer.h"
#include "TestSupport.h"

#include <QtTest/QTest>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

using namespace facet;

namespace {

constexpr int kSize = 32;
constexpr int kSamples = 256;
// What the two sides do differently on purpose, in the mean over the sphere: float arithmetic
// and the two sequences' stratification (measured at most 0.24%, Beckmann; -0.05 to -0.11% for
// the dielectrics under the rotated studio; printed per row).
constexpr double kMeanFloor = 2e-3;

using Row = facet::test::IblMethodCase;

Project projectOf(const Row& row)
{
    return facet::test::iblMethodCaseProject(row, IblMethod::Reference, kSamples);
}

std::optional<Image> cpuTruth(const Project& project, std::uint64_t seed, std::string* error)
{
    return facet::test::groundTruthImage(project, kSize, kSamples, seed, error);
}

using enum BrdfComposition;
using enum Visibility;
const Row kRows[] = {
    {"gltf dielectric", Gltf},
    {"gltf metal", Gltf, SmithGGXCorrelated, Distribution::GGX, Fresnel::Schlick, DielectricCoupling::FresnelMix, true,
        {0.95, 0.64, 0.54}, 1.0, 0.3},
    {"gltf metal smooth", Gltf, SmithGGXCorrelated, Distribution::GGX, Fresnel::Schlick, DielectricCoupling::FresnelMix,
        true, {0.95, 0.64, 0.54}, 1.0, 0.05},
    {"gltf dielectric smooth", Gltf, SmithGGXCorrelated, Distribution::GGX, Fresnel::Schlick,
        DielectricCoupling::FresnelMix, true, {0.8, 0.3, 0.1}, 0.0, 0.05},
    {"gltf dielectric rough", Gltf, SmithGGXCorrelated, Distribution::GGX, Fresnel::Schlick,
        DielectricCoupling::FresnelMix, true, {0.8, 0.3, 0.1}, 0.0, 0.9},
    {"gltf energy-preserving", Gltf, SmithGGXCorrelated, Distribution::GGX, Fresnel::Schlick,
        DielectricCoupling::EnergyPreserving},
    {"gltf single scattering", Gltf, SmithGGXCorrelated, Distribution::GGX, Fresnel::Schlick,
        DielectricCoupling::FresnelMix, false, {0.9, 0.9, 0.9}, 1.0, 0.6},
    {"gltf dielectric fresnel", Gltf, SmithGGXCorrelated, Distribution::GGX, Fresnel::Dielectric},
    {"learnopengl", LearnOpenGL, SchlickGGX},
    {"learnopengl metal", LearnOpenGL, SchlickGGX, Distribution::GGX, Fresnel::Schlick, DielectricCoupling::FresnelMix,
        true, {0.95, 0.64, 0.54}, 1.0, 0.3},
    {"uncorrelated", Gltf, SmithGGXUncorrelated},
    {"beckmann metal", Gltf, SmithGGXCorrelated, Distribution::Beckmann, Fresnel::Schlick,
        DielectricCoupling::FresnelMix, true, {0.95, 0.64, 0.54}, 1.0, 0.5},
    {"half metal", Gltf, SmithGGXCorrelated, Distribution::GGX, Fresnel::Schlick, DielectricCoupling::FresnelMix, true,
        {0.5, 0.7, 0.9}, 0.5, 0.5},
    {"sky unrotated", Gltf, SmithGGXCorrelated, Distribution::GGX, Fresnel::Schlick, DielectricCoupling::FresnelMix,
        true, {0.8, 0.3, 0.1}, 0.0, 0.4, "sky", 0.0},
    {"studio with a light", Gltf, SmithGGXCorrelated, Distribution::GGX, Fresnel::Schlick,
        DielectricCoupling::FresnelMix, true, {0.8, 0.3, 0.1}, 0.0, 0.4, "studio", 40.0, true},
};

} // namespace

class ReferenceGLTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { facet::test::forgetDisplayServer(); }

private Q_SLOTS:
    void initTestCase()
    {
        std::string error;
        QVERIFY2(m_gpu.initialize(&error), error.c_str());
    }

    void agreesWithTheGroundTruth_data()
    {
        QTest::addColumn<int>("row");
        for (std::size_t i = 0; i < std::size(kRows); ++i)
            QTest::newRow(kRows[i].name) << int(i);
    }

    void agreesWithTheGroundTruth()
    {
        QFETCH(int, row);
        const Project project = projectOf(kRows[row]);
        std::string error;
        std::optional<double> gpuNoise;
        const std::optional<Image> gpu = m_gpu.render(project, "draft", kSize, &error, &gpuNoise);
        QVERIFY2(gpu, error.c_str());
        QVERIFY(gpuNoise.has_value());
        const std::optional<Image> cpu = cpuTruth(project, 1, &error);
        QVERIFY2(cpu, error.c_str());
        const std::optional<Image> cpuOther = cpuTruth(project, 2, &error);
        QVERIFY2(cpuOther, error.c_str());
        const double cpuNoise = relativeRmse(*cpuOther, *cpu) / std::sqrt(2.0);
        const double rmse = relativeRmse(*gpu, *cpu);
        const double bound = 3.0 * std::sqrt(*gpuNoise * *gpuNoise + cpuNoise * cpuNoise) + 2e-3;
        // The mean over the interior pixels: per-pixel noise averages out (the shifts are
        // independent per pixel), so a bias of a term shows here long before it shows in the RMSE.
        double gpuSum = 0.0;
        double cpuSum = 0.0;
        int pixels = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x)
                if (referenceview::isInteriorSpherePixel(x, y, kSize, kSize)) {
                    for (int c = 0; c < 3; ++c) {
                        gpuSum += gpu->at(x, y)[c];
                        cpuSum += cpu->at(x, y)[c];
                    }
                    ++pixels;
                }
        const double meanError = gpuSum / cpuSum - 1.0;
        const double meanBound = 3.0 * std::sqrt(*gpuNoise * *gpuNoise + cpuNoise * cpuNoise) / std::sqrt(double(pixels))
            + kMeanFloor;
        std::printf("  %-24s rmse %.4f (bound %.4f) | mean %+.4f (bound %.4f) | gpu noise %.4f, cpu noise %.4f\n",
                    kRows[row].name, rmse, bound, meanError, meanBound, *gpuNoise, cpuNoise);
        QVERIFY2(std::abs(meanError) < meanBound,
                 qPrintable(QStringLiteral("mean over the sphere off by %1 >= %2").arg(meanError).arg(meanBound)));
        QVERIFY2(std::isfinite(rmse) && rmse < bound,
                 qPrintable(QStringLiteral("relative RMSE %1 >= %2 (gpu noise %3, cpu noise %4)")
                                .arg(rmse)
                                .arg(bound)
                                .arg(*gpuNoise)
                                .arg(cpuNoise)));
    }

    // A white furnace: radiance 1 all around, so each pixel is the BRDF's directional albedo,
    // which the compensated white metal and the energy-preserving dielectric hold at 1 (0.5%:
    // the bound; their tables are the ground truth's, so what is left is noise).
    void furnace_data()
    {
        QTest::addColumn<double>("metallic");
        QTest::addColumn<int>("coupling");
        QTest::newRow("white metal, compensated") << 1.0 << int(DielectricCoupling::FresnelMix);
        QTest::newRow("white dielectric, energy-preserving") << 0.0 << int(DielectricCoupling::EnergyPreserving);
    }
    void furnace()
    {
        QFETCH(double, metallic);
        QFETCH(int, coupling);
        Row row {"furnace"};
        row.environment = "uniform:1.0";
        row.baseColor = glm::dvec3(1.0);
        row.metallic = metallic;
        row.roughness = 0.6;
        row.coupling = DielectricCoupling(coupling);
        std::string error;
        const std::optional<Image> gpu = m_gpu.render(projectOf(row), "draft", kSize, &error);
        QVERIFY2(gpu, error.c_str());
        const Image one(kSize, kSize, glm::vec4(1.0f));
        const double rmse = relativeRmse(*gpu, one);
        std::printf("  furnace: relative RMSE from 1: %.5f\n", rmse);
        QVERIFY2(rmse < 5e-3, qPrintable(QString::number(rmse)));
    }

    // Radiance of a million suns and of a near-black map: every pixel finite and >= 0.
    void extremeRadianceStaysFinite_data()
    {
        QTest::addColumn<QString>("environment");
        QTest::newRow("1e6") << QStringLiteral("uniform:1000000");
        QTest::newRow("1e-6") << QStringLiteral("uniform:0.000001");
        QTest::newRow("black") << QStringLiteral("uniform:0");
    }
    void extremeRadianceStaysFinite()
    {
        QFETCH(QString, environment);
        Row row {"extreme"};
        Project project = projectOf(row);
        project.environment.source = environment.toStdString();
        project.environment.samples = 16;
        std::string error;
        const std::optional<Image> gpu = m_gpu.render(project, "draft", 16, &error);
        QVERIFY2(gpu, error.c_str());
        const std::string bad = facet::test::firstUnusablePixel(*gpu);
        QVERIFY2(bad.empty(), bad.c_str());
    }

    // The window's refinement (FrameRenderer::refine) estimates the reference's noise over the
    // object (its first draw's coverage, not the background, which has none) and stops at its
    // samples or at FrameRenderer::kRefinementNoiseTarget, whichever comes first.
    void refinementStopsAtTheSamplesOrTheNoiseTarget_data()
    {
        QTest::addColumn<QString>("environment");
        QTest::addColumn<double>("roughness");
        QTest::addColumn<int>("samples");
        QTest::addColumn<bool>("byNoise"); // done by the noise target, before the samples
        QTest::addColumn<int>("drawSamples"); // what the budget asks for
        QTest::newRow("white furnace, 4096 samples: the noise first")
            << QStringLiteral("uniform:1") << 0.6 << 4096 << true << 16;
        QTest::newRow("studio, 64 samples: the samples first")
            << QStringLiteral("studio") << 0.3 << 64 << false << 64;
        QTest::newRow("studio, 100 samples, draws of 8")
            << QStringLiteral("studio") << 0.3 << 100 << false << 8;
    }
    void refinementStopsAtTheSamplesOrTheNoiseTarget()
    {
        QFETCH(QString, environment);
        QFETCH(double, roughness);
        QFETCH(int, samples);
        QFETCH(bool, byNoise);
        QFETCH(int, drawSamples);
        Row row {"refinement"};
        row.environment = "studio";
        row.baseColor = glm::dvec3(1.0);
        row.roughness = roughness;
        row.coupling = DielectricCoupling::EnergyPreserving; // 1 everywhere in the white furnace
        Project project = projectOf(row);
        project.environment.source = environment.toStdString();
        project.environment.samples = samples;
        constexpr int kRefineSize = 32;
        std::string error;
        std::optional<FrameAccumulator::Spread> spread;
        std::vector<int> draws;
        const auto state = m_gpu.refine(project, "draft", kRefineSize, drawSamples, &error, &spread, &draws);
        QVERIFY2(state, error.c_str());
        // Draws in pairs of one power-of-two size, one to each half, each the next aligned block
        // of its half's run (the last may be cut short by the target), at most the budget's size.
        int base[2] = {0, 0};
        for (std::size_t i = 0; i < draws.size(); ++i) {
            const int k = draws[i];
            const int half = int(i % 2);
            const bool last = base[0] + base[1] + k >= state->samples;
            QVERIFY2(k >= 1 && k <= drawSamples, qPrintable(QString::number(k)));
            if (!last) {
                QVERIFY2((k & (k - 1)) == 0, qPrintable(QStringLiteral("draw %1: %2 samples").arg(i).arg(k)));
                QVERIFY2(base[half] % k == 0,
                    qPrintable(QStringLiteral("draw %1 at %2 of its half: %3 samples").arg(i).arg(base[half]).arg(k)));
                if (half == 1)
                    QCOMPARE(k, draws[i - 1]);
            }
            base[half] += k;
        }
        QCOMPARE(base[0] + base[1], state->samples);
        QVERIFY(base[1] > 0); // both halves drew: the noise is known
        QVERIFY(state->done());
        QVERIFY(state->noise && spread);
        std::printf("  %s: %d of %d samples, noise %.4f\n", qPrintable(environment), state->samples, state->target,
            *state->noise);
        QCOMPARE(state->noiseReached(), byNoise);
        QCOMPARE(state->samples < samples, byNoise);
        if (byNoise)
            QVERIFY(*state->noise <= FrameRenderer::kRefinementNoiseTarget);
        else
            QCOMPARE(state->samples, samples);
        // Over the object: the sphere's noise, not diluted by the background's noiseless pixels.
        const double sphere = relativeNoiseRmse(spread->mean, spread->variance, sphereMask(kRefineSize, kRefineSize));
        const double everywhere = relativeNoiseRmse(spread->mean, spread->variance);
        QVERIFY2(std::abs(*state->noise - sphere) < 0.15 * sphere,
            qPrintable(QStringLiteral("%1 against the sphere's %2").arg(*state->noise).arg(sphere)));
        // Honest: in the furnace, where the truth is 1, the estimate is the error it estimates
        // (within 2x either way; before the draws were paired and aligned it was 10 to 20x the error).
        if (environment == QLatin1String("uniform:1")) {
            const double actual
                = errorStats(spread->mean, Image(kRefineSize, kRefineSize, glm::vec4(1.0f)), sphereMask(kRefineSize, kRefineSize))
                      .relativeRmse;
            std::printf("  furnace: estimated noise %.4f, actual error %.4f\n", *state->noise, actual);
            QVERIFY2(*state->noise < 2.0 * actual && *state->noise > 0.5 * actual,
                qPrintable(QStringLiteral("estimate %1, error %2").arg(*state->noise).arg(actual)));
        }
        QVERIFY2(std::abs(*state->noise - sphere) < std::abs(*state->noise - everywhere),
            qPrintable(QStringLiteral("%1: nearer every pixel's %2 than the sphere's %3")
                           .arg(*state->noise)
                           .arg(everywhere)
                           .arg(sphere)));
    }

    // The command line's noise estimate (renderConverged, `facet render --ibl reference`) is the
    // error it estimates: in the white furnace, where the truth is 1, within 1.5x either way at
    // each count (measured 0.94-1.06x; with halves of alternate blocks of one run it read 1.5-1.8x
    // here, about 2.5x under studio (issue 29), and nothing at all for one draw of 64).
    void commandNoiseIsTheError_data()
    {
        QTest::addColumn<int>("samples");
        QTest::newRow("64") << 64;
        QTest::newRow("256") << 256;
        QTest::newRow("100 (unaligned)") << 100;
    }
    void commandNoiseIsTheError()
    {
        QFETCH(int, samples);
        Row row {"furnace"};
        row.baseColor = glm::dvec3(1.0);
        row.roughness = 0.6;
        row.coupling = DielectricCoupling::EnergyPreserving;
        Project project = projectOf(row);
        project.environment.source = "uniform:1";
        project.environment.samples = samples;
        constexpr int kNoiseSize = 32;
        std::string error;
        std::optional<double> noise;
        const auto image = m_gpu.render(project, "draft", kNoiseSize, &error, &noise);
        QVERIFY2(image, error.c_str());
        QVERIFY(noise);
        const double actual = errorStats(
            *image, Image(kNoiseSize, kNoiseSize, glm::vec4(1.0f)), sphereMask(kNoiseSize, kNoiseSize))
                                  .relativeRmse;
        std::printf("  %d samples: estimated noise %.4f, actual error %.4f\n", samples, *noise, actual);
        QVERIFY2(*noise<1.5 * actual&& * noise> actual / 1.5,
            qPrintable(QStringLiteral("estimate %1, error %2").arg(*noise).arg(actual)));
    }

private:
    facet::test::ReferenceViewRenderer m_gpu;
};

QTEST_GUILESS_MAIN(ReferenceGLTest)
#include "ReferenceGLTest.moc"
