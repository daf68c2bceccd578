// Golden images of debug views (render/ShaderVariant.h): the reference view of one material
// under the built-in `studio` environment (procedural, so no sample data is needed), 48 x 48,
// draft IBL preset, compared with EXRs in tests/data/golden/ by a maximum and a mean absolute
// difference. Each view's tolerances say why they are what they are. On failure the test writes
// the actual image and an absolute-difference image to the test output directory.
//
// To (re)create the goldens after an intended change: FACET_UPDATE_GOLDEN=1 DebugViewGoldenGLTest,
// then look at the images and say in the commit why they changed.

#include "core/image/Image.h"
#include "core/project/Project.h"
#include "core/shading/ReferenceView.h"

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

// Absolute RGB differences over the interior sphere pixels (core/shading/ReferenceView.h, margin 1): the
// view is the sphere's; whether a silhouette pixel's centre falls on the tessellated sphere or on
// the background is the rasteriser's call, and one such flip would force a tolerance of 1.
Difference compare(const Image& actual, const Image& golden)
{
    Difference d;
    d.image = Image(actual.width(), actual.height(), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < actual.height(); ++y)
        for (int x = 0; x < actual.width(); ++x) {
            if (!referenceview::isInteriorSpherePixel(x, y, actual.width(), actual.height()))
                continue;
            ++count;
            const glm::vec4 a = actual.at(x, y);
            const glm::vec4 b = golden.at(x, y);
            const glm::vec3 diff = glm::abs(glm::vec3(a) - glm::vec3(b));
            const double m = std::max({double(diff.x), double(diff.y), double(diff.z)});
            d.max = std::isfinite(m) ? std::max(d.max, m) : INFINITY;
            sum += m;
            d.image.at(x, y) = glm::vec4(diff, 1.0f);
        }
    d.mean = count > 0 ? sum / double(count) : INFINITY;
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
    // A shader feature the row turns on (Magnum's golden rows per feature): "" for the plain
    // material, "clearcoat" for a full coat of roughness 0.3 over it. The golden file is
    // debug-VIEW[-FEATURE].exr.
    QTest::addColumn<QString>("feature");
    // Interior sphere pixels only (compare()). The goldens are half-float EXRs: a value in
    // [0.5, 1) is stored to 2.4e-4, one in [4, 8) to 3.9e-3. Measured on llvmpipe (Mesa 22.3)
    // against its own goldens: max 1e-4 to 3.9e-3, mean 8e-5 to 5e-4 (printed by this test).
    // The bounds leave room for another driver's texture-filter weights (llvmpipe uses 8-bit
    // bilinear weights) and nothing more: a wrong map, a dropped term or a flipped normal moves
    // interior pixels by 0.05 to 1.
    // base-color: a constant uniform written as is; only the storage rounds it.
    QTest::newRow("base-color") << QStringLiteral("base-color") << 1e-3 << 5e-4 << QString();
    // shading-normal: interpolated vertex normals, 0.5 n + 0.5 (storage rounding, interpolation order).
    QTest::newRow("shading-normal") << QStringLiteral("shading-normal") << 2e-3 << 5e-4 << QString();
    // brdf-lut: the DFG LUT sampled at (n.v, r): fp16 LUT plus bilinear weights.
    QTest::newRow("brdf-lut") << QStringLiteral("brdf-lut") << 2e-3 << 5e-4 << QString();
    // prefiltered-radiance: up to ~8 on the built-in studio's soft box, where storage alone
    // rounds by 3.9e-3 and a filter weight of 1/256 moves a value by ~0.03 on the box's edge.
    QTest::newRow("prefiltered-radiance")
        << QStringLiteral("prefiltered-radiance") << 0.04 << 2e-3 << QString();
    // irradiance: a smooth function (E / pi) below ~2.
    QTest::newRow("irradiance") << QStringLiteral("irradiance") << 0.01 << 2e-3 << QString();
    // white-furnace: this metal's compensated directional albedo from the DFG LUT, in [0, 1].
    QTest::newRow("white-furnace-surface") << QStringLiteral("white-furnace") << 2e-3 << 5e-4 << QString();
    // none: the shaded image, everything together, up to ~4 where the soft box reflects.
    QTest::newRow("shaded") << QStringLiteral("none") << 0.04 << 2e-3 << QString();
    // The same with a clear coat: the coat's prefiltered lobe and its weight on the metal.
    QTest::newRow("shaded, clearcoat")
        << QStringLiteral("none") << 0.04 << 2e-3 << QStringLiteral("clearcoat");
    // The furnace under the coat: the coat's single scattering loses a little (docs/accuracy.md).
    QTest::newRow("white-furnace, clearcoat")
        << QStringLiteral("white-furnace") << 2e-3 << 5e-4 << QStringLiteral("clearcoat");
}

void DebugViewGoldenGLTest::matchesGolden()
{
    QFETCH(QString, view);
    QFETCH(double, maxTolerance);
    QFETCH(double, meanTolerance);
    QFETCH(QString, feature);

    Project project = Project::defaultProject();
    project.environment.source = "studio"; // built-in, procedural
    project.environment.rotationDegrees = 30.0;
    project.view.mesh = "sphere";
    project.view.debugView = debugViewFromString(view.toStdString()).value();
    project.lights.clear();
    project.material().setBaseColor(glm::dvec3(0.9, 0.6, 0.3));
    project.material().setFactor(MapSlot::Metallic, 1.0);
    project.material().setFactor(MapSlot::Roughness, 0.4);
    if (feature == QLatin1String("clearcoat"))
        project.material().setClearcoat(1.0, 0.3);
    std::string error;
    const auto rendered = m_gpu.render(project, "draft", kSize, &error);
    QVERIFY2(rendered, error.c_str());
    const Image& actual = *rendered;

    const QString name = view + (feature.isEmpty() ? QString() : QLatin1Char('-') + feature);
    const QString goldenPath = facet::test::sourceDir() + QStringLiteral("/tests/data/golden/debug-") + name
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
    std::printf("  %-32s max %.5f (tolerance %.4g), mean %.6f (tolerance %.4g)\n", qPrintable(name), d.max,
        maxTolerance, d.mean, meanTolerance);
    if (!(d.max <= maxTolerance && d.mean <= meanTolerance)) {
        const QString stem = facet::test::outputDir() + QStringLiteral("/golden-debug-") + name;
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
