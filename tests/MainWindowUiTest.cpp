// The main window: menus, the central viewport (a 4.1 core context), the GL version in the status
// bar; a viewport with no scene shows the empty grey; the dock layout gives the view the room, and
// a dock's width holds when its content changes. Needs a display (Xvfb via with-display.sh).
// ViewportUiTest checks what the viewport draws, ProjectFileUiTest the File menu's work.

#include "core/project/Project.h"
#include "ui/MainWindow.h"
#include "ui/docks/EnvironmentDock.h"
#include "ui/docks/LightsDock.h"
#include "ui/docks/MaterialsDock.h"
#include "ui/docks/TextureMapsDock.h"
#include "ui/document/Document.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportWidget.h"

#include "TestSupport.h"

#include <QAction>
#include <QApplication>
#include <QColor>
#include <QDockWidget>
#include <QImage>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QOpenGLContext>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <cmath>
#include <memory>

using namespace facet;

namespace {

// Where a window's width goes: the central view and the docks docked beside it.
struct Room {
    int window = 0;
    int central = 0;
    int docks = 0; // from the leftmost docked dock's left edge to the rightmost one's right edge
    QString layout; // each visible docked dock's x and width, for failure messages
};

Room measureRoom(const MainWindow& window)
{
    Room room {window.width(), window.centralWidget()->width(), 0, {}};
    QRect docks;
    for (const QDockWidget* dock : window.findChildren<QDockWidget*>()) {
        // A tab that is not raised is moved out of the window, not hidden.
        if (!dock->isVisible() || dock->isFloating() || !window.rect().intersects(dock->geometry()))
            continue;
        docks |= dock->geometry();
        room.layout += QStringLiteral(" %1 x=%2 w=%3 h=%4")
                           .arg(dock->objectName())
                           .arg(dock->x())
                           .arg(dock->width())
                           .arg(dock->height());
    }
    room.docks = docks.width();
    return room;
}

QString describe(const Room& room)
{
    return QStringLiteral("window %1, central %2, docks %3:%4")
        .arg(room.window)
        .arg(room.central)
        .arg(room.docks)
        .arg(room.layout);
}

// Layout requests are posted events: let the main window's layout run them.
void settle()
{
    for (int i = 0; i < 5; ++i) {
        QCoreApplication::processEvents();
        QTest::qWait(20);
    }
}

// A window of `size` on the default layout (no saved one, unless `keepSavedLayout`), shown and
// drawn once.
std::unique_ptr<MainWindow> shownWindow(
    const QString& recoveryDirectory, QSize size, bool keepSavedLayout = false)
{
    if (!keepSavedLayout)
        QSettings().remove(QStringLiteral("window")); // another row's saved layout must not apply
    auto window = std::make_unique<MainWindow>(nullptr, recoveryDirectory);
    window->resize(size);
    QSignalSpy swapped(window->viewport(), &QOpenGLWidget::frameSwapped);
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get()) || !(swapped.count() > 0 || swapped.wait(20000)))
        return nullptr;
    settle();
    return window;
}

// Whether the dock's content fits its width (each dock's content is in a DockScrollArea:
// MainWindow::addDock); says what it needs when it does not.
bool contentFits(const QDockWidget& dock)
{
    auto* scroll = qobject_cast<QScrollArea*>(dock.widget());
    if (!scroll || !scroll->widget()) {
        qWarning("%s: no scroll area", qPrintable(dock.objectName()));
        return false;
    }
    const int needed = scroll->widget()->minimumSizeHint().width();
    const int available = scroll->viewport()->width();
    const bool fits = needed <= available && !scroll->horizontalScrollBar()->isVisible();
    if (!fits)
        qWarning("%s: the content needs %d pixels of width, has %d", qPrintable(dock.objectName()), needed,
            available);
    return fits;
}

// A change of a dock's content, and the dock that shows it (raised before the change).
struct ContentChange {
    const char* name;
    const char* dock;
    void (*apply)(MainWindow& window, const QString& directory);
};

void addLights(MainWindow& window, int count)
{
    for (int i = 0; i < count; ++i)
        window.lightsDock()->addLight(LightType(i % 3));
    QCOMPARE(int(window.document()->project().lights.size()), count);
}

