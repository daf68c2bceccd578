// The Compare view's error view (CompareMode::Error, ui/compare/CompareRenderer.h): its numbers are
// core/image/ImageMetrics' on the images it shows (the relative RMSE and the worst pixel of the
// real-time image against the reference's mean over the object mask, the reference's noise),
// its heat map's pixels are heatmap::color of each pixel's relative error (or noise), row for
// row, and the reference's accumulation restarts on every change of what it sums (material,
// camera, environment, light, samples) and on none of the others (exposure, tone mapper, the
// heat map's scale and mode, names, the split sum's quality, which only redraws the real-time
// image). Needs a display (Xvfb via with-display.sh).

#include "core/image/HeatMap.h"
#include "core/image/ImageMetrics.h"
#include "core/image/ToneMap.h"
#include "ui/MainWindow.h"
#include "ui/compare/CompareRenderer.h"
#include "ui/compare/CompareView.h"
#include "ui/document/Document.h"
#include "ui/viewport/SurfaceFormat.h"

#include "CompareTestWindow.h"
#include "TestSupport.h"

#include <QImage>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace facet;
using namespace facet::test;

Q_DECLARE_METATYPE(std::function<void(facet::Project&)>)

namespace {

using Edit = std::function<void(Project&)>;

constexpr int kSamples = 32; // enough for a reference that is shown (16) with both halves drawn

// The error view of the default project (glossy plastic, studio) at `samples`.
Project errorProject(int samples = kSamples)
{
    Project project = CompareTestWindow::baseProject();
    project.compare.mode = CompareMode::Error;
    project.compare.error.samples = samples;
    return project;
}

std::size_t count(const PixelMask& mask)
{
    return std::size_t(std::count_if(mask.begin(), mask.end(), [](std::uint8_t m) { return m != 0; }));
}

} // namespace

class ErrorViewUiTest : public QObject {
    Q_OBJECT
public:
    static void initMain()
    {
        QStandardPaths::setTestModeEnabled(true);
        installViewportSurfaceFormat();
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_compare.open(m_recovery.path()));
        m_document = m_compare.document();
        m_view = m_compare.view();
    }
    void cleanupTestCase() { m_compare.close(); }

    void numbersAreImageMetricsOfTheImagesShown_data();
    void numbersAreImageMetricsOfTheImagesShown();
    void accumulationRestartsOnlyOnWhatItSums_data();
    void accumulationRestartsOnlyOnWhatItSums();

private:
    // The error cell's index among the view's cells (the heat map).
    int heatCell() const
    {
        for (std::size_t i = 0; i < m_view->cells().size(); ++i)
            if (m_view->cells()[i].role == CompareCell::Role::Error)
                return int(i);
        return -1;
    }

    QTemporaryDir m_recovery;
    CompareTestWindow m_compare;
    Document* m_document = nullptr;
    CompareView* m_view = nullptr;
};

void ErrorViewUiTest::numbersAreImageMetricsOfTheImagesShown_data()
{
    QTest::addColumn<Edit>("edit");
    QTest::addColumn<bool>("noise");
    QTest::newRow("plastic, studio") << Edit([](Project&) {}) << false;
    QTest::newRow("plastic, studio, noise") << Edit([](Project&) {}) << true;
    QTest::newRow("rough gold, sky, scale 5%") << Edit([](Project& p) {
        p.environment.source = "sky";
        p.material().map(MapSlot::BaseColor).factor = {1.0, 0.766, 0.336, 1.0};
        p.material().setFactor(MapSlot::Metallic, 1.0);
        p.material().setFactor(MapSlot::Roughness, 0.8);
        p.compare.error.scale = 0.05;
    }) << false;
    QTest::newRow("white furnace") << Edit([](Project& p) {
        p.environment.source = "uniform:1";
        p.material().map(MapSlot::BaseColor).factor = {1.0, 1.0, 1.0, 1.0};
    }) << false;
}

