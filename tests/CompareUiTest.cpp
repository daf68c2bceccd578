// The Compare modes in the main window (ui/compare/CompareView.h): the cells each mode makes, a linked
// orbit moving every linked cell while an unlinked one stays (and only it redraws when it orbits
// alone), the A/B divider dragged with the mouse and the pixels either side of it coming from A
// and from B, wedge values reaching the cells (a roughness wedge's highlight peak falls
// monotonically), the layout saved and opened again, every compare edit undone and redone, an
// environment shown by two cells loaded and precomputed once, an idle Compare view drawing
// nothing. Screenshots of each mode go to the test output folder. Needs a display (Xvfb via
// with-display.sh).

#include "core/material/MaterialPresets.h"
#include "ui/MainWindow.h"
#include "ui/compare/CompareActions.h"
#include "ui/compare/CompareController.h"
#include "ui/compare/CompareView.h"
#include "ui/docks/EnvironmentDock.h"
#include "ui/document/Document.h"
#include "ui/document/DocumentAssets.h"
#include "ui/viewport/CameraController.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportWidget.h"

#include "CompareTestWindow.h"
#include "TestSupport.h"

#include <QAction>
#include <QElapsedTimer>
#include <QImage>
#include <QListWidget>
#include <QMimeData>
#include <QSignalSpy>
#include <QStackedWidget>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest/QTest>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

using namespace facet;
using namespace facet::test;

Q_DECLARE_METATYPE(std::function<void(facet::Project&)>)
Q_DECLARE_METATYPE(std::function<void(facet::CompareController&)>)

namespace {

using Edit = std::function<void(Project&)>;

// A grid cell of `source` whose camera follows the shared one.
EnvironmentCell cellOf(const std::string& source)
{
    EnvironmentCell cell;
    cell.source = source;
    return cell;
}

double luma(QRgb p)
{
    return 0.2126 * qRed(p) + 0.7152 * qGreen(p) + 0.0722 * qBlue(p);
}

} // namespace

class CompareUiTest : public QObject {
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
    void cellsForEachMode_data();
    void cellsForEachMode();
    void linkedOrbitMovesEveryLinkedCell();
    void splitDragMovesDividerAndPixelsComeFromAB();
    void wedgeValuesReachTheCells();
    void layoutSavedAndRestored();
    void compareEditsUndoAndRedo_data();
    void compareEditsUndoAndRedo();
    void environmentInTwoCellsPreparedOnce();
    void singleAndCompareViewsShareLightingAndTextures();
    void replacedTexturesGoWhileACellWaits();
    void idleCompareViewDrawsNothing();
    void libraryEntryDroppedOnCell();

private:
    // Sets the project through one undo step and waits until the view drew every cell in full.
    void setProject(const Project& project);
    bool waitForSettledFrame(int timeoutMs = 60000);
    Project baseProject() const;

    QTemporaryDir m_recovery;
    CompareTestWindow m_compare;
    MainWindow* m_window = nullptr;
    Document* m_document = nullptr;
    CompareView* m_view = nullptr;
    CompareController* m_controller = nullptr;
};

void CompareUiTest::initTestCase()
{
    QVERIFY(m_compare.open(m_recovery.path()));
    m_window = m_compare.window();
    m_document = m_compare.document();
    m_view = m_compare.view();
    m_controller = m_compare.controller();
}

void CompareUiTest::cleanupTestCase()
{
    m_compare.close();
    m_window = nullptr;
}

Project CompareUiTest::baseProject() const
{
    return CompareTestWindow::baseProject();
}

void CompareUiTest::setProject(const Project& project)
{
    QVERIFY(m_compare.setProject(project));
}

bool CompareUiTest::waitForSettledFrame(int timeoutMs)
{
    return m_compare.waitForSettledFrame(timeoutMs);
}

