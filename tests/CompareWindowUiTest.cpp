// What an artist meets around the Compare view in the main window: environments multi-selected
// in the Environment dock's library filling the grid (selection order, one undo step, at most 9
// with a status message), the free part of a grid whose last row is short showing the gap grey
// (not black, not what an earlier mode drew there), the status bar following the shown view
// (the hidden single view's "Preparing the lighting" taken off, the Compare view's own lighting
// progress and frame statistics), and the Wedge Axes dialog (parameter combos, values checked
// while typed, from/to/steps). Needs a display (Xvfb via with-display.sh).

#include "core/project/WedgeAxis.h"
#include "ui/MainWindow.h"
#include "ui/compare/CompareActions.h"
#include "ui/compare/CompareCells.h"
#include "ui/compare/CompareController.h"
#include "ui/compare/CompareMenus.h"
#include "ui/compare/CompareRenderer.h"
#include "ui/compare/CompareView.h"
#include "ui/compare/WedgeAxesDialog.h"
#include "ui/compare/WedgeAxisEditor.h"
#include "ui/docks/EnvironmentDock.h"
#include "ui/document/Document.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewStatus.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/widgets/WindowMessages.h"

#include "CompareTestWindow.h"
#include "TestSupport.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QRadioButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStackedWidget>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QtTest/QTest>

#include <cmath>
#include <functional>
#include <memory>

using namespace facet;
using namespace facet::test;

using DialogEdit = std::function<void(WedgeAxesDialog&)>;
using Clicks = QList<QPair<QString, int>>; // (library source, keyboard modifiers), in order
Q_DECLARE_METATYPE(DialogEdit)

namespace {

EnvironmentCell cellOf(const std::string& source)
{
    EnvironmentCell cell;
    cell.source = source;
    return cell;
}

std::vector<std::string> sourcesOf(const Project& project)
{
    std::vector<std::string> sources;
    for (const EnvironmentCell& cell : project.compare.environments.cells)
        sources.push_back(cell.source);
    return sources;
}

// Chooses `parameter` in `editor`'s combo as a user does (the combo's signal runs).
void chooseParameter(WedgeAxisEditor* editor, const QString& parameter)
{
    const int index = editor->parameterCombo()->findText(parameter);
    QVERIFY2(index >= 0, qPrintable(parameter));
    editor->parameterCombo()->setCurrentIndex(index);
}

void typeValues(WedgeAxisEditor* editor, const QString& values)
{
    editor->valuesEdit()->selectAll();
    QTest::keyClicks(editor->valuesEdit(), values);
    QCOMPARE(editor->valuesEdit()->text(), values);
}

void chooseRange(WedgeAxisEditor* editor, double from, double to, int steps)
{
    editor->rangeMode()->click();
    editor->fromSpin()->setValue(from);
    editor->toSpin()->setValue(to);
    editor->stepsSpin()->setValue(steps);
}

} // namespace

class CompareWindowUiTest : public QObject {
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
    void compareSelectedEnvironments_data();
    void compareSelectedEnvironments();
    void moreThanNineSelectedUsesTheFirstNine();
    void freeGridSlotShowsGapGrey_data();
    void freeGridSlotShowsGapGrey();
    void singleViewPreparingMessageLeavesWithIt();
    void compareViewReportsItsLighting();
    void frameStatisticsDescribeTheShownView();
    void wedgeAxesDialog_data();
    void wedgeAxesDialog();
    void wedgeAxesDialogNamesAnAxisThatSweepsNothing_data();
    void wedgeAxesDialogNamesAnAxisThatSweepsNothing();
    void wedgeAxesFromTheCellMenu();

private:
    void setProject(const Project& project);
    bool waitForSettledFrame(int timeoutMs = 60000);
    Project baseProject() const;
    QListWidgetItem* libraryItem(const QString& source) const;
    void clickLibrary(QListWidgetItem* item, Qt::KeyboardModifiers modifiers);
    QStackedWidget* central() const { return static_cast<QStackedWidget*>(m_window->centralWidget()); }
    QLabel* frameStatsLabel() const
    {
        return m_window->findChild<QLabel*>(QStringLiteral("frameStatsLabel"));
    }

    QTemporaryDir m_recovery;
    QTemporaryDir m_files;
    CompareTestWindow m_compare;
    MainWindow* m_window = nullptr;
    Document* m_document = nullptr;
    CompareView* m_view = nullptr;
    CompareController* m_controller = nullptr;
    QListWidget* m_library = nullptr;
};