void ErrorViewUiTest::numbersAreImageMetricsOfTheImagesShown()
{
    QFETCH(Edit, edit);
    QFETCH(bool, noise);
    Project project = errorProject();
    edit(project);
    project.compare.error.showNoise = noise;
    QVERIFY(m_compare.setProject(project));

    const CompareFrameStats& frame = m_view->lastFrameStats();
    QVERIFY(frame.error);
    const ErrorViewStats& stats = *frame.error;
    QVERIFY(stats.done());
    QCOMPARE(stats.samples, kSamples);
    QCOMPARE(stats.showingNoise, noise);
    QVERIFY(stats.error && stats.noise);

    const CompareRenderer* renderer = m_view->renderer();
    QVERIFY(renderer);
    const Image& test = renderer->errorTestImage();
    const Image& reference = renderer->errorReferenceImage();
    const PixelMask& mask = renderer->errorMask();
    const int cell = heatCell();
    QVERIFY(cell >= 0);
    // The three cells' common size (a grid's cells may differ by a pixel): the heat cell's, at most.
    const QRect cellRect = m_view->cellRectOf(std::size_t(cell));
    QVERIFY(test.width() >= cellRect.width() - 1 && test.width() <= cellRect.width());
    QVERIFY(test.height() >= cellRect.height() - 1 && test.height() <= cellRect.height());
    QCOMPARE(reference.width(), test.width());
    QCOMPARE(reference.height(), test.height());
    const QRect rect(cellRect.topLeft(), QSize(test.width(), test.height()));
    // The object, not the background: thousands of pixels, none in the cell's corners, each
    // fully covered in the real-time image.
    QVERIFY2(count(mask) > 5000, qPrintable(QString::number(count(mask))));
    QVERIFY(!mask.front() && !mask.back());
    for (std::size_t i = 0; i < mask.size(); ++i)
        if (mask[i])
            QVERIFY(test.data()[i].a >= kFullCoverage);

    // The numbers: ImageMetrics on those images, to the bit.
    const ImageErrorStats expected = errorStats(test, reference, mask);
    QCOMPARE(stats.error->relativeRmse, expected.relativeRmse);
    QCOMPARE(stats.error->maxRelativeError, expected.maxRelativeError);
    QCOMPARE(stats.error->pixelCount, count(mask));
    QCOMPARE(*stats.noise, relativeNoiseRmse(reference, renderer->errorVariance(), mask));
    QVERIFY(*stats.noise > 0.0 && *stats.noise < 0.5);
    const QString percent
        = QStringLiteral("%1%").arg((noise ? *stats.noise : expected.relativeRmse) * 100.0, 0, 'f', 2);
    QVERIFY2(m_view->labelOf(std::size_t(cell)).contains(percent),
        qPrintable(m_view->labelOf(std::size_t(cell)) + QStringLiteral(" lacks ") + percent));

    // The heat map: each object pixel heatmap::color of its value, each other pixel the grey
    // around it (away from the label at the top and the legend at the bottom).
    const std::vector<float> values = noise ? relativeNoise(reference, renderer->errorVariance(), mask)
                                            : relativeErrors(test, reference, mask);
    const QImage shown = m_view->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
    const int outside
        = int(std::lround(CompareRenderer::displayGrey(CompareRenderer::kGapGrey * 2.0f) * 255.0f));
    int compared = 0;
    int wrong = 0;
    int over = 0;
    QString first;
    for (int y = 32; y < rect.height() - 48; ++y)
        for (int x = 0; x < rect.width(); ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(rect.width()) + std::size_t(x);
            const QRgb pixel = shown.pixel(rect.left() + x, rect.top() + y);
            glm::ivec3 want(outside);
            if (mask[i]) {
                const glm::vec3 c = heatmap::color(double(values[i]), project.compare.error.scale);
                want = glm::ivec3(glm::round(c * 255.0f));
                over += values[i] > project.compare.error.scale ? 1 : 0;
            }
            const glm::ivec3 got(qRed(pixel), qGreen(pixel), qBlue(pixel));
            const glm::ivec3 off = glm::abs(got - want);
            ++compared;
            if (std::max({off.x, off.y, off.z}) > 1) {
                if (wrong++ == 0)
                    first = QStringLiteral("(%1, %2): %3 %4 %5, expected %6 %7 %8")
                                .arg(x)
                                .arg(y)
                                .arg(got.x)
                                .arg(got.y)
                                .arg(got.z)
                                .arg(want.x)
                                .arg(want.y)
                                .arg(want.z);
            }
        }
    QVERIFY(compared > 10000);
    QVERIFY2(wrong == 0,
        qPrintable(
            QStringLiteral("%1 of %2 heat-map pixels wrong, first %3").arg(wrong).arg(compared).arg(first)));
    if (qstrcmp(QTest::currentDataTag(), "plastic, studio") == 0)
        QVERIFY(m_compare.window()->grab().save(outputDir() + QStringLiteral("/error-view.png")));
    qInfo("%s: RMSE %.2f%%, max %.1f%%, noise %.2f%%, %d of %zu pixels over the scale",
        QTest::currentDataTag(), expected.relativeRmse * 100.0, expected.maxRelativeError * 100.0,
        *stats.noise * 100.0, over, count(mask));
}