void CompareUiTest::cellsForEachMode_data()
{
    QTest::addColumn<Edit>("edit");
    QTest::addColumn<int>("stackIndex");
    QTest::addColumn<int>("cells");
    QTest::addColumn<int>("rows");
    QTest::addColumn<int>("columns");
    QTest::addColumn<QString>("firstLabel");
    QTest::addColumn<int>("axisLabels");
    QTest::addColumn<QString>("screenshot");

    const auto grid = [](std::vector<std::string> sources) {
        return Edit([sources](Project& p) {
            p.compare.mode = CompareMode::Environments;
            p.compare.environments.cells.clear();
            for (const std::string& source : sources)
                p.compare.environments.cells.push_back(cellOf(source));
        });
    };
    // Single: the window shows its viewport; the hidden Compare view builds no cells.
    QTest::newRow("single") << Edit([](Project& p) { p.compare.mode = CompareMode::Single; }) << 0 << 0 << 1
                            << 1 << QString() << 0 << QString();
    QTest::newRow("grid of 2") << grid({"studio", "sky"}) << 1 << 2 << 1 << 2 << QStringLiteral("studio") << 0
                               << QString();
    QTest::newRow("grid of 3 (2x2)") << grid({"studio", "sky", "uniform:1"}) << 1 << 3 << 2 << 2
                                     << QStringLiteral("studio") << 0 << QStringLiteral("compare-grid.png");
    QTest::newRow("grid of 5 (3x2)") << grid({"studio", "sky", "uniform:1", "uniform:0.5", "uniform:0.25"})
                                     << 1 << 5 << 2 << 3 << QStringLiteral("studio") << 0 << QString();
    QTest::newRow("A/B split") << Edit([](Project& p) {
        p.compare.mode = CompareMode::AB;
        p.compare.ab.source = BSource::Preset;
        p.compare.ab.preset = "gold";
    }) << 1 << 2 << 1 << 1 << QStringLiteral("A · Glossy plastic")
                               << 0 << QStringLiteral("compare-ab-split.png");
    QTest::newRow("A/B side by side") << Edit([](Project& p) {
        p.compare.mode = CompareMode::AB;
        p.compare.ab.source = BSource::Preset;
        p.compare.ab.preset = "gold";
        p.compare.ab.layout = ABLayout::SideBySide;
    }) << 1 << 2 << 1 << 2 << QStringLiteral("A · Glossy plastic")
                                      << 0 << QStringLiteral("compare-ab-side-by-side.png");
    QTest::newRow("wedge 5x2 (default)")
        << Edit([](Project& p) { p.compare.mode = CompareMode::Wedge; }) << 1 << 10 << 5 << 2 << QString()
        << 7 << QStringLiteral("compare-wedge.png");
    QTest::newRow("error view (2x2)") << Edit([](Project& p) {
        p.compare.mode = CompareMode::Error;
        p.compare.error.samples = 32;
    }) << 1 << 3 << 2 << 2 << QStringLiteral("Real time · split sum (draft)")
                                      << 0 << QStringLiteral("compare-error.png");
    QTest::newRow("wedge one axis") << Edit([](Project& p) {
        p.compare.mode = CompareMode::Wedge;
        p.compare.wedge.rows = *WedgeAxis::parse("ior=1,1.5,2.5", nullptr);
        p.compare.wedge.columns.reset();
    }) << 1 << 3 << 3 << 1 << QString()
                                    << 3 << QString();
}

