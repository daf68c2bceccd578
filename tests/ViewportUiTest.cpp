// The viewport in the main window: the default project shows a lit object (screenshot saved as an
// artefact), frames are drawn on demand only (none for a second without input), a material edit
// re-renders without reloading anything, camera drags draw reduced previews and then one full
// frame, the camera keys and the turntable work, number keys apply presets, an environment that
// cannot be used is named and never said to be lit. Prints the measured frame times. Framing (the
// first view of a project, F, Home) shows the whole object in a tall and in a wide viewport,
// filling the smaller dimension. Needs a display (Xvfb via with-display.sh).

#include "core/material/MaterialPresets.h"
#include "ui/MainWindow.h"
#include "ui/document/Document.h"
#include "ui/document/DocumentCommands.h"
#include "ui/document/MissingFilesDialog.h"
#include "ui/document/ProjectFileController.h"
#include "ui/viewport/CameraController.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportRenderer.h"
#include "ui/viewport/ViewportWidget.h"

#include "TestSupport.h"

#include <QAction>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest/QTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace facet;

namespace {

// Waits until the viewport has drawn a frame after now.
bool waitForFrame(ViewportWidget* viewport, int timeoutMs = 20000)
{
    QSignalSpy rendered(viewport, &ViewportWidget::frameRendered);
    return rendered.wait(timeoutMs);
}

// Waits for the refined (full resolution) frame that follows an interaction.
bool waitForFullFrame(ViewportWidget* viewport)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < 20000) {
        if (!viewport->isPreviewing() && !viewport->lastFrameStats().reduced)
            return true;
        QTest::qWait(20);
    }
    return false;
}

struct PixelSummary {
    double meanLuma = 0.0; // 0..255
    double stddevLuma = 0.0;
    int clearGreyPixels = 0; // within 1 code value of the empty viewport's grey
    int count = 0;
};

PixelSummary summarize(const QImage& image, const QRect& area)
{
    PixelSummary s;
    const int grey = int(std::lround(ViewportWidget::kClearGrey * 255.0f));
    double sum = 0.0;
    double sumSquares = 0.0;
    for (int y = area.top(); y <= area.bottom(); y += 3)
        for (int x = area.left(); x <= area.right(); x += 3) {
            const QRgb p = image.pixel(x, y);
            const double luma = 0.2126 * qRed(p) + 0.7152 * qGreen(p) + 0.0722 * qBlue(p);
            sum += luma;
            sumSquares += luma * luma;
            if (std::abs(qRed(p) - grey) <= 1 && std::abs(qGreen(p) - grey) <= 1
                && std::abs(qBlue(p) - grey) <= 1)
                ++s.clearGreyPixels;
            ++s.count;
        }
    s.meanLuma = sum / s.count;
    s.stddevLuma = std::sqrt(std::max(0.0, sumSquares / s.count - s.meanLuma * s.meanLuma));
    return s;
}

} // namespace

class ViewportUiTest : public QObject {
    Q_OBJECT
public:
    static void initMain()
    {
        QStandardPaths::setTestModeEnabled(true);
        installViewportSurfaceFormat();
    }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void screenshotShowsLitObject();
    void idleWindowDrawsNothing();
    void materialEditRerendersWithoutReloading();
    void brdfSwitchFetchesItsOwnTable();
    void environmentSwitchDrawsOnWhileTheWorkerPrepares();
    void refinementDrawsFollowTheBudget_data();
    void refinementDrawsFollowTheBudget();
    void sampledMethodRefinesTheStillFrame_data();
    void sampledMethodRefinesTheStillFrame();
    void cameraDragPreviewsThenRefines();
    void cameraKeysAndWheel();
    void turntableDrawsOnlyWhileRunning();
    void ctrlNumberKeyAppliesPreset();
    void framingFitsTallAndWideViewports();
    void unusableEnvironmentIsNamedNeverReady_data();
    void unusableEnvironmentIsNamedNeverReady();
    void projectWithMissingEnvironmentAtStartUp();

private:
    QTemporaryDir m_recovery;
    std::unique_ptr<MainWindow> m_window;
    ViewportWidget* m_viewport = nullptr;
};

void ViewportUiTest::initTestCase()
{
    QCoreApplication::setOrganizationName(QStringLiteral("FacetTests"));
    QElapsedTimer clock;
    clock.start();
    m_window = std::make_unique<MainWindow>(nullptr, m_recovery.path());
    m_viewport = m_window->viewport();
    QSignalSpy rendered(m_viewport, &ViewportWidget::frameRendered);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    QVERIFY(rendered.count() > 0 || rendered.wait(60000));
    const qint64 firstFrameMs = clock.elapsed();
    // Shortcuts (F, T, 1..9) need the window active; Xvfb has no window manager to do it.
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    QVERIFY2(m_viewport->lastError().isEmpty(), qPrintable(m_viewport->lastError()));
    const ViewportFrameStats& first = m_viewport->lastFrameStats();
    qInfo("start-up to first lit frame: %lld ms (IBL precompute %.0f ms, %d passes, %d disk cache hits; "
          "first frame %.0f ms incl. shader compiles)",
        firstFrameMs, first.ibl.msTotal, first.ibl.passesRun, first.ibl.cacheHitsDisk, first.frameMs);
}

