#include "ui/MainWindow.h"

#include "ui/ViewportWidget.h"

#include <QAction>
#include <QApplication>
#include <QDebug>
#include <QKeySequence>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>

namespace facet {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent)
    , m_viewport(new ViewportWidget(this))
    , m_glStatusLabel(new QLabel(tr("Initialising OpenGL…"), this))
{
    setWindowTitle(QStringLiteral("Facet"));
    setCentralWidget(m_viewport);
    m_glStatusLabel->setObjectName(QStringLiteral("glStatusLabel"));
    statusBar()->addPermanentWidget(m_glStatusLabel);
    createMenus();
    connect(m_viewport, &ViewportWidget::glInitialized, this, &MainWindow::onViewportGLInitialized);
    resize(1200, 800);
}

void MainWindow::createMenus()
{
    QMenu* fileMenu = menuBar()->addMenu(tr("&File"));
    fileMenu->setObjectName(QStringLiteral("fileMenu"));
    QAction* quitAction = fileMenu->addAction(tr("&Quit"), this, &QWidget::close);
    quitAction->setObjectName(QStringLiteral("quitAction"));
    quitAction->setShortcut(QKeySequence::Quit);
    quitAction->setMenuRole(QAction::QuitRole);

    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    viewMenu->setObjectName(QStringLiteral("viewMenu"));
    QAction* fullScreenAction = viewMenu->addAction(tr("&Full Screen"));
    fullScreenAction->setObjectName(QStringLiteral("fullScreenAction"));
    fullScreenAction->setCheckable(true);
    fullScreenAction->setShortcut(QKeySequence::FullScreen);
    connect(fullScreenAction, &QAction::toggled, this,
        [this](bool fullScreen) { setWindowState(windowState().setFlag(Qt::WindowFullScreen, fullScreen)); });

    QMenu* helpMenu = menuBar()->addMenu(tr("&Help"));
    helpMenu->setObjectName(QStringLiteral("helpMenu"));
    QAction* aboutAction = helpMenu->addAction(tr("&About Facet"), this, &MainWindow::showAbout);
    aboutAction->setObjectName(QStringLiteral("aboutAction"));
    aboutAction->setMenuRole(QAction::AboutRole);
    QAction* aboutQtAction = helpMenu->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
    aboutQtAction->setMenuRole(QAction::AboutQtRole);
}

void MainWindow::showStatusMessage(const QString& message)
{
    statusBar()->showMessage(message);
}

QString MainWindow::aboutText() const
{
    QString text = tr("<h3>Facet %1</h3><p>Authoring and previewing physically based materials.</p>")
                       .arg(QStringLiteral(FACET_VERSION));
    text += tr("<p>Qt %1</p>").arg(QString::fromLatin1(qVersion()));
    const GLInfo& gl = m_viewport->glInfo();
    if (gl.isValid()) {
        text += tr("<p>OpenGL %1<br>Renderer: %2<br>Vendor: %3</p>")
                    .arg(QString::fromStdString(gl.version).toHtmlEscaped(),
                        QString::fromStdString(gl.renderer).toHtmlEscaped(),
                        QString::fromStdString(gl.vendor).toHtmlEscaped());
    } else {
        text += tr("<p>OpenGL: not initialised yet</p>");
    }
    return text;
}

void MainWindow::showAbout()
{
    QMessageBox::about(this, tr("About Facet"), aboutText());
}

void MainWindow::onViewportGLInitialized()
{
    const GLInfo& gl = m_viewport->glInfo();
    const QString summary = QString::fromStdString(gl.summary());
    if (m_viewport->glProblem().isEmpty()) {
        m_glStatusLabel->setText(summary);
        return;
    }
    const QString problem = summary + QStringLiteral(" — ") + m_viewport->glProblem();
    m_glStatusLabel->setText(problem);
    qWarning().noquote() << "facet:" << problem;
}

} // namespace facet