void CompareUiTest::cellsForEachMode()
{
    QFETCH(Edit, edit);
    QFETCH(int, stackIndex);
    QFETCH(int, cells);
    QFETCH(int, rows);
    QFETCH(int, columns);
    QFETCH(QString, firstLabel);
    QFETCH(int, axisLabels);
    QFETCH(QString, screenshot);

    Project project = baseProject();
    edit(project);
    setProject(project);
    auto* central = static_cast<QStackedWidget*>(m_window->centralWidget());
    QCOMPARE(central->currentIndex(), stackIndex);
    QVERIFY(m_window->compareActions()->modeAction(project.compare.mode)->isChecked());
    QCOMPARE(int(m_view->cells().size()), cells);
    if (stackIndex == 0)
        return;
    const GridShape shape = gridShapeOf(m_document->project());
    QCOMPARE(shape.rows, rows);
    QCOMPARE(shape.columns, columns);
    QVERIFY2(m_view->lastError().isEmpty(), qPrintable(m_view->lastError()));
    if (!firstLabel.isEmpty())
        QCOMPARE(m_view->labelOf(0), firstLabel);
    QCOMPARE(int(m_view->axisLabels().size()), axisLabels);
    // Cells lie inside the view, apart (split A/B shares one rectangle), with a gap between.
    const bool split
        = project.compare.mode == CompareMode::AB && project.compare.ab.layout == ABLayout::Split;
    for (std::size_t i = 0; i < m_view->cells().size(); ++i) {
        const QRect rect = m_view->cellRectOf(i);
        QVERIFY2(m_view->rect().contains(rect),
            qPrintable(QStringLiteral("cell %1: %2,%3 %4x%5 in %6x%7")
                           .arg(i)
                           .arg(rect.x())
                           .arg(rect.y())
                           .arg(rect.width())
                           .arg(rect.height())
                           .arg(m_view->width())
                           .arg(m_view->height())));
        QVERIFY(rect.width() > 50 && rect.height() > 50);
        for (std::size_t j = i + 1; j < m_view->cells().size() && !split; ++j)
            QVERIFY(!rect.intersects(m_view->cellRectOf(j)));
    }
    // Each cell shows something lit (not the loading grey): the centre of cell 0 is not flat.
    const QImage frame = m_view->grabFramebuffer();
    const QRect first = m_view->cellRectOf(0);
    const QRgb centre = frame.pixel(first.center());
    const int loading = int(std::lround(CompareRenderer::kLoadingGrey * 255));
    QVERIFY(std::abs(qRed(centre) - loading) > 2 || std::abs(qGreen(centre) - loading) > 2);
    if (!screenshot.isEmpty())
        QVERIFY(m_window->grab().save(outputDir() + QLatin1Char('/') + screenshot));
}

void CompareUiTest::linkedOrbitMovesEveryLinkedCell()
{
    Project project = baseProject();
    project.compare.mode = CompareMode::Environments;
    project.compare.environments.cells = {cellOf("studio"), cellOf("sky"), cellOf("uniform:1")};
    setProject(project);
    m_controller->setCellLinked(2, false);
    QVERIFY(waitForSettledFrame());
    const Camera before = m_document->project().camera;
    const Camera unlinkedBefore = m_document->project().compare.environments.cells[2].camera;
    QCOMPARE(unlinkedBefore, before); // unlinking starts where the shared camera is

    // Drag in cell 0: every linked cell turns, the unlinked one stays; nothing to undo.
    const int undoSteps = m_document->undoStack()->count();
    const QPoint start = m_view->cellRectOf(0).center();
    QTest::mousePress(m_view, Qt::LeftButton, {}, start);
    QTest::mouseMove(m_view, start + QPoint(60, 10));
    QTest::mouseRelease(m_view, Qt::LeftButton, {}, start + QPoint(60, 10));
    const Project& after = m_document->project();
    QVERIFY(after.camera != before);
    const EnvironmentGrid& grid = after.compare.environments;
    QCOMPARE(grid.cameraOf(0, after), after.camera);
    QCOMPARE(grid.cameraOf(1, after), after.camera);
    QCOMPARE(grid.cameraOf(2, after), unlinkedBefore);
    QCOMPARE(m_document->undoStack()->count(), undoSteps);
    QVERIFY(waitForSettledFrame());
    QCOMPARE(m_view->cells()[1].project.camera, after.camera);
    QCOMPARE(m_view->cells()[2].project.camera, unlinkedBefore);

    // Drag in the unlinked cell: it turns alone, in one undo step, and only it is drawn again.
    const Camera shared = after.camera;
    const QPoint third = m_view->cellRectOf(2).center();
    QTest::mousePress(m_view, Qt::LeftButton, {}, third);
    QTest::mouseMove(m_view, third + QPoint(-40, 0));
    QTest::mouseMove(m_view, third + QPoint(-80, 0));
    QTest::mouseRelease(m_view, Qt::LeftButton, {}, third + QPoint(-80, 0));
    QCOMPARE(m_document->project().camera, shared);
    QVERIFY(m_document->project().compare.environments.cells[2].camera != unlinkedBefore);
    QCOMPARE(m_document->undoStack()->count(), undoSteps + 1);
    QVERIFY(waitForSettledFrame());
    QSignalSpy rendered(m_view, &CompareView::frameRendered);
    m_view->update();
    QVERIFY(rendered.wait(10000));
    QCOMPARE(m_view->lastFrameStats().cellsDrawn, 0); // nothing changed: every cell kept
    m_controller->setCellCamera(
        2, CameraController::orbited(m_document->project().compare.environments.cells[2].camera, 5, 0));
    QVERIFY(rendered.wait(10000));
    QCOMPARE(m_view->lastFrameStats().cellsDrawn, 1);
}