void ErrorViewUiTest::accumulationRestartsOnlyOnWhatItSums_data()
{
    QTest::addColumn<Edit>("edit");
    QTest::addColumn<bool>("restarts");
    QTest::addColumn<bool>("retests"); // the real-time image is drawn again
    const auto row = [](const char* name, Edit edit, bool restarts, bool retests) {
        QTest::newRow(name) << edit << restarts << retests;
    };
    row(
        "roughness", [](Project& p) { p.material().setFactor(MapSlot::Roughness, 0.7); }, true, true);
    row(
        "base colour",
        [](Project& p) {
            p.material().map(MapSlot::BaseColor).factor = {0.9, 0.1, 0.1, 1.0};
        },
        true, true);
    row(
        "camera", [](Project& p) { p.camera.position.x += 0.3; }, true, true);
    row(
        "environment", [](Project& p) { p.environment.source = "sky"; }, true, true);
    row(
        "environment rotation", [](Project& p) { p.environment.rotationDegrees = 90.0; }, true, true);
    row(
        "light", [](Project& p) { p.lights.push_back(Light {}); }, true, true);
    row(
        "samples", [](Project& p) { p.compare.error.samples = kSamples * 2; }, true, false);
    row(
        "exposure", [](Project& p) { p.view.exposureEV = 1.5; }, false, false);
    row(
        "tone mapper", [](Project& p) { p.view.toneMapper = ToneMapper::Aces; }, false, false);
    row(
        "heat-map scale", [](Project& p) { p.compare.error.scale = 1.0; }, false, false);
    row(
        "show noise", [](Project& p) { p.compare.error.showNoise = true; }, false, false);
    row(
        "material name", [](Project& p) { p.material().name = "Renamed"; }, false, false);
    row(
        "split-sum quality", [](Project& p) { p.environment.quality = IblQuality::High; }, false, true);
}

void ErrorViewUiTest::accumulationRestartsOnlyOnWhatItSums()
{
    QFETCH(Edit, edit);
    QFETCH(bool, restarts);
    QFETCH(bool, retests);
    const Project before = errorProject();
    QVERIFY(m_compare.setProject(before));
    const CompareRenderer* renderer = m_view->renderer();
    const Image testBefore = renderer->errorTestImage();
    const Image referenceBefore = renderer->errorReferenceImage();
    QVERIFY(m_view->lastFrameStats().error && m_view->lastFrameStats().error->done());

    // The fewest samples any frame after the edit showed: 0 or a few after a restart.
    int fewest = 1 << 30;
    const QMetaObject::Connection watch = connect(m_view, &CompareView::frameRendered, this, [&] {
        if (m_view->lastFrameStats().error)
            fewest = std::min(fewest, m_view->lastFrameStats().error->samples);
    });
    Project after = before;
    edit(after);
    QVERIFY(m_compare.setProject(after));
    disconnect(watch);

    const ErrorViewStats& stats = *m_view->lastFrameStats().error;
    QVERIFY(stats.done());
    QCOMPARE(stats.target, after.compare.error.samples);
    QCOMPARE(fewest < stats.target, restarts);
    const bool sameReference = renderer->errorReferenceImage().width() == referenceBefore.width()
        && std::equal(referenceBefore.data(), referenceBefore.data() + referenceBefore.pixelCount(),
            renderer->errorReferenceImage().data());
    QCOMPARE(!sameReference, restarts);
    const bool sameTest = std::equal(
        testBefore.data(), testBefore.data() + testBefore.pixelCount(), renderer->errorTestImage().data());
    QCOMPARE(!sameTest, retests);
}

QTEST_MAIN(ErrorViewUiTest)
#include "ErrorViewUiTest.moc"
