#pragma once
// The Compare menu and toolbar (not a widget): Single / Environment Grid / A-B / Wedge as one
// exclusive group that follows the project's compare mode (undo, open and promote included), and
// Swap A and B, and Compare Selected Environments (the Environment dock's selected entries become
// the environment grid's cells; also in the dock's library context menu); the central area shows the single
// view or the Compare view (a QStackedWidget) as the mode says. Choosing a mode is an undoable edit of the
// layout (CompareController::setMode).

#include "core/project/CompareLayout.h"
#include "ui/compare/CompareMenus.h"

#include <QObject>

class QAction;
class QActionGroup;
class QListWidget;
class QMenu;
class QStackedWidget;
class QToolBar;
class QWidget;

namespace facet {

class CompareController;
class Document;
class EnvironmentDock;

class CompareActions : public QObject {
    Q_OBJECT
public:
    // `central` holds the single view at index 0 and the Compare view at index 1; `parent`
    // (the window) parents the menu and the toolbar.
    CompareActions(
        Document* document, CompareController* controller, QStackedWidget* central, QWidget* parent);

    QMenu* menu() const { return m_menu; }
    QToolBar* toolBar() const { return m_toolBar; }
    QAction* modeAction(CompareMode mode) const;
    QAction* swapAction() const { return m_swap; }
    QAction* compareSelectedAction() const { return m_compareSelected; }
    // The error view's: Show Reference Noise, and the Error Scale menu (one checkable action per
    // ErrorCompare::kScaleChoices, its value in data()).
    QAction* showNoiseAction() const { return m_showNoise; }
    QMenu* errorScaleMenu() const { return m_errorScaleMenu; }

    // Wires Compare Selected Environments to `dock`'s library: enabled while at least
    // EnvironmentGrid::kMinCells entries are selected; also in the library's context menu.
    void setEnvironmentDock(EnvironmentDock* dock);
    // The dock's selected environments (EnvironmentDock::selectedSources, in selection order)
    // become the grid's cells and the mode the environment grid, one undo step
    // (CompareController::compareEnvironments). More than EnvironmentGrid::kMaxCells: the first
    // ones, and message() says so.
    void compareSelected();

    // The entries of the Environment dock's library (label, source) for the cells' menus.
    static EnvironmentChoices choicesOf(const QListWidget* library);

Q_SIGNALS:
    // For the status bar.
    void message(const QString& text);

private:
    void sync();
    void syncCompareSelected(int selectedCount);

    Document* m_document;
    CompareController* m_controller;
    EnvironmentDock* m_environmentDock = nullptr;
    QStackedWidget* m_central;
    QMenu* m_menu;
    QToolBar* m_toolBar;
    QActionGroup* m_modes;
    QAction* m_swap;
    QAction* m_compareSelected;
    QAction* m_showNoise;
    QMenu* m_errorScaleMenu;
    QActionGroup* m_errorScales;
};

} // namespace facet