void ViewportUiTest::cleanupTestCase()
{
    m_window->document()->newProject(); // nothing to ask about on close
    m_window.reset();
}

void ViewportUiTest::screenshotShowsLitObject()
{
    // A full frame (not a preview) is on screen.
    m_viewport->update();
    QVERIFY(waitForFrame(m_viewport));
    const QImage window = m_window->grab().toImage().convertToFormat(QImage::Format_RGB32);
    const QString path = test::outputDir() + QStringLiteral("/ViewportUiTest-window.png");
    QVERIFY2(window.save(path), qPrintable(path));

    const qreal scale = window.devicePixelRatio();
    const QRect area(m_viewport->mapTo(m_window.get(), QPoint(0, 0)) * scale, m_viewport->size() * scale);
    QVERIFY(window.rect().contains(area));
    // The object: the reference camera sees the unit sphere filling ~85% of the height, so the
    // central quarter of the view is all object.
    const QRect object(area.center() - QPoint(area.height() / 8, area.height() / 8),
        QSize(area.height() / 4, area.height() / 4));
    const PixelSummary lit = summarize(window, object);
    const PixelSummary whole = summarize(window, area);
    const QString report
        = QStringLiteral("object mean %1 sd %2, view mean %3 sd %4, clear-grey pixels %5/%6 (saved %7)")
              .arg(lit.meanLuma)
              .arg(lit.stddevLuma)
              .arg(whole.meanLuma)
              .arg(whole.stddevLuma)
              .arg(whole.clearGreyPixels)
              .arg(whole.count)
              .arg(path);
    qInfo("%s", qPrintable(report));
    // Not blank, not the clear colour: hardly any pixel is the empty viewport's grey.
    QVERIFY2(whole.clearGreyPixels < whole.count / 100, qPrintable(report));
    // Lit and in range: the default red-orange plastic under the studio is mid-grey-ish on average
    // (neither black nor clipped white), and shading varies across it (a flat colour would be an
    // unlit or failed frame).
    QVERIFY2(lit.meanLuma > 40.0 && lit.meanLuma < 230.0, qPrintable(report));
    QVERIFY2(lit.stddevLuma > 3.0, qPrintable(report));
    QVERIFY2(whole.stddevLuma > 5.0, qPrintable(report));
    // The object's colour differs from the background's: red dominates on the plastic.
    const QRgb centre = window.pixel(object.center());
    QVERIFY2(qRed(centre) > qBlue(centre) + 20, qPrintable(QColor(centre).name()));
}

void ViewportUiTest::idleWindowDrawsNothing()
{
    QVERIFY(waitForFullFrame(m_viewport));
    QTest::qWait(ViewportWidget::kRefineDelayMs + 100);
    const std::uint64_t before = m_viewport->frameCount();
    QTest::qWait(1000);
    QCOMPARE(m_viewport->frameCount(), before);
    qInfo("idle: %llu frames in 1 s without input", (unsigned long long)(m_viewport->frameCount() - before));
}

void ViewportUiTest::materialEditRerendersWithoutReloading()
{
    Document* document = m_window->document();
    const SceneController::LoadCounts loadsBefore = m_window->sceneController()->loadCounts();
    const std::uint64_t framesBefore = m_viewport->frameCount();
    const double oldRoughness = document->project().material().roughness();
    Material material = document->project().material();
    material.setFactor(MapSlot::Roughness, 0.8);
    document->setMaterial(material, QStringLiteral("Roughness"), MergeId::Roughness);
    QVERIFY(waitForFrame(m_viewport));
    QVERIFY(m_viewport->frameCount() > framesBefore);
    const SceneController::LoadCounts& loadsAfter = m_window->sceneController()->loadCounts();
    QCOMPARE(loadsAfter.environments, loadsBefore.environments);
    QCOMPARE(loadsAfter.maps, loadsBefore.maps);
    QCOMPARE(loadsAfter.meshes, loadsBefore.meshes);
    QCOMPARE(m_viewport->lastFrameStats().iblMs, 0.0); // no precompute for a roughness change
    QCOMPARE(m_viewport->lastFrameStats().render.texturesUploaded, 0);
    qInfo("full-resolution frame %dx%d: %.1f ms", m_viewport->lastFrameStats().width,
        m_viewport->lastFrameStats().height, m_viewport->lastFrameStats().frameMs);

    // Undo through the Edit menu: the old value, and another frame.
    auto* undo = m_window->findChild<QAction*>(QStringLiteral("undoAction"));
    QVERIFY(undo);
    QCOMPARE(undo->text(), QStringLiteral("&Undo Roughness"));
    undo->trigger();
    QCOMPARE(document->project().material().roughness(), oldRoughness);
    QVERIFY(waitForFrame(m_viewport));
}