void CompareUiTest::splitDragMovesDividerAndPixelsComeFromAB()
{
    Project project = baseProject();
    project.compare.mode = CompareMode::AB;
    project.compare.ab.source = BSource::Preset;
    project.compare.ab.preset = "gold";
    // A is all A at split 1, all B at split 0: the references for either side.
    project.compare.ab.split = 1.0;
    setProject(project);
    const QImage allA = m_view->grabFramebuffer();
    project.compare.ab.split = 0.0;
    setProject(project);
    const QImage allB = m_view->grabFramebuffer();
    project.compare.ab.split = 0.5;
    setProject(project);
    const QRect rect = m_view->cellRectOf(0);
    QCOMPARE(m_view->dividerX(), rect.left() + int(std::lround(0.5 * rect.width())));

    // Drag the divider to 30% of the width: one undo step.
    const int steps = m_document->undoStack()->count();
    const int y = rect.center().y();
    const int from = m_view->dividerX();
    const int to = rect.left() + int(std::lround(0.3 * rect.width()));
    QTest::mousePress(m_view, Qt::LeftButton, {}, QPoint(from + 2, y));
    QTest::mouseMove(m_view, QPoint((from + to) / 2, y));
    QTest::mouseMove(m_view, QPoint(to, y));
    QTest::mouseRelease(m_view, Qt::LeftButton, {}, QPoint(to, y));
    QCOMPARE(m_document->undoStack()->count(), steps + 1);
    QVERIFY(std::abs(m_document->project().compare.ab.split - 0.3) < 1.5 / rect.width());
    const int divider = m_view->dividerX();
    QCOMPARE(divider, to);
    QVERIFY(waitForSettledFrame());
    const QImage frame = m_view->grabFramebuffer();
    QCOMPARE(frame.size(), allA.size());
    // Every pixel left of the divider is A's, every pixel from it on B's (the object's rows and
    // the background's; within 1 code value for the rounding of the display transform).
    int differentFromA = 0;
    int differentFromB = 0;
    int abDiffer = 0;
    for (int row = rect.top(); row <= rect.bottom(); row += 4)
        for (int x = rect.left(); x <= rect.right(); ++x) {
            const QRgb p = frame.pixel(x, row);
            const QRgb a = allA.pixel(x, row);
            const QRgb b = allB.pixel(x, row);
            const auto near = [](QRgb u, QRgb v) {
                return std::abs(qRed(u) - qRed(v)) <= 1 && std::abs(qGreen(u) - qGreen(v)) <= 1
                    && std::abs(qBlue(u) - qBlue(v)) <= 1;
            };
            if (!near(a, b))
                ++abDiffer;
            if (x < divider && !near(p, a))
                ++differentFromA;
            if (x >= divider && !near(p, b))
                ++differentFromB;
        }
    QVERIFY2(abDiffer > 1000, "A and B must look different for this test to mean anything");
    QCOMPARE(differentFromA, 0);
    QCOMPARE(differentFromB, 0);

    // Undo puts the divider back.
    m_document->undoStack()->undo();
    QCOMPARE(m_document->project().compare.ab.split, 0.5);
}

