#include "ui/viewport/ViewStatus.h"

#include "ui/compare/CompareRenderer.h"
#include "ui/compare/CompareView.h"
#include "ui/docks/EnvironmentDock.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/widgets/WindowMessages.h"

#include <QDebug>
#include <QLabel>
#include <QStackedWidget>
#include <QStatusBar>

namespace facet {

ViewStatus::ViewStatus(QStatusBar* bar, QLabel* frameStats, QStackedWidget* central, ViewportWidget* single,
    SceneController* scene, CompareView* compare, EnvironmentDock* dock, QObject* parent)
    : QObject(parent)
    , m_bar(bar)
    , m_frameStats(frameStats)
    , m_central(central)
    , m_single(single)
    , m_scene(scene)
    , m_compare(compare)
    , m_dock(dock)
{
    // The single view. When the project's environment could not be loaded, the lighting drawn
    // is another one's: say so, never "ready".
    connect(m_single, &ViewportWidget::iblPrecomputeStarting, this, [this](const QString& name) {
        m_singlePending = WindowMessages::lightingPreparing(name);
        if (!compareShown())
            showLighting(m_singlePending, true);
    });
    connect(
        m_single, &ViewportWidget::iblPrecomputeProgress, this, [this](const QString& name, double fraction) {
            if (m_singlePending.isEmpty())
                return; // finished meanwhile
            m_singlePending = WindowMessages::lightingPreparing(name, fraction);
            if (!compareShown()) {
                showNews(m_singlePending);
                m_dock->showLightingProgress(m_singlePending, fraction);
            }
        });
    connect(m_single, &ViewportWidget::iblPrecomputeFinished, this, [this](const QString& name, double ms) {
        m_singlePending.clear();
        const QString& problem = m_scene->environmentProblem();
        const QString text = problem.isEmpty() ? WindowMessages::lightingReady(name, ms)
                                               : WindowMessages::environmentNotUsed(problem, name);
        if (!compareShown())
            showLighting(text, false);
    });
    connect(m_scene, &SceneController::environmentProblemChanged, this, [this](const QString& problem) {
        if (!problem.isEmpty())
            m_dock->showLightingStatus(
                WindowMessages::environmentNotUsed(problem, m_scene->environmentName()), false);
    });
    connect(m_single, &ViewportWidget::frameRendered, this, &ViewStatus::onSingleFrame);

    // The Compare view.
    connect(m_compare, &CompareView::lightingPreparing, this, [this](int environments) {
        m_comparePending = WindowMessages::lightingPreparing(environments);
        if (compareShown()) {
            showLighting(m_comparePending, true);
            if (!m_compareNote.isEmpty())
                showNews(withNote(m_comparePending));
        }
    });
    connect(m_compare, &CompareView::lightingReady, this, [this](int environments, double ms) {
        m_comparePending.clear();
        if (compareShown()) {
            const QString text = WindowMessages::lightingReady(environments, ms);
            showLighting(text, false);
            if (!m_compareNote.isEmpty())
                showNews(withNote(text));
        }
    });
    connect(m_compare, &CompareView::frameRendered, this, &ViewStatus::onCompareFrame);

    connect(m_central, &QStackedWidget::currentChanged, this, &ViewStatus::onViewSwitched);
}

void ViewStatus::showCompareNote(const QString& text)
{
    m_compareNote = text;
    m_bar->showMessage(text);
}

QString ViewStatus::withNote(const QString& text) const
{
    return m_compareNote.isEmpty() ? text : text + QStringLiteral(" — ") + m_compareNote;
}

bool ViewStatus::compareShown() const
{
    return m_central->currentWidget() == m_compare;
}

void ViewStatus::showLighting(const QString& text, bool busy)
{
    showNews(text);
    m_dock->showLightingStatus(text, busy);
}

void ViewStatus::noteUserMessage()
{
    m_userMessage.start();
}

void ViewStatus::showNews(const QString& text)
{
    if (m_userMessage.isValid() && m_userMessage.elapsed() < kUserMessageHoldMs)
        return;
    m_bar->showMessage(text);
}

void ViewStatus::onViewSwitched()
{
    const bool compare = compareShown();
    // The hidden view's pending message goes (it would stay until that view draws again); the
    // shown view's comes back if its work is still to do.
    const QString& hidden = compare ? m_singlePending : m_comparePending;
    const QString& shown = compare ? m_comparePending : m_singlePending;
    if (!hidden.isEmpty() && m_bar->currentMessage() == hidden)
        m_bar->clearMessage();
    if (!shown.isEmpty())
        showLighting(shown, true);
    else if (!hidden.isEmpty())
        m_dock->showLightingStatus(QString(), false);
    if (compare)
        onCompareFrame();
    else
        onSingleFrame();
}

void ViewStatus::onSingleFrame()
{
    if (compareShown())
        return;
    m_frameStats->setToolTip(QString());
    if (!m_single->lastError().isEmpty()) {
        m_frameStats->setText(tr("frame failed"));
        qWarning().noquote() << "facet:" << m_single->lastError();
        m_bar->showMessage(WindowMessages::fromCore(m_single->lastError()));
        return;
    }
    m_frameStats->setText(
        m_single->lastFrameStats().frameNumber > 0 ? m_single->lastFrameStats().summary() : QString());
}

void ViewStatus::onCompareFrame()
{
    if (!compareShown())
        return;
    if (!m_compare->isLoading())
        m_compareNote.clear(); // said with the last lighting message (or still on the bar)
    const CompareFrameStats& stats = m_compare->lastFrameStats();
    if (!m_compare->lastError().isEmpty()) {
        m_frameStats->setText(tr("frame failed"));
        m_frameStats->setToolTip(QString());
        qWarning().noquote() << "facet:" << m_compare->lastError();
        m_bar->showMessage(WindowMessages::fromCore(m_compare->lastError()));
        return;
    }
    m_frameStats->setText(stats.frameNumber > 0 ? compareSummary(stats) : QString());
    m_frameStats->setToolTip(stats.frameNumber > 0 ? compareDetails(stats) : QString());
}

QString ViewStatus::compareSummary(const CompareFrameStats& stats)
{
    // As short as the single view's "W×H · N ms": the status bar's message shares the line.
    QString text = tr("%1 cells, %2 drawn · %3 ms")
                       .arg(stats.cellsDrawn + stats.cellsKept)
                       .arg(stats.cellsDrawn)
                       .arg(stats.frameMs, 0, 'f', 0);
    if (stats.reduced)
        text += tr(" (preview)");
    if (stats.iblComputed > 0)
        text += tr(" · IBL %1 computed").arg(stats.iblComputed);
    if (stats.iblFromDisk > 0)
        text += tr(", %1 from disk").arg(stats.iblFromDisk);
    return text;
}

QString ViewStatus::compareDetails(const CompareFrameStats& stats)
{
    return tr("Compare view, frame %1: %2 cells drawn again, %3 kept as they were%4\n"
              "%5 ms to draw, tone-map and composite (GPU finished), %6 ms preparing lighting\n"
              "Lighting since the view started: %7 environments asked for, %8 precomputed, %9 from the disk "
              "cache")
        .arg(stats.frameNumber)
        .arg(stats.cellsDrawn)
        .arg(stats.cellsKept)
        .arg(stats.reduced ? tr(", at reduced resolution while interacting") : QString())
        .arg(stats.frameMs, 0, 'f', 1)
        .arg(stats.iblMs, 0, 'f', 1)
        .arg(stats.iblRequests)
        .arg(stats.iblComputed)
        .arg(stats.iblFromDisk);
}

} // namespace facet