void ViewportUiTest::brdfSwitchFetchesItsOwnTable()
{
    // The LearnOpenGL BRDF needs the Schlick-GGX split-sum table (the renderer refuses a frame
    // without it): the switch loads or makes that one table and nothing else; switching back
    // finds the glTF table in memory.
    QVERIFY(waitForFullFrame(m_viewport));
    Document* document = m_window->document();
    const SceneController::LoadCounts loadsBefore = m_window->sceneController()->loadCounts();
    Material material = document->project().material();
    const ShadingModel gltf = material.shading;
    QVERIFY(gltf.visibility != Visibility::SchlickGGX);
    material.shading = ShadingModel::learnOpenGL();
    document->setMaterial(material, QStringLiteral("BRDF"), MergeId::None);
    QVERIFY(waitForFrame(m_viewport));
    QVERIFY2(m_viewport->lastError().isEmpty(), qPrintable(m_viewport->lastError()));
    const ViewportFrameStats& switched = m_viewport->lastFrameStats();
    // The one table: shipped with Facet at the default quality, else made or read from disk.
    QCOMPARE(switched.ibl.passesRun + switched.ibl.cacheHitsDisk + switched.ibl.dfgShipped, 1);
    QVERIFY(switched.iblMs > 0.0);
    QCOMPARE(m_window->sceneController()->loadCounts().environments, loadsBefore.environments);

    material.shading = gltf;
    document->setMaterial(material, QStringLiteral("BRDF"), MergeId::None);
    QVERIFY(waitForFrame(m_viewport));
    QVERIFY2(m_viewport->lastError().isEmpty(), qPrintable(m_viewport->lastError()));
    QCOMPARE(m_viewport->lastFrameStats().iblMs, 0.0); // its table is still in memory
}

void ViewportUiTest::environmentSwitchDrawsOnWhileTheWorkerPrepares()
{
    // A new environment and quality: the lighting worker makes the set (ui/viewport/LightingWorker) while
    // the view draws on with the lighting it had; those frames are not announced as rendered.
    // The frame that shows the new set is, after "ready". Then back to the set in memory: at once.
    QVERIFY(waitForFullFrame(m_viewport));
    Document* document = m_window->document();
    const Project before = document->project();
    Project project = before;
    project.environment.source = "uniform:0.3,0.5,0.7";
    project.environment.quality = IblQuality::High;
    QSignalSpy rendered(m_viewport, &ViewportWidget::frameRendered);
    int renderedWhenReady = -1;
    QMetaObject::Connection ready = connect(m_viewport, &ViewportWidget::iblPrecomputeFinished, this,
        [&] { renderedWhenReady = int(rendered.count()); });
    const std::uint64_t awaitingBefore = m_viewport->framesAwaitingLighting();
    document->setProject(project, QStringLiteral("environment"));
    QTRY_VERIFY_WITH_TIMEOUT(renderedWhenReady >= 0, 60000);
    QVERIFY(rendered.count() > 0 || rendered.wait(20000));
    disconnect(ready);
    QCOMPARE(renderedWhenReady, 0); // nothing announced while the worker ran
    QVERIFY(m_viewport->framesAwaitingLighting() > awaitingBefore);
    QVERIFY2(m_viewport->lastError().isEmpty(), qPrintable(m_viewport->lastError()));
    const ViewportFrameStats& switched = m_viewport->lastFrameStats();
    QVERIFY(!switched.lightingPending);
    // Made on the worker for this set: computed, or read from a disk cache an earlier run left.
    QVERIFY(switched.ibl.passesRun == 3 || switched.ibl.cacheHitsDisk == 1);
    QCOMPARE(switched.ibl.cacheHitsMemory, 0);
    QVERIFY(switched.iblMs > 0.0);

    const std::uint64_t awaiting = m_viewport->framesAwaitingLighting();
    rendered.clear();
    document->setProject(before, QStringLiteral("environment"));
    QVERIFY(rendered.wait(20000));
    QCOMPARE(m_viewport->framesAwaitingLighting(), awaiting); // in memory: no frame waited
    QCOMPARE(m_viewport->lastFrameStats().ibl.cacheHitsMemory, 1);
}

