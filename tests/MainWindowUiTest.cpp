// The main window: menus, the central viewport (a 4.1 core context), the GL version in the status
// bar; a viewport with no scene shows the empty grey. Needs a display (Xvfb via with-display.sh).
// ViewportUiTest checks what the viewport draws, ProjectFileUiTest the File menu's work.

#include "ui/MainWindow.h"
#include "ui/SurfaceFormat.h"
#include "ui/ViewportWidget.h"

#include "TestSupport.h"

#include <QAction>
#include <QApplication>
#include <QColor>
#include <QImage>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QOpenGLContext>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <cmath>
#include <memory>

using namespace facet;

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
            QStringLiteral("File"), QStringLiteral("Edit"), QStringLiteral("View"), QStringLiteral("Help")}));
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

QTEST_MAIN(MainWindowUiTest)
#include "MainWindowUiTest.moc"
