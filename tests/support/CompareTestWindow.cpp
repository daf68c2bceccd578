#include "CompareTestWindow.h"

#include "ui/MainWindow.h"
#include "ui/compare/CompareController.h"
#include "ui/compare/CompareView.h"
#include "ui/document/Document.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QStackedWidget>
#include <QtTest/QTest>

namespace facet::test {

CompareTestWindow::CompareTestWindow() = default;
CompareTestWindow::~CompareTestWindow() = default;

bool CompareTestWindow::open(const QString& recoveryDirectory)
{
    QCoreApplication::setOrganizationName(QStringLiteral("FacetTests"));
    m_window = std::make_unique<MainWindow>(nullptr, recoveryDirectory);
    m_document = m_window->document();
    m_view = m_window->compareView();
    m_controller = m_window->compareController();
    if (!m_view || !m_controller || !m_window->compareActions())
        return false;
    m_view->setUseDiskCache(false); // counts precomputes, never touches the user's cache
    m_window->resize(1100, 760);
    m_window->show();
    return QTest::qWaitForWindowExposed(m_window.get());
}

void CompareTestWindow::close()
{
    m_window.reset();
    m_document = nullptr;
    m_view = nullptr;
    m_controller = nullptr;
}

Project CompareTestWindow::baseProject()
{
    Project project = Project::defaultProject();
    project.environment.quality = IblQuality::Draft;
    project.view.msaaSamples = 1;
    project.compare = CompareLayout::defaultFor(project);
    return project;
}

bool CompareTestWindow::setProject(const Project& project)
{
    m_document->setProject(project, QStringLiteral("test"));
    m_document->setCamera(project.camera);
    return waitForSettledFrame();
}

bool CompareTestWindow::waitForSettledFrame(int timeoutMs)
{
    if (static_cast<QStackedWidget*>(m_window->centralWidget())->currentIndex() == 0)
        return true; // the single view
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < timeoutMs) {
        QSignalSpy rendered(m_view, &CompareView::frameRendered);
        m_view->update();
        if (!rendered.wait(5000))
            continue;
        if (!m_view->isPreviewing() && !m_view->isLoading() && !m_view->lastFrameStats().reduced
            && !m_view->isRefining() && m_view->lastError().isEmpty())
            return true;
        QTest::qWait(50);
    }
    qWarning("no settled frame: %s", qPrintable(m_view->lastError()));
    return false;
}

} // namespace facet::test
