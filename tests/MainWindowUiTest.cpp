// The main window of this stage: a menu bar, the empty viewport (a 4.1 core context cleared to
// dark grey) and the GL version in the status bar. Needs a display (Xvfb via with-display.sh).

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
#include <QStatusBar>
#include <QtTest/QTest>

#include <cmath>
#include <memory>

using namespace facet;

class MainWindowUiTest : public QObject {
    Q_OBJECT
public:
    // QTEST_MAIN calls this before it constructs the QApplication, as facet's main() does.
    static void initMain() { installViewportSurfaceFormat(); }

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
    std::unique_ptr<MainWindow> m_window;
};

void MainWindowUiTest::initTestCase()
{
    m_window = std::make_unique<MainWindow>();
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
    QCOMPARE(m_window->windowTitle(), QStringLiteral("Facet"));
    auto* viewport = qobject_cast<ViewportWidget*>(m_window->centralWidget());
    QVERIFY(viewport);
    QCOMPARE(viewport, m_window->viewport());
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
    QCOMPARE(titles, (QStringList {QStringLiteral("File"), QStringLiteral("View"), QStringLiteral("Help")}));
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
    const QImage window = m_window->grab().toImage().convertToFormat(QImage::Format_RGB32);
    const QString path = test::outputDir() + QStringLiteral("/MainWindowUiTest-empty-viewport.png");
    QVERIFY2(window.save(path), qPrintable(path));

    ViewportWidget* viewport = m_window->viewport();
    const qreal scale = window.devicePixelRatio();
    const QRect area(viewport->mapTo(m_window.get(), QPoint(0, 0)) * scale, viewport->size() * scale);
    QVERIFY(window.rect().contains(area));
    // 0.18 in an 8-bit framebuffer is 45.9: 46, one code value either way for the driver's rounding.
    const int expected = int(std::lround(ViewportWidget::kClearGrey * 255.0f));
    const int tolerance = 1;
    int checked = 0;
    for (int y = area.top() + 1; y < area.bottom(); y += 7)
        for (int x = area.left() + 1; x < area.right(); x += 7) {
            const QRgb pixel = window.pixel(x, y);
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

    // The viewport's own framebuffer agrees.
    const QImage frame = viewport->grabFramebuffer();
    QVERIFY(!frame.isNull());
    const QRgb centre = frame.pixel(frame.width() / 2, frame.height() / 2);
    QVERIFY(std::abs(qRed(centre) - expected) <= tolerance);
}

QTEST_MAIN(MainWindowUiTest)
#include "MainWindowUiTest.moc"