void ViewportUiTest::refinementDrawsFollowTheBudget_data()
{
    // The samples of the next refinement draw after one of `samples` took `ms`, for a 100 ms
    // budget: a power of two near the budget, at most 4x up or down a draw, from 1 to 64.
    QTest::addColumn<int>("samples");
    QTest::addColumn<double>("ms");
    QTest::addColumn<int>("expected");
    QTest::newRow("on budget") << 4 << 100.0 << 4;
    QTest::newRow("half the budget") << 4 << 50.0 << 8;
    QTest::newRow("a quarter") << 4 << 25.0 << 16;
    QTest::newRow("far under: 4x at most") << 4 << 1.0 << 16;
    QTest::newRow("twice over") << 4 << 200.0 << 2;
    QTest::newRow("far over: a quarter at most") << 16 << 10000.0 << 4;
    QTest::newRow("never below 1") << 1 << 10000.0 << 1;
    QTest::newRow("never above 64") << 64 << 1.0 << 64;
    QTest::newRow("a power of two") << 3 << 100.0 << 2;
    QTest::newRow("no time measured") << 8 << 0.0 << 8;
}

void ViewportUiTest::refinementDrawsFollowTheBudget()
{
    QFETCH(int, samples);
    QFETCH(double, ms);
    QFETCH(int, expected);
    QCOMPARE(ViewportRenderer::nextDrawSamples(samples, ms, 100.0), expected);
}

void ViewportUiTest::sampledMethodRefinesTheStillFrame_data()
{
    QTest::addColumn<int>("method");
    QTest::newRow("reference") << int(IblMethod::Reference);
    QTest::newRow("fis") << int(IblMethod::Fis);
}

void ViewportUiTest::sampledMethodRefinesTheStillFrame()
{
    // A project whose environment.method is fis or reference: the still frame refines by it, one
    // draw per paint, to the project's samples, the status text saying where it stands; then the
    // window draws nothing more. An edit starts the refinement again.
    QFETCH(int, method);
    constexpr int kSamples = 32;
    QVERIFY(waitForFullFrame(m_viewport));
    Document* document = m_window->document();
    const QImage splitSum = m_viewport->grabFramebuffer();
    EnvironmentSettings environment = document->project().environment;
    const EnvironmentSettings original = environment;
    environment.method = IblMethod(method);
    environment.samples = kSamples;
    QElapsedTimer clock;
    clock.start();
    document->setEnvironment(environment, QStringLiteral("Lighting Method"));
    QTRY_VERIFY_WITH_TIMEOUT(m_viewport->lastFrameStats().refinement.done(), 120000);
    const double seconds = double(clock.elapsed()) / 1000.0;
    QVERIFY2(m_viewport->lastError().isEmpty(), qPrintable(m_viewport->lastError()));
    const ViewportFrameStats done = m_viewport->lastFrameStats();
    QCOMPARE(int(done.refineMethod), method);
    QCOMPARE(done.refinement.samples, kSamples);
    QCOMPARE(done.refinement.target, kSamples);
    QVERIFY(done.refinement.showing);
    QVERIFY2(done.refinement.draws >= 2, qPrintable(QString::number(done.refinement.draws)));
    QVERIFY2(done.summary().contains(QStringLiteral("32/32 spp"))
            && done.summary().endsWith(QStringLiteral("(done)")),
        qPrintable(done.summary()));
    qInfo("%s: %d samples in %d draws, %.1f s of drawing, %.1f s in all", qPrintable(done.summary()),
        done.refinement.samples, done.refinement.draws, done.refinement.seconds, seconds);
    // Another image of the same object: close to the split sum's on the whole, not the same.
    const QImage refined = m_viewport->grabFramebuffer();
    QVERIFY(refined != splitSum);
    const QRect area = refined.rect();
    const double before = summarize(splitSum.convertToFormat(QImage::Format_RGB32), area).meanLuma;
    const double after = summarize(refined.convertToFormat(QImage::Format_RGB32), area).meanLuma;
    QVERIFY2(std::abs(after - before) < 0.15 * before,
        qPrintable(QStringLiteral("%1 vs %2").arg(after).arg(before)));
    // Done: idle.
    const std::uint64_t frames = m_viewport->frameCount();
    QTest::qWait(1000);
    QCOMPARE(m_viewport->frameCount(), frames);

    // A display-only edit keeps the samples: the frames after an exposure change, a slider drag
    // included, show the same accumulation anew (brighter), with no preview and no restart.
    {
        std::vector<int> shownSamples;
        std::vector<bool> reduced;
        const auto watch = connect(m_viewport, &ViewportWidget::frameRendered, this, [&] {
            shownSamples.push_back(m_viewport->lastFrameStats().refinement.samples);
            reduced.push_back(m_viewport->lastFrameStats().reduced);
        });
        ViewSettings view = document->project().view;
        view.exposureEV += 1.0;
        document->beginInteractiveEdit();
        document->setView(view, QStringLiteral("Exposure"));
        document->endInteractiveEdit();
        QTRY_VERIFY_WITH_TIMEOUT(!shownSamples.empty(), 10000);
        QTest::qWait(300);
        disconnect(watch);
        QVERIFY2(std::all_of(shownSamples.begin(), shownSamples.end(), [](int n) { return n == kSamples; }),
            qPrintable(QStringLiteral("%1 frames, the first with %2 samples")
                           .arg(shownSamples.size())
                           .arg(shownSamples.front())));
        QVERIFY(std::none_of(reduced.begin(), reduced.end(), [](bool r) { return r; }));
        QVERIFY(m_viewport->lastFrameStats().refinement.done());
        const double brighter
            = summarize(m_viewport->grabFramebuffer().convertToFormat(QImage::Format_RGB32), area).meanLuma;
        QVERIFY2(brighter > after * 1.1, qPrintable(QStringLiteral("%1 vs %2").arg(brighter).arg(after)));
        document->undoStack()->undo(); // the exposure
        QVERIFY(waitForFrame(m_viewport));
        QCOMPARE(m_viewport->lastFrameStats().refinement.samples, kSamples);
    }

    // An edit restarts it: the first frame after it is the split sum's again (no samples), then
    // the samples grow draw by draw to the target.
    Material material = document->project().material();
    material.setFactor(MapSlot::Roughness, material.roughness() * 0.5);
    std::vector<int> samplesSeen;
    const auto connection = connect(m_viewport, &ViewportWidget::frameRendered, this,
        [&] { samplesSeen.push_back(m_viewport->lastFrameStats().refinement.samples); });
    document->setMaterial(material, QStringLiteral("Roughness"), MergeId::None);
    QTRY_VERIFY_WITH_TIMEOUT(!samplesSeen.empty() && samplesSeen.back() == kSamples, 120000);
    disconnect(connection);
    QCOMPARE(samplesSeen.front(), 0);
    QVERIFY(std::is_sorted(samplesSeen.begin(), samplesSeen.end()));
    QVERIFY(samplesSeen.size() >= 3);
    document->undoStack()->undo(); // the roughness
    document->setEnvironment(original, QStringLiteral("Lighting Method"));
    QVERIFY(waitForFrame(m_viewport));
    QVERIFY(waitForFullFrame(m_viewport));
    QCOMPARE(int(m_viewport->lastFrameStats().refineMethod), int(IblMethod::SplitSum));
}

