// Golden images of debug views (render/ShaderVariant.h): the reference view of one material
// under the built-in `studio` environment (procedural, so no sample data is needed), 48 x 48,
// draft IBL preset, compared with EXRs in tests/data/golden/ by a maximum and a mean absolute
// difference. Each view's tolerances say why they are what they are. On failure the test writes
// the actual image and an absolute-difference image to the test output directory.
//
// To (re)create the goldens after an intended change: FACET_UPDATE_GOLDEN=1 DebugViewGoldenGLTest,
// then look at the images and say in the commit why they changed.

#include "core/Image.h"
#include "core/Project.h"

#include "ReferenceViewRenderer.h"
#include "TestSupport.h"

#include <QDir>
#include <QtTest/QTest>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

using namespace facet;

namespace {

constexpr int kSize = 48;

struct Difference {
    double max = 0.0;
    double mean = 0.0;
    Image image;
};

// Absolute RGB differences over the whole image (background included: it is part of the view).
Difference compare(const Image& actual, const Image& golden)
{
    Difference d;
    d.image = Image(actual.width(), actual.height(), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    double sum = 0.0;
    for (int y = 0; y < actual.height(); ++y)
        for (int x = 0; x < actual.width(); ++x) {
            const glm::vec4 a = actual.at(x, y);
            const glm::vec4 b = golden.at(x, y);
            const glm::vec3 diff = glm::abs(glm::vec3(a) - glm::vec3(b));
            const double m = std::max({double(diff.x), double(diff.y), double(diff.z)});
            d.max = std::isfinite(m) ? std::max(d.max, m) : INFINITY;
            sum += m;
            d.image.at(x, y) = glm::vec4(diff, 1.0f);
        }
    d.mean = sum / (double(actual.width()) * actual.height());
    return d;
}

} // namespace

class DebugViewGoldenGLTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { facet::test::forgetDisplayServer(); }

private Q_SLOTS:
    void initTestCase();
    void matchesGolden_data();
    void matchesGolden();

private:
    facet::test::ReferenceViewRenderer m_gpu;
};

void DebugViewGoldenGLTest::initTestCase()
{
    std::string error;
    QVERIFY2(m_gpu.initialize(&error), error.c_str());
}

void DebugViewGoldenGLTest::matchesGolden_data()
{
    QTest::addColumn<QString>("view");
    QTest::addColumn<double>("maxTolerance");
    QTest::addColumn<double>("meanTolerance");
    // base-color: a constant uniform written as is. The goldens are stored as half floats, which
    // round 0.9 by up to 2.4e-4 (measured max 2.4e-4, mean 7.4e-5); nothing else may differ.
    QTest::newRow("base-color") << QStringLiteral("base-color") << 1e-3 << 5e-4;
    // shading-normal: interpolated vertex normals, 0.5 n + 0.5. Drivers may interpolate and
    // rasterise silhouette pixels differently (coverage at the edge flips a pixel between sphere
    // and background: up to ~1 there); the mean stays small.
    QTest::newRow("shading-normal") << QStringLiteral("shading-normal") << 1.0 << 0.01;
    // brdf-lut: the DFG LUT sampled at (n.v, r), made on the GPU from Hammersley points: fp16
    // storage (5e-4 of ~1) plus the silhouette flips above.
    QTest::newRow("brdf-lut") << QStringLiteral("brdf-lut") << 1.0 << 0.01;
    // prefiltered-radiance: the prefiltered map along the dominant direction. Radiance of the
    // built-in studio reaches ~8 on the soft box; another GPU's filtering (8-bit bilinear weights
    // on llvmpipe, finer on NVIDIA) and mip selection move values by a few percent there.
    QTest::newRow("prefiltered-radiance") << QStringLiteral("prefiltered-radiance") << 1.0 << 0.03;
    // irradiance: a smooth function (E / pi); the same filtering differences, much smaller.
    QTest::newRow("irradiance") << QStringLiteral("irradiance") << 0.2 << 0.01;
    // white-furnace: the surface lit by a uniform radiance of 1 (the studio behind it): for this
    // metal its compensated directional albedo, from the DFG LUT only, so tight (LUT fp16 5e-4
    // plus bilinear weights); silhouette pixels may flip to the background.
    QTest::newRow("white-furnace-surface") << QStringLiteral("white-furnace") << 1.0 << 2e-3;
    // none: the shaded image, everything together.
    QTest::newRow("shaded") << QStringLiteral("none") << 1.0 << 0.03;
}

void DebugViewGoldenGLTest::matchesGolden()
{
    QFETCH(QString, view);
    QFETCH(double, maxTolerance);
    QFETCH(double, meanTolerance);

    Project project = Project::defaultProject();
    project.environment.source = "studio"; // built-in, procedural
    project.environment.rotationDegrees = 30.0;
    project.view.mesh = "sphere";
    project.view.debugView = view.toStdString();
    project.lights.clear();
    project.material.setBaseColor(glm::dvec3(0.9, 0.6, 0.3));
    project.material.setFactor(MapSlot::Metallic, 1.0);
    project.material.setFactor(MapSlot::Roughness, 0.4);
    std::string error;
    const auto rendered = m_gpu.render(project, "draft", kSize, &error);
    QVERIFY2(rendered, error.c_str());
    const Image& actual = *rendered;

    const QString goldenPath = facet::test::sourceDir() + QStringLiteral("/tests/data/golden/debug-") + view
        + QStringLiteral(".exr");
    if (qEnvironmentVariableIsSet("FACET_UPDATE_GOLDEN")) {
        QDir().mkpath(QFileInfo(goldenPath).path());
        QVERIFY2(actual.save(goldenPath.toStdString(), &error, false), error.c_str());
        QSKIP(qPrintable(QStringLiteral("golden written: ") + goldenPath));
    }
    const auto golden = Image::load(goldenPath.toStdString(), &error);
    QVERIFY2(golden, error.c_str());
    QCOMPARE(golden->width(), kSize);
    QCOMPARE(golden->height(), kSize);

    const Difference d = compare(actual, *golden);
    std::printf("  %-22s max %.5f (tolerance %.4g), mean %.6f (tolerance %.4g)\n", qPrintable(view), d.max,
        maxTolerance, d.mean, meanTolerance);
    if (!(d.max <= maxTolerance && d.mean <= meanTolerance)) {
        const QString stem = facet::test::outputDir() + QStringLiteral("/golden-debug-") + view;
        std::string ignored;
        actual.save((stem + QStringLiteral("-actual.exr")).toStdString(), &ignored, false);
        d.image.save((stem + QStringLiteral("-diff.exr")).toStdString(), &ignored, false);
    }
    QVERIFY2(d.max <= maxTolerance,
        qPrintable(QStringLiteral("max difference %1 > %2").arg(d.max).arg(maxTolerance)));
    QVERIFY2(d.mean <= meanTolerance,
        qPrintable(QStringLiteral("mean difference %1 > %2").arg(d.mean).arg(meanTolerance)));
}

QTEST_GUILESS_MAIN(DebugViewGoldenGLTest)
#include "DebugViewGoldenGLTest.moc"