void CompareUiTest::wedgeValuesReachTheCells()
{
    Project project = baseProject();
    project.compare.mode = CompareMode::Wedge;
    project.compare.wedge.rows = *WedgeAxis::parse("roughness=0.05,0.3,0.6,1", nullptr);
    project.compare.wedge.columns.reset();
    project.material().map(MapSlot::BaseColor).factor = {0.8, 0.8, 0.8, 1.0};
    project.material().map(MapSlot::Metallic).factor = glm::dvec4(1.0);
    // A flat dark background and an exposure that keeps the highlight below white: the peak of
    // each cell is the object's highlight.
    project.view.background = BackgroundMode::Color;
    project.view.backgroundColor = glm::dvec3(0.02);
    project.view.exposureEV = -4.0;
    setProject(project);
    QCOMPARE(int(m_view->cells().size()), 4);
    QCOMPARE(
        m_view->axisLabels(), strings({"roughness 0.05", "roughness 0.3", "roughness 0.6", "roughness 1"}));
    const QImage frame = m_view->grabFramebuffer();
    std::vector<double> peaks;
    for (std::size_t i = 0; i < m_view->cells().size(); ++i) {
        QCOMPARE(m_view->cells()[i].project.material().map(MapSlot::Metallic).factor.r, 1.0);
        const QRect rect = m_view->cellRectOf(i);
        double peak = 0.0;
        for (int y = rect.top(); y <= rect.bottom(); ++y)
            for (int x = rect.left(); x <= rect.right(); ++x)
                peak = std::max(peak, luma(frame.pixel(x, y)));
        peaks.push_back(peak);
    }
    qInfo("wedge highlight peaks (luma): %.1f %.1f %.1f %.1f", peaks[0], peaks[1], peaks[2], peaks[3]);
    QVERIFY2(peaks[0] < 254.0, "the sharpest highlight must not clip, or the order means nothing");
    for (std::size_t i = 1; i < peaks.size(); ++i)
        QVERIFY2(peaks[i] < peaks[i - 1] - 1.0, qPrintable(QStringLiteral("cell %1").arg(i)));
}

void CompareUiTest::layoutSavedAndRestored()
{
    Project project = baseProject();
    project.compare.mode = CompareMode::Environments;
    project.compare.environments.cells = {cellOf("sky"), cellOf("uniform:0.5"), cellOf("studio")};
    project.compare.environments.cells[1].exposureFollowsAll = false;
    project.compare.environments.cells[1].exposureOffsetEV = 1.5;
    project.compare.ab.split = 0.25;
    setProject(project);
    m_controller->setCellLinked(2, false);
    const CompareLayout saved = m_document->project().compare;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("compare.facet.json"));
    QString error;
    QVERIFY2(m_document->saveAs(path, &error), qPrintable(error));
    m_document->newProject();
    QCOMPARE(m_document->project().compare.mode, CompareMode::Single);
    QCOMPARE(static_cast<QStackedWidget*>(m_window->centralWidget())->currentIndex(), 0);
    QVERIFY2(m_document->open(path, &error), qPrintable(error));
    QCOMPARE(m_document->project().compare, saved);
    QCOMPARE(static_cast<QStackedWidget*>(m_window->centralWidget())->currentIndex(), 1);
    QVERIFY(waitForSettledFrame());
    QCOMPARE(int(m_view->cells().size()), 3);
    QCOMPARE(m_view->labelOf(1), QStringLiteral("uniform 0.5 · +1.5 EV"));
    QCOMPARE(m_view->labelOf(2), QStringLiteral("studio · unlinked"));
}