void CompareWindowUiTest::initTestCase()
{
    QVERIFY(m_compare.open(m_recovery.path()));
    m_window = m_compare.window();
    m_document = m_compare.document();
    m_view = m_compare.view();
    m_controller = m_compare.controller();
    m_library = m_window->environmentDock()->library();
    m_window->environmentDock()->raise();
}

void CompareWindowUiTest::cleanupTestCase()
{
    m_compare.close();
    m_window = nullptr;
}

Project CompareWindowUiTest::baseProject() const
{
    return CompareTestWindow::baseProject();
}

void CompareWindowUiTest::setProject(const Project& project)
{
    QVERIFY(m_compare.setProject(project));
}

bool CompareWindowUiTest::waitForSettledFrame(int timeoutMs)
{
    return m_compare.waitForSettledFrame(timeoutMs);
}

QListWidgetItem* CompareWindowUiTest::libraryItem(const QString& source) const
{
    for (int row = 0; row < m_library->count(); ++row)
        if (m_library->item(row)->data(Qt::UserRole).toString() == source)
            return m_library->item(row);
    return nullptr;
}

void CompareWindowUiTest::clickLibrary(QListWidgetItem* item, Qt::KeyboardModifiers modifiers)
{
    QVERIFY(item);
    m_library->scrollToItem(item);
    QTest::mouseClick(
        m_library->viewport(), Qt::LeftButton, modifiers, m_library->visualItemRect(item).center());
}

void CompareWindowUiTest::compareSelectedEnvironments_data()
{
    QTest::addColumn<Clicks>("clicks");
    QTest::addColumn<bool>("enabled");
    QTest::addColumn<QStringList>("cells"); // empty: nothing happens
    const int ctrl = int(Qt::ControlModifier);
    const int shift = int(Qt::ShiftModifier);
    const int none = int(Qt::NoModifier);
    QTest::newRow("one selected: disabled")
        << Clicks {{QStringLiteral("sky"), none}} << false << QStringList();
    // Ctrl-click order, not the list's (studio is above sky in it).
    QTest::newRow("two by Ctrl-click, in that order") << Clicks {{QStringLiteral("sky"), none},
        {QStringLiteral("studio"), ctrl}} << true << strings({"sky", "studio"});
    QTest::newRow("Shift range, in the list's order") << Clicks {{QStringLiteral("studio"), none},
        {QStringLiteral("sky"), shift}} << true << strings({"studio", "sky"});
    QTest::newRow("Ctrl-click takes one out again") << Clicks {{QStringLiteral("studio"), none},
        {QStringLiteral("sky"), ctrl}, {QStringLiteral("studio"), ctrl}}
                                                    << false << QStringList();
}

void CompareWindowUiTest::compareSelectedEnvironments()
{
    QFETCH(Clicks, clicks);
    QFETCH(bool, enabled);
    QFETCH(QStringList, cells);

    Project project = baseProject();
    project.environment.source = "uniform:0.5"; // in no library entry: clicks below change it visibly
    project.compare.environments.cells
        = {cellOf("uniform:1"), cellOf("uniform:0.25"), cellOf("uniform:0.75")};
    project.compare.environments.cells[0].rotationFollowsAll = false;
    project.compare.environments.cells[0].rotationDegrees = 45.0;
    setProject(project);
    QCOMPARE(central()->currentIndex(), 0);

    QAction* action = m_window->compareActions()->compareSelectedAction();
    QVERIFY(m_window->compareActions()->menu()->actions().contains(action));
    QCOMPARE(m_library->contextMenuPolicy(), Qt::ActionsContextMenu);
    QVERIFY(m_library->actions().contains(action));

    const int steps = m_document->undoStack()->count();
    for (const auto& [source, modifiers] : clicks)
        clickLibrary(libraryItem(source), Qt::KeyboardModifiers(modifiers));
    // A plain click chooses the single view's environment (one step); a Ctrl- or Shift-click
    // only selects.
    QCOMPARE(QString::fromStdString(m_document->project().environment.source), clicks.front().first);
    QCOMPARE(m_document->undoStack()->count(), steps + 1);
    QCOMPARE(action->isEnabled(), enabled);

    const Project before = m_document->project();
    action->trigger();
    if (cells.isEmpty()) {
        QCOMPARE(m_document->project().compare, before.compare);
        QCOMPARE(m_document->undoStack()->count(), steps + 1);
        return;
    }
    const Project& after = m_document->project();
    QCOMPARE(after.compare.mode, CompareMode::Environments);
    QCOMPARE(central()->currentIndex(), 1);
    std::vector<std::string> expected;
    for (const QString& cell : cells)
        expected.push_back(cell.toStdString());
    QCOMPARE(sourcesOf(after), expected);
    // Each cell with the defaults: follows the grid's rotation and exposure, camera linked.
    for (const EnvironmentCell& cell : after.compare.environments.cells) {
        QVERIFY(cell.rotationFollowsAll && cell.exposureFollowsAll && cell.cameraLinked);
        QCOMPARE(cell.camera, after.camera);
    }
    QCOMPARE(m_document->undoStack()->count(), steps + 2);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Compare Selected Environments"));
    QVERIFY(waitForSettledFrame());
    QCOMPARE(m_view->labelOf(0), environmentLabel(expected[0]));

    // One undo: the old cells and the single view back.
    m_document->undoStack()->undo();
    QCOMPARE(m_document->project().compare, before.compare);
    QCOMPARE(central()->currentIndex(), 0);
}