// 200 characters, one word: nothing to wrap at.
QString longName(const QString& suffix = {})
{
    return QString(200 - suffix.size(), QLatin1Char('x')) + suffix;
}

// A second material, current, named with 200 characters: in the Materials list, the parts'
// combo boxes, the Texture Maps dock's "Material: … (2 of 2)" and the Material dock's name field.
void addLongNamedMaterial(MainWindow& window, const QString&)
{
    Project project = window.document()->project();
    project.materials.push_back(project.material());
    project.materials.back().name = longName().toStdString();
    project.currentMaterial = int(project.materials.size()) - 1;
    window.document()->setProject(project, QStringLiteral("Add Material"));
}

const ContentChange kContentChanges[] = {
    {"a light", "lightsDock", [](MainWindow& window, const QString&) { addLights(window, 1); }},
    {"eight lights", "lightsDock", [](MainWindow& window, const QString&) { addLights(window, 8); }},
    {"a map with a 200-character file name", "textureMapsDock",
        [](MainWindow& window, const QString& directory) {
            const QString path = directory + QLatin1Char('/') + longName(QStringLiteral("_basecolor.png"));
            QImage image(8, 8, QImage::Format_RGB32);
            image.fill(Qt::red);
            QVERIFY2(image.save(path), qPrintable(path));
            const QString message = window.textureMapsDock()->assignFiles({path});
            QVERIFY2(message.contains(QStringLiteral("Base Colour")), qPrintable(message));
            QTRY_COMPARE_WITH_TIMEOUT(window.textureMapsDock()->pendingThumbnails(), 0, 20000);
        }},
    {"a material with a 200-character name", "materialsDock", addLongNamedMaterial},
    {"the long-named material in the Texture Maps dock", "textureMapsDock", addLongNamedMaterial},
    {"an environment with a 200-character file name", "environmentDock",
        [](MainWindow& window, const QString& directory) {
            const QString path = directory + QLatin1Char('/') + longName(QStringLiteral(".exr"));
            QVERIFY(test::writeConstantExr(path, 0.5f));
            QSignalSpy ready(window.viewport(), &ViewportWidget::iblPrecomputeFinished);
            QVERIFY(window.environmentDock()->chooseEnvironment(path));
            QVERIFY(ready.count() > 0 || ready.wait(30000));
        }},
};

const char* const kDockNames[]
    = {"materialsDock", "textureMapsDock", "materialDock", "environmentDock", "lightsDock", "viewDock"};

} // namespace

class MainWindowUiTest : public QObject {
    Q_OBJECT
public:
    // QTEST_MAIN calls this before it constructs the QApplication, as facet's main() does.
    static void initMain()
    {
        QStandardPaths::setTestModeEnabled(true);
        installViewportSurfaceFormat();
    }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void titleAndCentralViewport();
    void viewportContextIsCore41();
    void menusExist();
    void statusBarShowsGLVersion();
    void aboutNamesVersionAndGL();
    void emptyViewportShowsClearColour();
    void defaultLayoutGivesTheViewTheRoom_data();
    void defaultLayoutGivesTheViewTheRoom();
    void dockWidthHoldsWhenContentChanges_data();
    void dockWidthHoldsWhenContentChanges();
    void savedLayout_data();
    void savedLayout();

private:
    QTemporaryDir m_recovery;
    std::unique_ptr<MainWindow> m_window;
};

void MainWindowUiTest::initTestCase()
{
    QCoreApplication::setOrganizationName(QStringLiteral("FacetTests"));
    m_window = std::make_unique<MainWindow>(nullptr, m_recovery.path());
    QSignalSpy initialized(m_window->viewport(), &ViewportWidget::glInitialized);
    QSignalSpy swapped(m_window->viewport(), &QOpenGLWidget::frameSwapped);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    // llvmpipe under Xvfb takes a moment for the first context and frame.
    QVERIFY(initialized.count() > 0 || initialized.wait(20000));
    QVERIFY(swapped.count() > 0 || swapped.wait(20000));
}

void MainWindowUiTest::cleanupTestCase()
{
    m_window.reset();
}

void MainWindowUiTest::titleAndCentralViewport()
{
    QCOMPARE(m_window->windowTitle(), QStringLiteral("Untitled[*] — Facet"));
    QVERIFY(!m_window->isWindowModified());
    auto* viewport = m_window->viewport();
    QVERIFY(viewport);
    QVERIFY(m_window->centralWidget()->isAncestorOf(viewport)); // the single view of the central stack
    QVERIFY(viewport->isVisible());
}