void CompareUiTest::compareEditsUndoAndRedo_data()
{
    QTest::addColumn<std::function<void(CompareController&)>>("edit");
    QTest::addColumn<QString>("undoText");
    using E = std::function<void(CompareController&)>;
    QTest::newRow("mode") << E([](CompareController& c) { c.setMode(CompareMode::Wedge); })
                          << QStringLiteral("Compare: Wedge");
    QTest::newRow("cell source") << E([](CompareController& c) { c.setCellSource(1, "uniform:2"); })
                                 << QStringLiteral("Cell Environment");
    QTest::newRow("add cell") << E([](CompareController& c) { QVERIFY(c.addCell("sky")); })
                              << QStringLiteral("Add Cell");
    QTest::newRow("remove cell") << E([](CompareController& c) { QVERIFY(c.removeCell(0)); })
                                 << QStringLiteral("Remove Cell");
    QTest::newRow("cell rotation") << E([](CompareController& c) { c.setCellRotation(0, 90.0); })
                                   << QStringLiteral("Cell Rotation");
    QTest::newRow("cell exposure") << E([](CompareController& c) { c.setCellExposure(1, -1.0); })
                                   << QStringLiteral("Cell Exposure");
    QTest::newRow("unlink cell") << E([](CompareController& c) { c.setCellLinked(1, false); })
                                 << QStringLiteral("Unlink Cell Camera");
    QTest::newRow("unlink all") << E([](CompareController& c) { c.setLinkedCameras(false); })
                                << QStringLiteral("Unlink Cameras");
    QTest::newRow("split") << E([](CompareController& c) { c.setSplit(0.8); }) << QStringLiteral("A/B Split");
    QTest::newRow("side by side") << E([](CompareController& c) { c.setABLayout(ABLayout::SideBySide); })
                                  << QStringLiteral("A/B Side by Side");
    QTest::newRow("B preset") << E([](CompareController& c) { c.setBPreset("gold"); })
                              << QStringLiteral("B: Preset");
    QTest::newRow("swap") << E([](CompareController& c) { c.swap(); }) << QStringLiteral("Swap A and B");
    QTest::newRow("wedge axes") << E([](CompareController& c) {
        QVERIFY(c.setWedge("metallic=0,1", "ior=1.2,1.8", nullptr));
    }) << QStringLiteral("Wedge Axes");
    QTest::newRow("error view") << E([](CompareController& c) { c.setMode(CompareMode::Error); })
                                << QStringLiteral("Compare: Error View");
    QTest::newRow("error scale") << E([](CompareController& c) { c.setErrorScale(0.05); })
                                 << QStringLiteral("Error Scale");
    QTest::newRow("error noise") << E([](CompareController& c) { c.setErrorShowsNoise(true); })
                                 << QStringLiteral("Show Reference Noise");
    QTest::newRow("error samples") << E([](CompareController& c) { c.setErrorSamples(16); })
                                   << QStringLiteral("Error View Samples");
    QTest::newRow("promote") << E([](CompareController& c) { c.promoteCell(1); })
                             << QStringLiteral("Promote Cell to Single View");
}

void CompareUiTest::compareEditsUndoAndRedo()
{
    QFETCH(std::function<void(CompareController&)>, edit);
    QFETCH(QString, undoText);
    Project project = baseProject();
    project.compare.mode = CompareMode::Environments;
    project.compare.environments.cells = {cellOf("studio"), cellOf("uniform:1"), cellOf("uniform:0.5")};
    project.material().map(MapSlot::BaseColor).factor = {0.2, 0.4, 0.9, 1.0};
    setProject(project);
    const Project before = m_document->project();
    const int steps = m_document->undoStack()->count();
    edit(*m_controller);
    const Project after = m_document->project();
    QVERIFY(after.compare != before.compare || after.material() != before.material());
    QCOMPARE(m_document->undoStack()->count(), steps + 1);
    QCOMPARE(m_document->undoStack()->undoText(), undoText);
    m_document->undoStack()->undo();
    QCOMPARE(m_document->project().compare, before.compare);
    QCOMPARE(m_document->project().materials, before.materials);
    QCOMPARE(m_document->project().environment, before.environment);
    // The view follows the undo (cells rebuilt from the document).
    QCOMPARE(int(m_view->cells().size()), int(before.compare.environments.cells.size()));
    m_document->undoStack()->redo();
    QCOMPARE(m_document->project().compare, after.compare);
    QCOMPARE(m_document->project().materials, after.materials);
}