void CompareWindowUiTest::moreThanNineSelectedUsesTheFirstNine()
{
    // A user library of 11 environments, selected last to first.
    const QString folder = m_files.filePath(QStringLiteral("eleven"));
    QStringList files;
    for (int i = 0; i < 11; ++i) {
        files.append(QStringLiteral("%1/env%2.exr").arg(folder).arg(i, 2, 10, QLatin1Char('0')));
        QVERIFY(writeConstantExr(files.back(), 0.1f * float(i + 1)));
    }
    QVERIFY(m_window->environmentDock()->addFolder(folder));
    Project project = baseProject();
    setProject(project);
    m_library->clearSelection();
    for (int i = int(files.size()) - 1; i >= 0; --i) {
        QListWidgetItem* item = libraryItem(files[i]);
        QVERIFY2(item, qPrintable(files[i]));
        item->setSelected(true);
    }
    QAction* action = m_window->compareActions()->compareSelectedAction();
    QVERIFY(action->isEnabled());
    const int steps = m_document->undoStack()->count();
    action->trigger();
    QCOMPARE(m_document->undoStack()->count(), steps + 1);
    const std::vector<std::string> sources = sourcesOf(m_document->project());
    QCOMPARE(int(sources.size()), EnvironmentGrid::kMaxCells);
    for (int i = 0; i < EnvironmentGrid::kMaxCells; ++i)
        QCOMPARE(QString::fromStdString(sources[std::size_t(i)]), files[10 - i]);
    QVERIFY2(m_window->statusMessage().contains(QStringLiteral("first 9 of the 11 selected")),
        qPrintable(m_window->statusMessage()));
    // Still said once the grid has prepared its lighting (its messages come right after). The
    // environments are decoded on a pool and may reach the grid in more than one frame, each
    // frame's lighting then announced alone (seen under the asan preset): the last batch is named.
    QVERIFY(waitForSettledFrame());
    static const QRegularExpression kReady(QStringLiteral("^Lighting of \\d environments? ready"));
    QVERIFY2(kReady.match(m_window->statusMessage()).hasMatch()
            && m_window->statusMessage().contains(QStringLiteral("first 9 of the 11 selected")),
        qPrintable(m_window->statusMessage()));
    QVERIFY(m_window->grab().save(outputDir() + QStringLiteral("/compare-selected-nine.png")));
}

void CompareWindowUiTest::freeGridSlotShowsGapGrey_data()
{
    // Shown first: a 3x1 wedge, whose three rows cover the whole view and its axis margin (the
    // same number of cells as a 3-cell grid in another arrangement: nothing of it may show).
    QTest::addColumn<bool>("afterWedge");
    QTest::addColumn<int>("cells");
    QTest::addColumn<QString>("screenshot");
    QTest::newRow("3 cells (2x2)") << false << 3 << QStringLiteral("compare-grid-of-3.png");
    QTest::newRow("5 cells (3x2)") << false << 5 << QStringLiteral("compare-grid-of-5.png");
    QTest::newRow("7 cells (3x3)") << false << 7 << QString();
    QTest::newRow("3 cells after a 3-cell wedge") << true << 3 << QString();
}