void MainWindowUiTest::viewportContextIsCore41()
{
    ViewportWidget* viewport = m_window->viewport();
    QVERIFY(viewport->isValid());
    const QSurfaceFormat format = viewport->context()->format();
    QVERIFY2(format.version() >= qMakePair(4, 1),
        qPrintable(QStringLiteral("%1.%2").arg(format.majorVersion()).arg(format.minorVersion())));
    QCOMPARE(format.profile(), QSurfaceFormat::CoreProfile);

    // What render/ read through libepoxy inside Qt's context agrees with Qt.
    const GLInfo& info = viewport->glInfo();
    QVERIFY(info.isValid());
    QVERIFY(info.coreProfile);
    QVERIFY(info.atLeast(4, 1));
    QCOMPARE(info.major, format.majorVersion());
    QCOMPARE(info.minor, format.minorVersion());
    QVERIFY(!info.renderer.empty());
    QVERIFY2(viewport->glProblem().isEmpty(), qPrintable(viewport->glProblem()));
    qInfo("viewport: %s", info.summary().c_str());
}

void MainWindowUiTest::menusExist()
{
    const QStringList titles = [this] {
        QStringList result;
        for (QAction* action : m_window->menuBar()->actions())
            result.append(action->text().remove(QLatin1Char('&')));
        return result;
    }();
    QCOMPARE(titles,
        (QStringList {
            QStringLiteral("File"), QStringLiteral("Edit"), QStringLiteral("View"), QStringLiteral("Compare"),
            QStringLiteral("Help")}));
    QVERIFY(m_window->findChild<QMenu*>(QStringLiteral("editMenu")));
    for (const char* name :
        {"newAction", "openAction", "saveAction", "saveAsAction", "undoAction", "redoAction",
            "resetLayoutAction", "turntableAction", "frameAction", "resetCameraAction", "flyModeAction"})
        QVERIFY2(m_window->findChild<QAction*>(QLatin1String(name)), name);
    QVERIFY(m_window->findChild<QMenu*>(QStringLiteral("recentMenu")));
    QVERIFY(m_window->findChild<QMenu*>(QStringLiteral("fileMenu")));
    QVERIFY(m_window->findChild<QMenu*>(QStringLiteral("viewMenu")));
    QVERIFY(m_window->findChild<QMenu*>(QStringLiteral("helpMenu")));
    auto* quit = m_window->findChild<QAction*>(QStringLiteral("quitAction"));
    QVERIFY(quit);
    QCOMPARE(quit->shortcut(), QKeySequence(QKeySequence::Quit));
    QVERIFY(m_window->findChild<QAction*>(QStringLiteral("aboutAction")));
    QVERIFY(m_window->findChild<QAction*>(QStringLiteral("fullScreenAction")));
}

void MainWindowUiTest::statusBarShowsGLVersion()
{
    auto* label = m_window->statusBar()->findChild<QLabel*>(QStringLiteral("glStatusLabel"));
    QVERIFY(label);
    const QString expected
        = QStringLiteral("OpenGL ") + QString::fromStdString(m_window->viewport()->glInfo().version);
    QVERIFY2(label->text().startsWith(expected), qPrintable(label->text()));
    QVERIFY(label->isVisible());
}

void MainWindowUiTest::aboutNamesVersionAndGL()
{
    const QString text = m_window->aboutText();
    QVERIFY2(text.contains(QStringLiteral("Facet " FACET_VERSION)), qPrintable(text));
    const GLInfo& info = m_window->viewport()->glInfo();
    QVERIFY2(text.contains(QString::fromStdString(info.version).toHtmlEscaped()), qPrintable(text));
    QVERIFY2(text.contains(QString::fromStdString(info.renderer).toHtmlEscaped()), qPrintable(text));
}

