#pragma once
// What the status bar (and the Environment dock's lighting status) says about the views follows
// the one the central area shows (not a widget): the single view (ViewportWidget) or the Compare
// view (ui/compare/CompareView.h), which share a QStackedWidget.
//
// - Lighting progress: each view's "Preparing the lighting of …" and "Lighting of … ready" go to
//   the status bar and the dock while that view is shown. A hidden view's pending message is
//   taken off the bar when the other view is shown (a hidden QOpenGLWidget never draws, so it
//   would never be replaced) and shown again when its view comes back with the work still to do.
// - Frame statistics: the permanent label beside the GL summary describes the shown view's last
//   frame, in the same place and style: "1280×720 · 112 ms" for the single view,
//   compareSummary() for the Compare view; a failed frame says "frame failed" and puts the
//   reason in the status bar.

#include <QElapsedTimer>
#include <QObject>
#include <QString>

class QLabel;
class QStackedWidget;
class QStatusBar;

namespace facet {

class CompareView;
class EnvironmentDock;
class SceneController;
class ViewportWidget;
struct CompareFrameStats;

class ViewStatus : public QObject {
    Q_OBJECT
public:
    // `central` shows `single` at index 0 and `compare` at index 1 (ui/compare/CompareActions.h).
    ViewStatus(QStatusBar* bar, QLabel* frameStats, QStackedWidget* central, ViewportWidget* single,
        SceneController* scene, CompareView* compare, EnvironmentDock* dock, QObject* parent);

    // "4 cells, 1 drawn · 35 ms" (an example; + " (preview)" when reduced, + " · IBL 3 computed,
    // 1 from disk" once this view has prepared lighting); compareDetails(): the tooltip, with the
    // cells kept and the milliseconds spent on lighting.
    static QString compareSummary(const CompareFrameStats& stats);

    // A file was opened, imported or saved and the status bar says what came of it
    // (ProjectFileController::statusMessage): for kUserMessageHoldMs lighting progress does not
    // replace it (issue 30: "Opened barrel.glb (...)" was overwritten at once by "Preparing the
    // lighting"); the Environment dock still shows the lighting.
    void noteUserMessage();
    static constexpr int kUserMessageHoldMs = 5000;
    static QString compareDetails(const CompareFrameStats& stats);

    // A message about what the Compare view is about to show (Compare Selected Environments using
    // the first 9): shown now, and kept in the lighting messages of the Compare view's next
    // frames, which would otherwise replace it at once ("Lighting of 9 environments ready (160
    // ms) — NOTE"), until a frame with nothing left to load.
    void showCompareNote(const QString& text);

private:
    bool compareShown() const;
    QString withNote(const QString& text) const;
    void onViewSwitched();
    void onSingleFrame();
    void onCompareFrame();
    // The lighting status of the shown view, to the bar and the dock.
    void showLighting(const QString& text, bool busy);

    QStatusBar* m_bar;
    QElapsedTimer m_userMessage; // since the last message of the artist's action (invalid: none)
    // Lighting news on the bar, unless an action's message is fresh.
    void showNews(const QString& text);
    QLabel* m_frameStats;
    QStackedWidget* m_central;
    ViewportWidget* m_single;
    SceneController* m_scene;
    CompareView* m_compare;
    EnvironmentDock* m_dock;
    // Each view's "Preparing the lighting of …" while it is not ready, else empty.
    QString m_singlePending;
    QString m_comparePending;
    QString m_compareNote;
};

} // namespace facet