void CompareWindowUiTest::freeGridSlotShowsGapGrey()
{
    QFETCH(bool, afterWedge);
    QFETCH(int, cells);
    QFETCH(QString, screenshot);
    const char* const sources[]
        = {"studio", "sky", "uniform:1", "uniform:0.5", "uniform:0.25", "uniform:0.75", "uniform:2"};
    if (afterWedge) {
        Project wedge = baseProject();
        wedge.compare.mode = CompareMode::Wedge;
        wedge.compare.wedge.rows = *WedgeAxis::parse("roughness=0.2,0.5,0.8", nullptr);
        wedge.compare.wedge.columns.reset();
        setProject(wedge);
    }
    Project project = baseProject();
    project.compare.mode = CompareMode::Environments;
    project.compare.environments.cells.clear();
    for (int i = 0; i < cells; ++i)
        project.compare.environments.cells.push_back(cellOf(sources[i]));
    setProject(project);

    const QImage frame = m_view->grabFramebuffer();
    const GridShape shape = gridShapeFor(std::size_t(cells));
    const int gap = int(std::lround(CompareRenderer::displayGrey(CompareRenderer::kGapGrey) * 255.0f));
    QVERIFY2(gap > 40, "the gap grey must not read as black");
    int checked = 0;
    for (int slot = cells; slot < shape.rows * shape.columns; ++slot) {
        const QRect rect = cellRect(
            m_view->size(), shape, slot / shape.columns, slot % shape.columns, CompareView::kGapPixels);
        QVERIFY(rect.width() > 20 && rect.height() > 20);
        // A 5x5 lattice over the free slot, inset from its edges.
        for (int j = 0; j < 5; ++j)
            for (int i = 0; i < 5; ++i) {
                const QPoint at(rect.left() + 4 + (rect.width() - 8) * i / 4,
                    rect.top() + 4 + (rect.height() - 8) * j / 4);
                const QRgb pixel = frame.pixel(at);
                QVERIFY2(std::abs(qRed(pixel) - gap) <= 1 && std::abs(qGreen(pixel) - gap) <= 1
                        && std::abs(qBlue(pixel) - gap) <= 1,
                    qPrintable(QStringLiteral("slot %1 at (%2, %3): %4 %5 %6, expected %7")
                                   .arg(slot)
                                   .arg(at.x())
                                   .arg(at.y())
                                   .arg(qRed(pixel))
                                   .arg(qGreen(pixel))
                                   .arg(qBlue(pixel))
                                   .arg(gap)));
                ++checked;
            }
    }
    QVERIFY(checked > 0);
    if (!screenshot.isEmpty())
        QVERIFY(m_window->grab().save(outputDir() + QLatin1Char('/') + screenshot));
}

void CompareWindowUiTest::singleViewPreparingMessageLeavesWithIt()
{
    // The single view shown and drawn, nothing announced.
    Project project = baseProject();
    QSignalSpy drawn(m_window->viewport(), &ViewportWidget::frameRendered);
    setProject(project);
    QVERIFY(drawn.count() > 0 || drawn.wait(60000));
    // A new environment for the single view: it announces its precompute, and the window switches
    // to the grid before the (now hidden) single view draws it.
    QSignalSpy starting(m_window->viewport(), &ViewportWidget::iblPrecomputeStarting);
    project.environment.source = "uniform:0.8125";
    m_document->setProject(project, QStringLiteral("environment"));
    QCOMPARE(starting.count(), 1);
    const QString preparing = WindowMessages::lightingPreparing(starting.front().front().toString());
    QCOMPARE(m_window->statusMessage(), preparing);
    m_controller->setMode(CompareMode::Environments);
    QCOMPARE(central()->currentIndex(), 1);
    QVERIFY2(m_window->statusMessage() != preparing, qPrintable(m_window->statusMessage()));
    QVERIFY(waitForSettledFrame());
    QTest::qWait(200);
    QVERIFY2(m_window->statusMessage() != preparing, qPrintable(m_window->statusMessage()));
    const auto* dockStatus = m_window->findChild<QLabel*>(QStringLiteral("environmentStatus"));
    QVERIFY(dockStatus->text() != preparing);
    QVERIFY(m_window->grab().save(outputDir() + QStringLiteral("/compare-status-after-switch.png")));

    // Back to the single view, which has not drawn it yet: its message comes back, then "ready".
    QSignalSpy finished(m_window->viewport(), &ViewportWidget::iblPrecomputeFinished);
    m_controller->setMode(CompareMode::Single);
    QCOMPARE(m_window->statusMessage(), preparing);
    QVERIFY(finished.wait(60000));
    QVERIFY2(m_window->statusMessage().startsWith(QStringLiteral("Lighting of")),
        qPrintable(m_window->statusMessage()));

    // Announced while hidden, then undone before the single view drew it: showing the single view
    // again ends with its lighting ready, not with the "Preparing" of the environment it never drew.
    m_controller->setMode(CompareMode::Environments);
    QVERIFY(waitForSettledFrame());
    Project other = m_document->project();
    other.environment.source = "uniform:0.9375";
    starting.clear();
    m_document->setProject(other, QStringLiteral("environment"));
    QCOMPARE(starting.count(), 1);
    m_document->undoStack()->undo();
    finished.clear();
    m_controller->setMode(CompareMode::Single);
    QVERIFY(finished.count() > 0 || finished.wait(60000));
    QVERIFY2(m_window->statusMessage().startsWith(QStringLiteral("Lighting of uniform")),
        qPrintable(m_window->statusMessage()));
    // And the next environment is announced again.
    starting.clear();
    other.compare.mode = CompareMode::Single;
    other.environment.source = "uniform:0.4375";
    m_document->setProject(other, QStringLiteral("environment"));
    QCOMPARE(starting.count(), 1);
}

