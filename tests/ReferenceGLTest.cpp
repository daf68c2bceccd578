// IblMethod::Reference on the GPU (ibl_reference.glsl, FrameRenderer::renderConverged) against the
// CPU ground truth (core/GroundTruth, `facet render --spp`): the same rendering equation, so the
// two must agree within their noise, for every BRDF composition, under a rotated environment and
// a CC0 map, with lights, in a furnace, and under extreme radiance. DESIGN.md's reference view,
// relative RMSE over the interior sphere pixels (core/ImageMetrics).
//
// The bound of an agreement row is statistical: rmse(GPU, CPU) < 3 sqrt(nG^2 + nC^2) + 2e-3, where
// nG is the GPU's own noise estimate (FrameAccumulator's two half-buffers) and nC the CPU's,
// relativeRmse of two CPU renders with different seeds over sqrt 2, plus 2e-3 for float
// arithmetic. The GPU shades the analytic sphere in the reference view, as the CPU does
// (RenderScene::analyticSphere): with the 64 x 32 mesh's interpolated normals (about 1e-3 rad
// off) the smooth metal row measured 2.0% against a bound of 1.7%; with it, 0.29%. A broken term
// (a lobe, a weight, a pdf) shows as a bias far above the noise.

#include "core/GroundTruth.h"
#include "core/ImageMetrics.h"
#include "core/Project.h"
#include "core/ReferenceView.h"

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

private:
    facet::test::ReferenceViewRenderer m_gpu;
};

QTEST_GUILESS_MAIN(ReferenceGLTest)
#include "ReferenceGLTest.moc"
