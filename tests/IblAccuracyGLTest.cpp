// The real-time renderer against the ground truth (core/shading/GroundTruth.h) on docs/architecture.md's
// reference view: the default IBL preset, metal and dielectric spheres at several roughness values under
// three CC0 HDRIs. Each case has its own bound on the relative RMSE over interior sphere pixels,
// sqrt(sum |gpu - truth|^2 / sum |truth|^2): the measured value on Mesa llvmpipe plus a margin,
// so that a regression of the prefilter, the lookups or the composition fails here.
//
// Why most bounds are far above the 2% aim: the split sum itself. The same formula
// evaluated on the CPU with the EXACT prefiltered radiance (no cubemap, no mips, 4096 samples)
// is already 46% (r 0.3) and 121% (r 0.7) off on `studio`, whose small, very bright lights are
// reflected at grazing angles near the silhouette, where the true lobe is stretched and shifted
// and the split sum's n = v = r lobe is not. docs/accuracy.md ("The split sum's own error")
// separates that floor from what the GPU adds; docs/ibl.md has the measurements behind the
// roughness-to-level map and the dominant direction that brought rough cases down (city r 1:
// 47% -> 4%, studio r 0.7: 126% -> 45%).

#include "core/image/ImageMetrics.h"
#include "core/project/Project.h"
#include "core/shading/GroundTruth.h"

#include "ReferenceViewRenderer.h"
#include "TestSupport.h"

#include <QtTest/QTest>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

using namespace facet;

namespace {

// 48 x 48 and 512 samples per pixel: the ground truth's own noise is about 0.5% relative RMSE
// here (docs/accuracy.md: 256 spp gives 0.3% absolute on city r 0.4), far below every bound.
constexpr int kSize = 48;
constexpr int kSamplesPerPixel = 512;

enum class Kind { Metal, Dielectric };

Project accuracyProject(const QString& hdri, Kind kind, double roughness)
{
    Project project = Project::defaultProject();
    project.environment.source = hdri.toStdString();
    project.environment.quality = IblQuality::Default;
    project.view.mesh = "sphere";
    project.lights.clear();
    if (kind == Kind::Metal) {
        project.material().setBaseColor(glm::dvec3(1.0, 0.78, 0.34)); // gold-like F0
        project.material().setFactor(MapSlot::Metallic, 1.0);
    } else {
        project.material().setBaseColor(glm::dvec3(0.8, 0.1, 0.1));
        project.material().setFactor(MapSlot::Metallic, 0.0);
    }
    project.material().setFactor(MapSlot::Roughness, roughness);
    return project;
}

} // namespace

class IblAccuracyGLTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { facet::test::forgetDisplayServer(); }

private Q_SLOTS:
    void initTestCase();
    void gpuAgainstGroundTruth_data();
    void gpuAgainstGroundTruth();

private:
    facet::test::ReferenceViewRenderer m_gpu;
};

void IblAccuracyGLTest::initTestCase()
{
    std::string error;
    QVERIFY2(m_gpu.initialize(&error), error.c_str());
}

void IblAccuracyGLTest::gpuAgainstGroundTruth_data()
{
    QTest::addColumn<QString>("hdri");
    QTest::addColumn<int>("kind");
    QTest::addColumn<double>("roughness");
    QTest::addColumn<double>("bound");
    // Bounds: the relative RMSE measured on Mesa llvmpipe (docs/accuracy.md, "The real-time
    // renderer against the ground truth") x 1.3, rounded up: headroom for the ground truth's
    // noise and another driver's filtering, not for a worse prefilter.
    struct Case {
        const char* hdri;
        Kind kind;
        double roughness;
        double bound;
    };
    const Case cases[] = {
        {"city", Kind::Metal, 0.05, 0.056},
        {"city", Kind::Metal, 0.3, 0.067},
        {"city", Kind::Metal, 0.6, 0.085},
        {"city", Kind::Metal, 1.0, 0.054},
        {"city", Kind::Dielectric, 0.05, 0.035},
        {"city", Kind::Dielectric, 0.3, 0.046},
        {"city", Kind::Dielectric, 0.6, 0.023},
        {"city", Kind::Dielectric, 1.0, 0.040},
        {"sunset", Kind::Metal, 0.05, 0.160},
        {"sunset", Kind::Metal, 0.3, 0.091},
        {"sunset", Kind::Metal, 0.6, 0.076},
        {"sunset", Kind::Metal, 1.0, 0.071},
        {"sunset", Kind::Dielectric, 0.05, 0.041},
        {"sunset", Kind::Dielectric, 0.3, 0.031},
        {"sunset", Kind::Dielectric, 0.6, 0.015},
        {"sunset", Kind::Dielectric, 1.0, 0.035},
        {"studio", Kind::Metal, 0.05, 0.089},
        {"studio", Kind::Metal, 0.3, 0.253},
        {"studio", Kind::Metal, 0.6, 0.562},
        {"studio", Kind::Metal, 1.0, 0.155},
        {"studio", Kind::Dielectric, 0.05, 0.054},
        {"studio", Kind::Dielectric, 0.3, 0.313},
        {"studio", Kind::Dielectric, 0.6, 0.133},
        {"studio", Kind::Dielectric, 1.0, 0.032},
    };
    for (const Case& c : cases)
        QTest::addRow("%s-%s-r%.2f", c.hdri, c.kind == Kind::Metal ? "metal" : "dielectric", c.roughness)
            << QString::fromLatin1(c.hdri) << int(c.kind) << c.roughness << c.bound;
}

void IblAccuracyGLTest::gpuAgainstGroundTruth()
{
    QFETCH(QString, hdri);
    QFETCH(int, kind);
    QFETCH(double, roughness);
    QFETCH(double, bound);
    const QString path = facet::test::hdriPath(hdri);
    FACET_REQUIRE_ASSET(path, qPrintable(hdri + QStringLiteral(".exr")));

    const Project project = accuracyProject(path, Kind(kind), roughness);
    // The GPU: the default preset, the reference view, linear radiance in RGBA32F.
    std::string error;
    const auto gpu = m_gpu.render(project, "default", kSize, &error);
    QVERIFY2(gpu, error.c_str());

    // The ground truth of the same project.
    const auto truthScene = groundTruthSceneFromProject(project, &error);
    QVERIFY2(truthScene, error.c_str());
    GroundTruthSettings truthSettings;
    truthSettings.width = kSize;
    truthSettings.height = kSize;
    truthSettings.samplesPerPixel = kSamplesPerPixel;
    const Image truth = renderGroundTruth(*truthScene, truthSettings);

    const double error2 = relativeRmse(*gpu, truth);
    std::printf("  %-6s %-10s r %.2f: relative RMSE %.4f (bound %.3f)\n", qPrintable(hdri),
        Kind(kind) == Kind::Metal ? "metal" : "dielectric", roughness, error2, bound);
    if (!(error2 < bound)) {
        const QString stem = facet::test::outputDir() + QStringLiteral("/accuracy-")
            + QString::fromLatin1(QTest::currentDataTag());
        std::string ignored;
        gpu->save((stem + QStringLiteral("-gpu.exr")).toStdString(), &ignored);
        truth.save((stem + QStringLiteral("-truth.exr")).toStdString(), &ignored);
    }
    QVERIFY2(std::isfinite(error2) && error2 < bound,
        qPrintable(QStringLiteral("relative RMSE %1 >= bound %2 (images in %3)")
                       .arg(error2)
                       .arg(bound)
                       .arg(facet::test::outputDir())));
}

QTEST_GUILESS_MAIN(IblAccuracyGLTest)
#include "IblAccuracyGLTest.moc"