void CompareWindowUiTest::compareViewReportsItsLighting()
{
    Project project = baseProject();
    setProject(project);
    // Environments no other test shows (the views share one precompute: one the single view
    // lit earlier would be a memory hit): three precomputes.
    project.compare.mode = CompareMode::Environments;
    project.compare.environments.cells = {cellOf("uniform:0.3125"), cellOf("uniform:0.6875"),
        cellOf("uniform:0.5625"), cellOf("uniform:0.6875")};
    QStringList messages;
    std::vector<int> computedAtMessage;
    connect(m_window->statusBar(), &QStatusBar::messageChanged, this, [&](const QString& text) {
        messages.append(text);
        computedAtMessage.push_back(m_view->lastFrameStats().iblComputed);
    });
    const int computedBefore = m_view->lastFrameStats().iblComputed;
    m_document->setProject(project, QStringLiteral("grid"));
    QVERIFY(waitForSettledFrame());
    disconnect(m_window->statusBar(), &QStatusBar::messageChanged, this, nullptr);
    // The views share one precompute, so a set another row's frames left in memory is a hit, not
    // announced: the announcement names exactly the sets this grid computed (3, or fewer).
    const int computed = m_view->lastFrameStats().iblComputed - computedBefore;
    QVERIFY2(computed >= 2 && computed <= 3, qPrintable(QString::number(computed)));
    QCOMPARE(
        WindowMessages::lightingPreparing(3), QStringLiteral("Preparing the lighting of 3 environments…"));
    const QString preparing = WindowMessages::lightingPreparing(computed);
    const qsizetype announced = messages.indexOf(preparing);
    QVERIFY2(announced >= 0, qPrintable(messages.join(QLatin1Char('|'))));
    // Said before the frame that precomputed, and replaced by the time once done.
    QCOMPARE(computedAtMessage[std::size_t(announced)], computedBefore);
    QVERIFY2(m_window->statusMessage().startsWith(
                 QStringLiteral("Lighting of %1 environments ready (").arg(computed)),
        qPrintable(m_window->statusMessage()));
    const auto* dockStatus = m_window->findChild<QLabel*>(QStringLiteral("environmentStatus"));
    QCOMPARE(dockStatus->text(), m_window->statusMessage());
    QVERIFY(m_window->grab().save(outputDir() + QStringLiteral("/compare-status-lighting.png")));
}

void CompareWindowUiTest::frameStatisticsDescribeTheShownView()
{
    Project project = baseProject();
    project.compare.mode = CompareMode::Environments;
    project.compare.environments.cells = {cellOf("studio"), cellOf("sky"), cellOf("uniform:1")};
    setProject(project);
    QLabel* label = frameStatsLabel();
    QVERIFY(label);
    QCOMPARE(label->text(), ViewStatus::compareSummary(m_view->lastFrameStats()));
    QVERIFY2(label->text().startsWith(QStringLiteral("3 cells, ")), qPrintable(label->text()));
    QVERIFY(!label->text().contains(QStringLiteral("(preview)")));
    QVERIFY(label->toolTip().contains(QStringLiteral("Compare view")));

    // While orbiting: previews, said as the single view says it.
    QSignalSpy rendered(m_view, &CompareView::frameRendered);
    const QPoint start = m_view->cellRectOf(0).center();
    QTest::mousePress(m_view, Qt::LeftButton, {}, start);
    QTest::mouseMove(m_view, start + QPoint(40, 0));
    QVERIFY(rendered.wait(10000));
    QVERIFY(m_view->lastFrameStats().reduced);
    QVERIFY2(label->text().contains(QStringLiteral("3 cells, 3 drawn · ")), qPrintable(label->text()));
    QVERIFY2(label->text().contains(QStringLiteral(" (preview)")), qPrintable(label->text()));
    QTest::mouseRelease(m_view, Qt::LeftButton, {}, start + QPoint(40, 0));
    QVERIFY(waitForSettledFrame());
    QVERIFY(!label->text().contains(QStringLiteral("(preview)")));

    // The single view: its own "W×H · N ms" once shown.
    QSignalSpy single(m_window->viewport(), &ViewportWidget::frameRendered);
    m_controller->setMode(CompareMode::Single);
    QVERIFY(single.wait(60000));
    const QRegularExpression singleStyle(QStringLiteral("^\\d+×\\d+ · \\d+ ms"));
    QVERIFY2(singleStyle.match(label->text()).hasMatch(), qPrintable(label->text()));
    QCOMPARE(label->text(), m_window->viewport()->lastFrameStats().summary());
    QVERIFY(label->toolTip().isEmpty());
    // And back: the Compare view's at once, before it draws again.
    m_controller->setMode(CompareMode::Environments);
    QVERIFY2(label->text().startsWith(QStringLiteral("3 cells, ")), qPrintable(label->text()));
}