void ViewportUiTest::cameraDragPreviewsThenRefines()
{
    QVERIFY(waitForFullFrame(m_viewport));
    Document* document = m_window->document();
    const Camera before = document->project().camera;
    const int undoCount = document->undoStack()->count();
    const QPoint start = m_viewport->rect().center();
    QTest::mousePress(m_viewport, Qt::LeftButton, {}, start);
    QSignalSpy rendered(m_viewport, &ViewportWidget::frameRendered);
    for (int step = 1; step <= 5; ++step) {
        QMouseEvent move(QEvent::MouseMove, QPointF(start + QPoint(step * 10, step * 2)),
            m_viewport->mapToGlobal(QPointF(start + QPoint(step * 10, step * 2))), Qt::NoButton,
            Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(m_viewport, &move);
        QTest::qWait(10);
    }
    QVERIFY(rendered.count() > 0 || rendered.wait(5000));
    const ViewportFrameStats preview = m_viewport->lastFrameStats();
    QVERIFY(preview.reduced);
    QTest::mouseRelease(m_viewport, Qt::LeftButton, {}, start + QPoint(50, 10));
    QVERIFY(document->project().camera != before);
    QCOMPARE(document->undoStack()->count(), undoCount); // orbiting is not an undo step
    QVERIFY(waitForFullFrame(m_viewport));
    const ViewportFrameStats full = m_viewport->lastFrameStats();
    QVERIFY(!full.reduced);
    QCOMPARE(full.width, int(m_viewport->width() * m_viewport->devicePixelRatioF()));
    qInfo("orbit preview %dx%d: %.1f ms; refined %dx%d: %.1f ms", preview.width, preview.height,
        preview.frameMs, full.width, full.height, full.frameMs);
    // Orbiting keeps the distance to the target.
    const Camera after = document->project().camera;
    QVERIFY(
        std::abs(glm::length(after.position - after.target) - glm::length(before.position - before.target))
        < 1e-9);
}

void ViewportUiTest::cameraKeysAndWheel()
{
    Document* document = m_window->document();
    const auto distance = [document] {
        const Camera& c = document->project().camera;
        return glm::length(c.position - c.target);
    };
    const double start = distance();
    QWheelEvent wheel(QPointF(m_viewport->rect().center()),
        m_viewport->mapToGlobal(QPointF(m_viewport->rect().center())), QPoint(), QPoint(0, 120), Qt::NoButton,
        Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(m_viewport, &wheel);
    QVERIFY(distance() < start); // closer

    // Shift+drag pans: the target moves.
    const glm::dvec3 target = document->project().camera.target;
    QTest::mousePress(m_viewport, Qt::LeftButton, Qt::ShiftModifier, QPoint(100, 100));
    QMouseEvent move(QEvent::MouseMove, QPointF(130, 100), m_viewport->mapToGlobal(QPointF(130, 100)),
        Qt::NoButton, Qt::LeftButton, Qt::ShiftModifier);
    QCoreApplication::sendEvent(m_viewport, &move);
    QTest::mouseRelease(m_viewport, Qt::LeftButton, Qt::ShiftModifier, QPoint(130, 100));
    QVERIFY(document->project().camera.target != target);

    m_viewport->setFocus();
    QTest::keyClick(m_viewport, Qt::Key_F); // frame: aimed at the origin again
    QCOMPARE(document->project().camera.target, glm::dvec3(0.0));
    QTest::keyClick(m_viewport, Qt::Key_Home); // reset: the reference view, backed off if the view is tall
    const Camera home = CameraController::defaultView(double(m_viewport->width()) / m_viewport->height());
    QCOMPARE(document->project().camera, home);

    // Fly mode: W moves forward while held.
    m_window->cameraController()->setFlyMode(true);
    QTest::keyPress(m_viewport, Qt::Key_W);
    QTRY_VERIFY_WITH_TIMEOUT(document->project().camera.position.z < home.position.z, 10000);
    QTest::keyRelease(m_viewport, Qt::Key_W);
    m_window->cameraController()->setFlyMode(false);
    m_window->cameraController()->resetView();
    QVERIFY(waitForFullFrame(m_viewport));
}

void ViewportUiTest::turntableDrawsOnlyWhileRunning()
{
    QVERIFY(waitForFullFrame(m_viewport));
    auto* turntable = m_window->findChild<QAction*>(QStringLiteral("turntableAction"));
    QVERIFY(turntable);
    const std::uint64_t before = m_viewport->frameCount();
    m_viewport->setFocus();
    QTest::keyClick(m_viewport, Qt::Key_T);
    QVERIFY(turntable->isChecked());
    QVERIFY(m_window->cameraController()->turntableRunning());
    QTest::qWait(1000);
    const std::uint64_t spinning = m_viewport->frameCount() - before;
    QVERIFY2(spinning >= 3, qPrintable(QString::number(spinning)));
    QVERIFY(m_window->viewport()->viewState().objectTurntableDegrees > 0.0);
    qInfo("turntable: %llu frames in 1 s (preview resolution)", (unsigned long long)spinning);
    turntable->trigger();
    QVERIFY(!m_window->cameraController()->turntableRunning());
    QVERIFY(waitForFullFrame(m_viewport));
    QTest::qWait(ViewportWidget::kRefineDelayMs + 100);
    const std::uint64_t stopped = m_viewport->frameCount();
    QTest::qWait(1000);
    QCOMPARE(m_viewport->frameCount(), stopped);
}

void ViewportUiTest::ctrlNumberKeyAppliesPreset()
{
    Document* document = m_window->document();
    const MaterialPreset& first = builtinPresets().front();
    m_viewport->setFocus();
    // Ctrl+1 (issue 30: the key alone replaced and renamed the material; it does nothing now).
    QTest::keyClick(m_viewport, Qt::Key_1);
    QCOMPARE(document->project().material(), Project::defaultProject().material());
    QTest::keyClick(m_viewport, Qt::Key_1, Qt::ControlModifier);
    QCOMPARE(document->project().material().baseColorFactor(), first.material.baseColorFactor());
    QCOMPARE(document->project().material().name, Project::defaultProject().material().name);
    QCOMPARE(document->project().material().roughness(), first.material.roughness());
    QVERIFY(waitForFrame(m_viewport));
    document->undoStack()->undo();
    QCOMPARE(document->project().material(), Project::defaultProject().material());
}

void ViewportUiTest::framingFitsTallAndWideViewports()
{
    // The viewport alone (no docks), so its shape is the window's; a black background, so the
    // object is every pixel that is not black.
    Document* document = m_window->document();
    CameraController* camera = m_window->cameraController();
    const QSize windowSize = m_window->size();
    QList<QDockWidget*> hidden;
    for (QDockWidget* dock : m_window->findChildren<QDockWidget*>())
        if (dock->toggleViewAction()->isChecked()) { // in the layout (a tabbed-away dock is not visible)
            dock->hide();
            hidden.append(dock);
        }
    // The status bar's labels (the GL renderer's name) would keep the window wider than a tall view.
    m_window->statusBar()->hide();
    const auto blackBackground = [document] {
        ViewSettings view = document->project().view;
        view.background = BackgroundMode::Color;
        view.backgroundColor = glm::dvec3(0.0);
        document->setView(view, QStringLiteral("Background"));
    };
    // Resizes the window and waits until the viewport has drawn a full frame of its new size.
    const auto resizeTo = [&](QSize size) {
        QElapsedTimer clock;
        clock.start();
        while (clock.elapsed() < 20000) {
            // Again until it takes: right after docks are hidden the layout still holds their width.
            if (m_window->size() != size)
                m_window->resize(size);
            QTest::qWait(50);
            const ViewportFrameStats& stats = m_viewport->lastFrameStats();
            if (m_window->size() == size && !m_viewport->isPreviewing() && !stats.reduced
                && stats.width == int(m_viewport->width() * m_viewport->devicePixelRatioF())
                && stats.height == int(m_viewport->height() * m_viewport->devicePixelRatioF()))
                return true;
        }
        return false;
    };
    // The object's bounding box in the viewport (pixels brighter than the black background).
    const auto objectBox = [&](QRect* area) {
        m_viewport->update();
        waitForFrame(m_viewport);
        waitForFullFrame(m_viewport);
        const QImage window = m_window->grab().toImage().convertToFormat(QImage::Format_RGB32);
        const qreal scale = window.devicePixelRatio();
        *area = QRect(m_viewport->mapTo(m_window.get(), QPoint(0, 0)) * scale, m_viewport->size() * scale);
        QRect box;
        for (int y = area->top(); y <= area->bottom(); ++y)
            for (int x = area->left(); x <= area->right(); ++x) {
                const QRgb p = window.pixel(x, y);
                if (std::max({qRed(p), qGreen(p), qBlue(p)}) > 24)
                    box |= QRect(x, y, 1, 1);
            }
        return box.translated(-area->topLeft());
    };
    // The whole object is in the view, centred, with a margin, and fills the smaller dimension
    // (Camera::kFramingFill, 85%, less the few pixels antialiasing dims below the threshold).
    const auto framingProblem = [&](const char* what) -> QString {
        QRect area;
        const QRect box = objectBox(&area);
        const int smaller = std::min(area.width(), area.height());
        const double fill = double(area.width() < area.height() ? box.width() : box.height()) / smaller;
        const int margin = std::min(
            {box.left(), box.top(), area.width() - 1 - box.right(), area.height() - 1 - box.bottom()});
        const QString report
            = QStringLiteral("%1: view %2x%3, object %4x%5 at (%6, %7), fill %8, margin %9 px")
                  .arg(QLatin1String(what))
                  .arg(area.width())
                  .arg(area.height())
                  .arg(box.width())
                  .arg(box.height())
                  .arg(box.left())
                  .arg(box.top())
                  .arg(fill)
                  .arg(margin);
        qInfo("%s", qPrintable(report));
        const bool framed = fill > 0.78 && fill < 0.90 && margin >= smaller / 50
            && std::abs(box.center().x() - area.width() / 2) <= smaller / 50
            && std::abs(box.center().y() - area.height() / 2) <= smaller / 50;
        return framed ? QString() : report;
    };
#define CHECK_FRAMED(what)                                                                                   \
    do {                                                                                                     \
        const QString problem = framingProblem(what);                                                        \
        QVERIFY2(problem.isEmpty(), qPrintable(problem));                                                    \
    } while (false)

    // A tall viewport: a new project's first view shows the whole sphere, fitted to the width.
    QVERIFY(resizeTo(QSize(440, 980)));
    QVERIFY2(m_viewport->height() > 1.3 * m_viewport->width(),
        qPrintable(QStringLiteral("%1x%2").arg(m_viewport->width()).arg(m_viewport->height())));
    document->newProject();
    QVERIFY(document->project().camera.position.z > Camera::referenceView().position.z); // backed off
    QVERIFY(!document->isModified()); // framing is not an edit
    blackBackground();
    CHECK_FRAMED("tall, new project");
    // F after orbiting and dollying in: framed again from the new direction.
    camera->orbit(120.0, -40.0);
    camera->dolly(4.0);
    camera->frameObject();
    CHECK_FRAMED("tall, F");
    const Camera framed = document->project().camera;
    QCOMPARE(framed.target, glm::dvec3(0.0));
    // The same camera in a wide viewport: not moved since F, so the resize fits it again.
    QVERIFY(resizeTo(QSize(1240, 440)));
    QVERIFY2(m_viewport->width() > 2.0 * m_viewport->height(),
        qPrintable(QStringLiteral("%1x%2").arg(m_viewport->width()).arg(m_viewport->height())));
    CHECK_FRAMED("wide, F, after the resize");
    QVERIFY(glm::length(document->project().camera.position) < glm::length(framed.position));
    // Home in a wide viewport is the reference view itself.
    camera->resetView();
    QCOMPARE(document->project().camera, Camera::referenceView());
    CHECK_FRAMED("wide, Home");
    // A camera the user moved stays where it is when the viewport changes shape.
    camera->orbit(30.0, 0.0);
    const Camera moved = document->project().camera;
    QVERIFY(resizeTo(QSize(600, 900)));
    QCOMPARE(document->project().camera, moved);

#undef CHECK_FRAMED
    document->newProject();
    for (QDockWidget* dock : hidden)
        dock->show();
    m_window->statusBar()->show();
    QVERIFY(resizeTo(windowSize));
}

void ViewportUiTest::unusableEnvironmentIsNamedNeverReady_data()
{
    QTest::addColumn<QString>("source"); // {dir}: a temporary folder
    QTest::addColumn<QString>("file"); // the name the messages must use
    QTest::addColumn<QString>("problem"); // how the window says what is wrong
    QTest::newRow("missing file") << "{dir}/night.exr"
                                  << "night.exr"
                                  << "night.exr is missing";
    QTest::newRow("not an image") << "{dir}/broken.exr"
                                  << "broken.exr"
                                  << "broken.exr";
    QTest::newRow("library this computer lacks") << "library:nobody/night.exr"
                                                 << "night.exr"
                                                 << "night.exr comes from the library “nobody”";
}

// An environment that cannot be used is named, with the reason, in the status bar and the
// Environment dock, and the lighting is never said to be its (the previous one stays lit).
void ViewportUiTest::unusableEnvironmentIsNamedNeverReady()
{
    QFETCH(QString, source);
    QFETCH(QString, file);
    QFETCH(QString, problem);
    QTemporaryDir dir;
    QFile garbage(dir.filePath(QStringLiteral("broken.exr")));
    QVERIFY(garbage.open(QIODevice::WriteOnly) && garbage.write("not an EXR at all") > 0);
    garbage.close();
    source.replace(QLatin1String("{dir}"), dir.path());
    Document* document = m_window->document();
    SceneController* scene = m_window->sceneController();
    const QString shown = scene->environmentName();
    EnvironmentSettings environment = document->project().environment;
    environment.source = source.toStdString();
    document->setEnvironment(environment, QStringLiteral("Environment"));
    // The file is tried off the GUI thread (ui/document/DocumentAssets); until it fails the previous
    // environment stays lit.
    QTRY_COMPARE_WITH_TIMEOUT(scene->pendingAssetLoads(), 0, 30000);
    waitForFrame(m_viewport, 3000); // nothing to relight: a frame may or may not follow

    const auto* dockStatus = m_window->findChild<QLabel*>(QStringLiteral("environmentStatus"));
    QVERIFY(dockStatus);
    for (const QString& text : {m_window->statusMessage(), dockStatus->text(), scene->environmentProblem()}) {
        QVERIFY2(text.contains(problem), qPrintable(text));
        QVERIFY2(!text.contains(QStringLiteral("ready")), qPrintable(text));
        QVERIFY2(!text.contains(QStringLiteral("Environment::")), qPrintable(text));
    }
    QVERIFY2(dockStatus->text().contains(QStringLiteral("Showing %1 instead").arg(shown)),
        qPrintable(dockStatus->text()));
    QCOMPARE(scene->environmentName(), shown);
    QVERIFY(scene->environmentName() != file);

    document->undoStack()->undo();
    QVERIFY(scene->environmentProblem().isEmpty()); // at once: another choice, loading or not
    QTRY_COMPARE_WITH_TIMEOUT(scene->pendingAssetLoads(), 0, 30000);
    QVERIFY(scene->environmentProblem().isEmpty());
}

// What `facet P.json` does when P.json names a missing environment: the project opens before the
// viewport has drawn anything, and the first lighting is the built-in studio's. The window must
// say the project's file is missing, not "Lighting of night.exr ready".
void ViewportUiTest::projectWithMissingEnvironmentAtStartUp()
{
    QTemporaryDir dir;
    Project project = Project::defaultProject();
    project.environment.source = dir.filePath(QStringLiteral("night.exr")).toStdString();
    const QString path = dir.filePath(QStringLiteral("missing-environment.json"));
    std::string error;
    QVERIFY2(project.save(path.toStdString(), &error), error.c_str());

    MainWindow window(nullptr, dir.filePath(QStringLiteral("recovery")));
    window.projectFiles()->setErrorDialogsEnabled(false);
    QVERIFY(window.projectFiles()->openFile(path));
    QSignalSpy finished(window.viewport(), &ViewportWidget::iblPrecomputeFinished);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(finished.count() > 0 || finished.wait(60000));
    QTRY_COMPARE_WITH_TIMEOUT(window.sceneController()->pendingAssetLoads(), 0, 30000);
    const auto* dockStatus = window.findChild<QLabel*>(QStringLiteral("environmentStatus"));
    for (const QString& text : {window.statusMessage(), dockStatus->text()}) {
        QVERIFY2(text.contains(QStringLiteral("night.exr is missing")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("Showing studio instead")), qPrintable(text));
        QVERIFY2(!text.contains(QStringLiteral("ready")), qPrintable(text));
    }
    QCOMPARE(finished.first().first().toString(), QStringLiteral("studio")); // what was lit
    if (auto* dialog = window.projectFiles()->missingFilesDialog())
        dialog->close();
    window.document()->newProject();
}

QTEST_MAIN(ViewportUiTest)
#include "ViewportUiTest.moc"