void MainWindowUiTest::emptyViewportShowsClearColour()
{
    // A viewport with no scene (the window's has one) shows the empty grey.
    ViewportWidget viewport;
    viewport.resize(320, 240);
    QSignalSpy swapped(&viewport, &QOpenGLWidget::frameSwapped);
    viewport.show();
    QVERIFY(QTest::qWaitForWindowExposed(&viewport));
    QVERIFY(swapped.count() > 0 || swapped.wait(20000));
    const QImage frame = viewport.grabFramebuffer().convertToFormat(QImage::Format_RGB32);
    QVERIFY(!frame.isNull());
    const QString path = test::outputDir() + QStringLiteral("/MainWindowUiTest-empty-viewport.png");
    QVERIFY2(frame.save(path), qPrintable(path));
    // 0.18 in an 8-bit framebuffer is 45.9: 46, one code value either way for the driver's rounding.
    const int expected = int(std::lround(ViewportWidget::kClearGrey * 255.0f));
    const int tolerance = 1;
    int checked = 0;
    for (int y = 1; y < frame.height() - 1; y += 7)
        for (int x = 1; x < frame.width() - 1; x += 7) {
            const QRgb pixel = frame.pixel(x, y);
            for (const int channel : {qRed(pixel), qGreen(pixel), qBlue(pixel)})
                QVERIFY2(std::abs(channel - expected) <= tolerance,
                    qPrintable(QStringLiteral("pixel (%1, %2) is %3, expected grey %4 (saved %5)")
                                   .arg(x)
                                   .arg(y)
                                   .arg(QColor(pixel).name())
                                   .arg(expected)
                                   .arg(path)));
            ++checked;
        }
    QVERIFY(checked > 100);
    QCOMPARE(viewport.frameCount(), std::uint64_t(0)); // nothing was rendered, only cleared
}

void MainWindowUiTest::defaultLayoutGivesTheViewTheRoom_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addColumn<bool>("resetAfterResize");
    QTest::newRow("1200x800, the default") << QSize(1200, 800) << false;
    QTest::newRow("1600x1000") << QSize(1600, 1000) << false;
    QTest::newRow("1920x1080") << QSize(1920, 1080) << false;
    // View > Reset Layout in a window the user made larger: a quarter of that window.
    QTest::newRow("1920x1080, Reset Layout after resizing") << QSize(1920, 1080) << true;
}

void MainWindowUiTest::defaultLayoutGivesTheViewTheRoom()
{
    QFETCH(QSize, size);
    QFETCH(bool, resetAfterResize);
    std::unique_ptr<MainWindow> window
        = shownWindow(m_recovery.path(), resetAfterResize ? QSize(1200, 800) : size);
    QVERIFY(window);
    if (resetAfterResize) {
        window->resize(size);
        settle();
        window->resetLayout();
        settle();
    }
    QCOMPARE(window->size(), size); // the docks' minimum sizes do not make the window larger
    const Room room = measureRoom(*window);
    qInfo("%s", qPrintable(describe(room)));
    // Every dock docked in one column on the right.
    for (QDockWidget* dock : window->findChildren<QDockWidget*>()) {
        QVERIFY2(!dock->isFloating(), qPrintable(dock->objectName()));
        QCOMPARE(window->dockWidgetArea(dock), Qt::RightDockWidgetArea);
    }
    QVERIFY2(room.central >= room.window * 70 / 100, qPrintable(describe(room)));
    // Each dock's content fits the column's width: nothing to scroll sideways, nothing cut (a dock
    // hidden by default, as Values, shown as its menu action shows it).
    for (QDockWidget* dock : window->findChildren<QDockWidget*>()) {
        dock->show();
        dock->raise();
        settle();
        QVERIFY2(contentFits(*dock), qPrintable(dock->objectName()));
    }
    // About a quarter: 22% to 28% of the width.
    QVERIFY2(room.docks >= room.window * 22 / 100 && room.docks <= room.window * 28 / 100,
        qPrintable(describe(room)));
}

void MainWindowUiTest::dockWidthHoldsWhenContentChanges_data()
{
    QTest::addColumn<int>("change");
    for (int i = 0; i < int(std::size(kContentChanges)); ++i)
        QTest::newRow(kContentChanges[i].name) << i;
    // Switching tabs: a row per dock, raised from the default's raised tab (rows -1, -2, ...).
    for (int i = 0; i < int(std::size(kDockNames)); ++i)
        QTest::addRow("%s raised", kDockNames[i]) << -1 - i;
}