void CompareWindowUiTest::wedgeAxesDialog_data()
{
    QTest::addColumn<DialogEdit>("edit");
    QTest::addColumn<bool>("ok");
    QTest::addColumn<QString>("rowsMessage"); // contained in the rows' message
    QTest::addColumn<QString>("columnsMessage");
    QTest::addColumn<QString>("rows"); // the axes applied (when ok)
    QTest::addColumn<QString>("columns");

    const auto rows = [](WedgeAxesDialog& d) { return d.rows(); };
    const auto columns = [](WedgeAxesDialog& d) { return d.columns(); };
    QTest::newRow("unchanged: the wedge's axes")
        << DialogEdit([](WedgeAxesDialog&) {}) << true << QStringLiteral("5 values")
        << QStringLiteral("2 values") << QStringLiteral("roughness=0,0.25,0.5,0.75,1")
        << QStringLiteral("metallic=0,1");
    QTest::newRow("list typed") << DialogEdit(
        [=](WedgeAxesDialog& d) { typeValues(rows(d), QStringLiteral("0.1, 0.9")); })
                                << true << QStringLiteral("2 values") << QString()
                                << QStringLiteral("roughness=0.1,0.9") << QStringLiteral("metallic=0,1");
    QTest::newRow("value out of range")
        << DialogEdit([=](WedgeAxesDialog& d) { typeValues(rows(d), QStringLiteral("0, 1.5")); }) << false
        << QStringLiteral("1.5 is outside [0, 1]") << QString() << QString() << QString();
    QTest::newRow("not a number") << DialogEdit([=](WedgeAxesDialog& d) {
        typeValues(rows(d), QStringLiteral("0, half"));
    }) << false << QStringLiteral("\"half\", is not a number")
                                  << QString() << QString() << QString();
    QTest::newRow("empty value") << DialogEdit([=](WedgeAxesDialog& d) {
        typeValues(rows(d), QStringLiteral("0,,1"));
    }) << false << QStringLiteral("value 2 is empty")
                                 << QString() << QString() << QString();
    QTest::newRow("more than 16") << DialogEdit([=](WedgeAxesDialog& d) {
        typeValues(rows(d), QStringLiteral("0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0"));
    }) << false << QStringLiteral("17 values, more than the 16")
                                  << QString() << QString() << QString();
    QTest::newRow("second axis invalid") << DialogEdit([=](WedgeAxesDialog& d) {
        chooseParameter(columns(d), QStringLiteral("exposure"));
        typeValues(columns(d), QStringLiteral("0, 30"));
    }) << false << QString() << QStringLiteral("30 is outside [-20, 20]")
                                         << QString() << QString();
    QTest::newRow("second axis none")
        << DialogEdit([=](WedgeAxesDialog& d) { chooseParameter(columns(d), QStringLiteral("none")); })
        << true << QString() << QString() << QStringLiteral("roughness=0,0.25,0.5,0.75,1") << QString();
    QTest::newRow("range fills the list") << DialogEdit([=](WedgeAxesDialog& d) {
        chooseParameter(rows(d), QStringLiteral("metallic"));
        chooseRange(rows(d), 0.0, 1.0, 3);
        QCOMPARE(rows(d)->valuesEdit()->text(), QStringLiteral("0, 0.5, 1"));
        QVERIFY(rows(d)->valuesEdit()->isReadOnly());
    }) << true << QStringLiteral("3 values")
                                          << QString() << QStringLiteral("metallic=0,0.5,1")
                                          << QStringLiteral("metallic=0,1");
    QTest::newRow("both axes from ranges") << DialogEdit([=](WedgeAxesDialog& d) {
        chooseRange(rows(d), 0.1, 0.3, 3);
        chooseParameter(columns(d), QStringLiteral("ior"));
        chooseRange(columns(d), 1.0, 2.0, 5);
    }) << true << QString() << QString() << QStringLiteral("roughness=0.1,0.2,0.3")
                                           << QStringLiteral("ior=1,1.25,1.5,1.75,2");
    QTest::newRow("range clamped to the parameter's") << DialogEdit([=](WedgeAxesDialog& d) {
        chooseRange(rows(d), 0.0, 5.0, 2); // roughness stops at 1
    }) << true << QString() << QString() << QStringLiteral("roughness=0,1")
                                                      << QStringLiteral("metallic=0,1");
    QTest::newRow("env: a list only") << DialogEdit([=](WedgeAxesDialog& d) {
        chooseParameter(columns(d), QStringLiteral("env"));
        QVERIFY(!columns(d)->rangeMode()->isEnabled());
        typeValues(columns(d), QStringLiteral("studio, sky"));
    }) << true << QString() << QStringLiteral("2 values")
                                      << QStringLiteral("roughness=0,0.25,0.5,0.75,1")
                                      << QStringLiteral("env=studio,sky");
    QTest::newRow("back from invalid to valid") << DialogEdit([=](WedgeAxesDialog& d) {
        typeValues(rows(d), QStringLiteral("0, 2"));
        QVERIFY(!d.okButton()->isEnabled());
        typeValues(rows(d), QStringLiteral("0, 0.75"));
    }) << true << QStringLiteral("2 values") << QString()
                                                << QStringLiteral("roughness=0,0.75")
                                                << QStringLiteral("metallic=0,1");
}