void CompareUiTest::environmentInTwoCellsPreparedOnce()
{
    // Sources no other test shows, so the counts start here.
    Project project = baseProject();
    project.compare.mode = CompareMode::Environments;
    project.compare.environments.cells
        = {cellOf("uniform:0.375"), cellOf("uniform:0.625"), cellOf("uniform:0.375")};
    setProject(baseProject()); // the single view's environment loaded before the count starts
    const int loadsBefore = m_view->assets()->loads(DocumentAssets::Kind::Environment);
    QVERIFY(waitForSettledFrame());
    const CompareFrameStats statsBefore = m_view->lastFrameStats();
    setProject(project);
    const CompareFrameStats& stats = m_view->lastFrameStats();
    QCOMPARE(m_view->assets()->loads(DocumentAssets::Kind::Environment) - loadsBefore, 2);
    QCOMPARE(stats.iblRequests - statsBefore.iblRequests, 2);
    QCOMPARE(
        (stats.iblComputed + stats.iblFromDisk) - (statsBefore.iblComputed + statsBefore.iblFromDisk), 2);
    // Both made on the view's lighting worker, off the GUI thread (where the platform has one:
    // Xvfb's llvmpipe does).
    QCOMPARE(stats.iblFromWorker - statsBefore.iblFromWorker, 2);
    // Orbiting prepares nothing.
    const QPoint start = m_view->cellRectOf(0).center();
    QTest::mousePress(m_view, Qt::LeftButton, {}, start);
    QTest::mouseMove(m_view, start + QPoint(30, 0));
    QTest::mouseRelease(m_view, Qt::LeftButton, {}, start + QPoint(30, 0));
    QVERIFY(waitForSettledFrame());
    QCOMPARE(m_view->lastFrameStats().iblRequests - statsBefore.iblRequests, 2);
    QCOMPARE(m_view->assets()->loads(DocumentAssets::Kind::Environment) - loadsBefore, 2);
}

void CompareUiTest::singleAndCompareViewsShareLightingAndTextures()
{
    // The single view shows a red base colour map under an environment no other test shows;
    // once its frame is complete it releases the decoded map (only the texture is left).
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString mapPath = dir.filePath(QStringLiteral("red.png"));
    QImage red(64, 64, QImage::Format_RGB32);
    red.fill(qRgb(220, 24, 16));
    QVERIFY(red.save(mapPath));
    Project project = baseProject();
    project.environment.source = "uniform:0.4375";
    project.materials[0].setBaseColor({1.0, 1.0, 1.0});
    project.materials[0].map(MapSlot::Metallic).factor.x = 0.0;
    project.materials[0].map(MapSlot::BaseColor).path = mapPath.toStdString();
    project.compare.mode = CompareMode::Single;
    setProject(project);
    const SceneController* scene = m_window->sceneController();
    const auto released = [scene] {
        const auto& maps = scene->assets().maps;
        const auto& image = maps.empty() ? nullptr : maps[0][std::size_t(MapSlot::BaseColor)].image;
        return image && !image->hasPixels();
    };
    // And its lighting is made: until then (on its worker, slower when the machine is busy) the
    // Compare view would find no set to share and make its own.
    const ViewportWidget* single = m_window->viewport();
    QTRY_VERIFY_WITH_TIMEOUT(released() && !single->lastFrameStats().lightingPending, 60000);

    // The Compare view, in a context of the same share group, finds both: the environment's IBL
    // set is not computed again (only the new one is) and the map is not decoded or uploaded again.
    const CompareFrameStats before = m_view->lastFrameStats();
    const int mapLoadsBefore = m_view->assets()->loads(DocumentAssets::Kind::Map);
    project.compare.mode = CompareMode::Environments;
    project.compare.environments.cells = {cellOf("uniform:0.4375"), cellOf("uniform:0.5625")};
    setProject(project);
    const CompareFrameStats& stats = m_view->lastFrameStats();
    QCOMPARE(stats.iblRequests - before.iblRequests, 2);
    QCOMPARE(stats.iblComputed - before.iblComputed, 1);
    QCOMPARE(stats.texturesUploaded - before.texturesUploaded, 0);
    QCOMPARE(m_view->assets()->loads(DocumentAssets::Kind::Map) - mapLoadsBefore, 0);
    QVERIFY(released()); // drawn from the shared texture, not from a decoded copy

    // And the cells show the map: the sphere's centre is red, not the white factor.
    const QImage frame = m_view->grabFramebuffer();
    for (int cell = 0; cell < 2; ++cell) {
        const QRgb centre = frame.pixel(m_view->cellRectOf(cell).center() * frame.devicePixelRatio());
        QVERIFY2(qRed(centre) > 2 * qGreen(centre) && qRed(centre) > 2 * qBlue(centre),
            qPrintable(QStringLiteral("cell %1 centre is (%2, %3, %4)")
                           .arg(cell)
                           .arg(qRed(centre))
                           .arg(qGreen(centre))
                           .arg(qBlue(centre))));
    }
}