void MainWindowUiTest::dockWidthHoldsWhenContentChanges()
{
    QFETCH(int, change);
    QTemporaryDir directory;
    QVERIFY(directory.isValid());
    std::unique_ptr<MainWindow> window = shownWindow(m_recovery.path(), QSize(1200, 800));
    QVERIFY(window);
    const char* dockName = change >= 0 ? kContentChanges[change].dock : kDockNames[-1 - change];
    auto* dock = window->findChild<QDockWidget*>(QLatin1String(dockName));
    QVERIFY2(dock, dockName);
    if (change >= 0) {
        dock->raise();
        settle();
    }
    const Room before = measureRoom(*window);
    if (change >= 0) {
        kContentChanges[change].apply(*window, directory.path());
        if (QTest::currentTestFailed())
            return;
    } else {
        dock->raise();
    }
    settle();
    const Room after = measureRoom(*window);
    qInfo("before: %s", qPrintable(describe(before)));
    qInfo("after:  %s", qPrintable(describe(after)));
    const QString grab = test::outputDir()
        + QStringLiteral("/MainWindowUiTest-%1.png")
              .arg(QString::fromLatin1(QTest::currentDataTag())
                       .replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9]+")), QStringLiteral("-")));
    QVERIFY2(window->grab().save(grab), qPrintable(grab));
    QCOMPARE(after.window, before.window);
    QCOMPARE(after.central, before.central);
    QCOMPARE(after.docks, before.docks);
    QVERIFY(contentFits(*dock));
    window->document()->newProject(); // nothing to ask about
}

void MainWindowUiTest::savedLayout_data()
{
    // What the last session left in QSettings: "window/layout" is QMainWindow::saveState(version).
    QTest::addColumn<int>("savedVersion"); // 0: this build's (written by closing a window)
    QTest::addColumn<bool>("garbage");
    QTest::addColumn<bool>("restored"); // the Lights dock the last session moved left comes back there
    QTest::newRow("saved by this version: restored") << 0 << false << true;
    // Version 2 was the layout with docks on both sides: replaced by the default, once.
    QTest::newRow("saved by version 2: the default") << 2 << false << false;
    QTest::newRow("unreadable: the default") << 0 << true << false;
}

void MainWindowUiTest::savedLayout()
{
    QFETCH(int, savedVersion);
    QFETCH(bool, garbage);
    QFETCH(bool, restored);
    const QString layoutKey = QStringLiteral("window/layout");
    {
        std::unique_ptr<MainWindow> last = shownWindow(m_recovery.path(), QSize(1200, 800));
        QVERIFY(last);
        last->addDockWidget(Qt::LeftDockWidgetArea, last->lightsDock());
        settle();
        QCOMPARE(last->dockWidgetArea(last->lightsDock()), Qt::LeftDockWidgetArea);
        QVERIFY(last->close()); // saves the layout
        if (savedVersion != 0)
            QSettings().setValue(layoutKey, last->saveState(savedVersion));
        if (garbage)
            QSettings().setValue(layoutKey, QByteArray("not a layout"));
    }
    std::unique_ptr<MainWindow> window = shownWindow(m_recovery.path(), QSize(1200, 800), true);
    QVERIFY(window);
    QCOMPARE(window->dockWidgetArea(window->lightsDock()),
        restored ? Qt::LeftDockWidgetArea : Qt::RightDockWidgetArea);
    const Room room = measureRoom(*window);
    if (!restored) {
        // The default in full: every dock on the right, the view three quarters of the window.
        for (QDockWidget* dock : window->findChildren<QDockWidget*>())
            QCOMPARE(window->dockWidgetArea(dock), Qt::RightDockWidgetArea);
        QVERIFY2(room.central >= room.window * 70 / 100, qPrintable(describe(room)));
    }
    // Closing saves this version's layout: the next start restores it, the old one is gone.
    QVERIFY(window->close());
    std::unique_ptr<MainWindow> next = shownWindow(m_recovery.path(), QSize(1200, 800), true);
    QVERIFY(next);
    QCOMPARE(next->dockWidgetArea(next->lightsDock()), window->dockWidgetArea(window->lightsDock()));
    QCOMPARE(measureRoom(*next).central, room.central);
}

QTEST_MAIN(MainWindowUiTest)
#include "MainWindowUiTest.moc"