void CompareWindowUiTest::wedgeAxesDialog()
{
    QFETCH(DialogEdit, edit);
    QFETCH(bool, ok);
    QFETCH(QString, rowsMessage);
    QFETCH(QString, columnsMessage);
    QFETCH(QString, rows);
    QFETCH(QString, columns);

    Project project = baseProject();
    project.compare.mode = CompareMode::Wedge;
    setProject(project);
    WedgeAxesDialog dialog(m_document->project(), m_window);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    QCOMPARE(dialog.rows()->parameterCombo()->currentText(), QStringLiteral("roughness"));
    QCOMPARE(dialog.rows()->valuesEdit()->text(), QStringLiteral("0, 0.25, 0.5, 0.75, 1"));
    QCOMPARE(dialog.columns()->parameterCombo()->currentText(), QStringLiteral("metallic"));
    QCOMPARE(dialog.columns()->parameterCombo()->itemText(0), QStringLiteral("none"));
    QCOMPARE(dialog.rows()->parameterCombo()->findText(QStringLiteral("none")), -1);
    // Every parameter WedgeAxis accepts is offered.
    QCOMPARE(dialog.rows()->parameterCombo()->count(), int(wedgeParameters().size()));
    edit(dialog);
    QCOMPARE(dialog.okButton()->isEnabled(), ok);
    QString tag = QString::fromLatin1(QTest::currentDataTag());
    tag.replace(QRegularExpression(QStringLiteral("[^a-z0-9]+")), QStringLiteral("-"));
    QVERIFY(dialog.grab().save(outputDir() + QStringLiteral("/compare-wedge-axes-%1.png").arg(tag)));
    if (!rowsMessage.isEmpty())
        QVERIFY2(dialog.rows()->messageLabel()->text().contains(rowsMessage),
            qPrintable(dialog.rows()->messageLabel()->text()));
    if (!columnsMessage.isEmpty())
        QVERIFY2(dialog.columns()->messageLabel()->text().contains(columnsMessage),
            qPrintable(dialog.columns()->messageLabel()->text()));
    if (!ok) {
        QVERIFY(!dialog.rows()->isValid() || !dialog.columns()->isValid());
        return;
    }
    const int steps = m_document->undoStack()->index();
    QString error;
    QVERIFY2(dialog.applyTo(*m_controller, &error), qPrintable(error));
    const WedgeLayout& wedge = m_document->project().compare.wedge;
    QCOMPARE(QString::fromStdString(wedge.rows.toString()), rows);
    QCOMPARE(wedge.columns ? QString::fromStdString(wedge.columns->toString()) : QString(), columns);
    if (wedge != project.compare.wedge) {
        QCOMPARE(m_document->undoStack()->index(), steps + 1);
        QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Wedge Axes"));
        m_document->undoStack()->undo();
        QCOMPARE(m_document->project().compare.wedge, project.compare.wedge);
    }
}