void CompareUiTest::replacedTexturesGoWhileACellWaits()
{
    // A grid of two cells, one of them an environment file that cannot be read (it waits in the
    // loading grey for good). The current material's map is replaced: the old texture must go,
    // although not every cell was drawn with its environment (it stayed on the GPU for as long
    // as any cell waited), and the new one is uploaded once.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const auto writeMap = [&dir](const char* name, QRgb colour) {
        QImage image(32, 32, QImage::Format_RGB32);
        image.fill(colour);
        const QString path = dir.filePath(QString::fromLatin1(name));
        return image.save(path) ? path.toStdString() : std::string();
    };
    const std::string first = writeMap("first.png", qRgb(200, 40, 40));
    const std::string second = writeMap("second.png", qRgb(40, 200, 40));
    QVERIFY(!first.empty() && !second.empty());
    Project project = baseProject();
    project.materials[0].map(MapSlot::BaseColor).path = first;
    project.compare.mode = CompareMode::Environments;
    project.compare.environments.cells
        = {cellOf("uniform:0.53125"), cellOf(dir.filePath(QStringLiteral("missing.exr")).toStdString())};
    setProject(project);
    QTRY_COMPARE_WITH_TIMEOUT(m_window->sceneController()->pendingMapLoads(), 0, 30000);
    QVERIFY(waitForSettledFrame());
    QCOMPARE(m_view->lastFrameStats().texturesResident, 1);

    Project edited = m_document->project();
    edited.materials[0].map(MapSlot::BaseColor).path = second;
    const int uploadsBefore = m_view->lastFrameStats().texturesUploaded;
    m_document->setProject(edited, QStringLiteral("New map"));
    QTRY_COMPARE_WITH_TIMEOUT(m_window->sceneController()->pendingMapLoads(), 0, 30000);
    QVERIFY(waitForSettledFrame());
    QCOMPARE(m_view->lastFrameStats().texturesResident, 1); // the first map's texture went
    QCOMPARE(m_view->lastFrameStats().texturesUploaded - uploadsBefore, 1);
}

void CompareUiTest::idleCompareViewDrawsNothing()
{
    Project project = baseProject();
    project.compare.mode = CompareMode::Environments;
    setProject(project);
    QTest::qWait(CompareView::kRefineDelayMs * 2);
    const std::uint64_t frames = m_view->frameCount();
    QTest::qWait(1000);
    QCOMPARE(m_view->frameCount(), frames);
}

void CompareUiTest::libraryEntryDroppedOnCell()
{
    Project project = baseProject();
    project.compare.mode = CompareMode::Environments;
    project.compare.environments.cells = {cellOf("studio"), cellOf("uniform:1"), cellOf("uniform:0.5")};
    setProject(project);
    // The dock's "Sky (built-in)" entry, dragged as the list drags it, onto cell 1, then onto
    // the free quarter of the 2x2 grid (a new cell).
    QListWidget* library = m_window->environmentDock()->library();
    QListWidgetItem* sky = nullptr;
    for (int row = 0; row < library->count(); ++row)
        if (library->item(row)->data(Qt::UserRole).toString() == QStringLiteral("sky"))
            sky = library->item(row);
    QVERIFY(sky);
    const auto drop = [this, library, sky](const QPoint& at) {
        std::unique_ptr<QMimeData> mime(library->model()->mimeData({library->indexFromItem(sky)}));
        QDragEnterEvent enter(at, Qt::CopyAction, mime.get(), Qt::LeftButton, {});
        QCoreApplication::sendEvent(m_view, &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent dropped(QPointF(at), Qt::CopyAction, mime.get(), Qt::LeftButton, {});
        QCoreApplication::sendEvent(m_view, &dropped);
    };
    drop(m_view->cellRectOf(1).center());
    QCOMPARE(m_document->project().compare.environments.cells[1].source, std::string("sky"));
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Cell Environment"));
    const QRect last = m_view->cellRectOf(2);
    drop(QPoint(m_view->width() - 5, last.center().y()));
    QCOMPARE(int(m_document->project().compare.environments.cells.size()), 4);
    QCOMPARE(m_document->project().compare.environments.cells[3].source, std::string("sky"));
}

QTEST_MAIN(CompareUiTest)
#include "CompareUiTest.moc"