// An axis that changes nothing in any cell is named under the editors (as `facet sheet` warns
// of it), and the dialog still accepts it; an axis that the other one makes count is not named.
// The project's material has no coat and no normal map.
void CompareWindowUiTest::wedgeAxesDialogNamesAnAxisThatSweepsNothing_data()
{
    QTest::addColumn<DialogEdit>("edit");
    QTest::addColumn<QString>("warning"); // what the warning says, or empty: none shown
    const auto rows = [](WedgeAxesDialog& d) { return d.rows(); };
    const auto columns = [](WedgeAxesDialog& d) { return d.columns(); };
    QTest::newRow("roughness x metallic") << DialogEdit([](WedgeAxesDialog&) {}) << QString();
    QTest::newRow("coat roughness without a coat")
        << DialogEdit([=](WedgeAxesDialog& d) {
               chooseParameter(rows(d), QStringLiteral("clearcoatRoughness"));
               typeValues(rows(d), QStringLiteral("0, 0.5"));
           })
        << QStringLiteral(
               "Rows: clearcoatRoughness sweeps nothing: clearcoatRoughness shapes the clear coat, "
               "and the material has none (clearcoat 0)");
    QTest::newRow("coat roughness across a coat axis") << DialogEdit([=](WedgeAxesDialog& d) {
        chooseParameter(rows(d), QStringLiteral("clearcoatRoughness"));
        typeValues(rows(d), QStringLiteral("0, 0.5"));
        chooseParameter(columns(d), QStringLiteral("clearcoat"));
        typeValues(columns(d), QStringLiteral("0, 1"));
    }) << QString();
    QTest::newRow("normal strength without a normal map") << DialogEdit([=](WedgeAxesDialog& d) {
        chooseParameter(columns(d), QStringLiteral("normal"));
        typeValues(columns(d), QStringLiteral("0, 1"));
    }) << QStringLiteral("Columns: normal sweeps nothing: normal strength scales a normal map");
}

void CompareWindowUiTest::wedgeAxesDialogNamesAnAxisThatSweepsNothing()
{
    QFETCH(DialogEdit, edit);
    QFETCH(QString, warning);
    Project project = baseProject();
    project.compare.mode = CompareMode::Wedge;
    setProject(project);
    WedgeAxesDialog dialog(m_document->project(), m_window);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    edit(dialog);
    QVERIFY(dialog.okButton()->isEnabled());
    QCOMPARE(dialog.warningLabel()->isVisibleTo(&dialog), !warning.isEmpty());
    if (!warning.isEmpty())
        QVERIFY2(dialog.warningLabel()->text().contains(warning), qPrintable(dialog.warningLabel()->text()));
}

void CompareWindowUiTest::wedgeAxesFromTheCellMenu()
{
    Project project = baseProject();
    project.compare.mode = CompareMode::Wedge;
    setProject(project);
    QMenu menu;
    CompareMenus::fill(menu, *m_controller, m_document->project(), m_view->cells().front(), {}, m_window);
    QAction* axes = menu.findChild<QAction*>(QStringLiteral("wedgeAxesAction"));
    QVERIFY(axes);
    bool sawDialog = false;
    // Should the dialog not come (or not take the values), it is closed rather than left waiting.
    QTimer::singleShot(20000, this, [] {
        if (QWidget* modal = QApplication::activeModalWidget())
            modal->close();
    });
    QTimer::singleShot(0, this, [&sawDialog] {
        auto* dialog = qobject_cast<WedgeAxesDialog*>(QApplication::activeModalWidget());
        if (!dialog)
            return;
        sawDialog = true;
        chooseParameter(dialog->rows(), QStringLiteral("ior"));
        chooseRange(dialog->rows(), 1.2, 1.8, 4);
        chooseParameter(dialog->columns(), QStringLiteral("none"));
        dialog->okButton()->click();
    });
    const int steps = m_document->undoStack()->index();
    axes->trigger(); // exec()s the dialog until the timer above accepts it
    QVERIFY(sawDialog);
    QCOMPARE(m_document->undoStack()->index(), steps + 1);
    QCOMPARE(QString::fromStdString(m_document->project().compare.wedge.rows.toString()),
        QStringLiteral("ior=1.2,1.4,1.6,1.8"));
    QVERIFY(!m_document->project().compare.wedge.columns);
    QVERIFY(waitForSettledFrame());
    QCOMPARE(m_view->axisLabels().size(), 4);
}

QTEST_MAIN(CompareWindowUiTest)
#include "CompareWindowUiTest.moc"
