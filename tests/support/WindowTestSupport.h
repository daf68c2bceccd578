#pragma once
// Set-up the main-window tests share. Header only: the UI tests (which link facet_ui) include it;
// the support library links no widgets.

#include "ui/MainWindow.h"
#include "ui/document/Document.h"
#include "ui/document/ProjectFileController.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportWidget.h"

#include <QAbstractItemView>
#include <QComboBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QMessageBox>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QUndoStack>
#include <QtTest/QTest>

#include <memory>

namespace facet::test {

// Waits (processing events) until `done` holds, at most `timeoutMs`.
template <typename Predicate> bool waitFor(Predicate done, int timeoutMs = 30000)
{
    QElapsedTimer clock;
    clock.start();
    while (!done()) {
        if (clock.elapsed() > timeoutMs)
            return false;
        QTest::qWait(20);
    }
    return true;
}

// What a main-window test's initMain() does before the QApplication exists: QStandardPaths in
// test mode (the user's settings and presets untouched), Qt's own dialogs (a test can answer
// them), and the viewport's surface format.
inline void initWindowTestMain()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs);
    installViewportSurfaceFormat();
}

// A main window as the tests drive it: error dialogs off, unsaved changes discarded, shown, its
// first frame drawn and the window active. Null when one of those did not happen in time.
inline std::unique_ptr<MainWindow> showTestWindow(const QString& recoveryFolder)
{
    auto window = std::make_unique<MainWindow>(nullptr, recoveryFolder);
    window->projectFiles()->setErrorDialogsEnabled(false);
    window->projectFiles()->setUnsavedChangesAnswer(QMessageBox::Discard);
    QSignalSpy rendered(window->viewport(), &ViewportWidget::frameRendered);
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get()) || !(rendered.count() > 0 || rendered.wait(60000)))
        return nullptr;
    window->activateWindow();
    if (!QTest::qWaitForWindowActive(window.get()))
        return nullptr;
    return window;
}

// Opens `path` (a project or an asset) and waits until its files are loaded; the undo stack is
// cleared so a test counts only its own steps. False when it could not be opened in time.
inline bool openAndSettle(MainWindow& window, const QString& path)
{
    if (!window.projectFiles()->openFile(path))
        return false;
    SceneController* scene = window.sceneController();
    const bool loaded = QTest::qWaitFor([scene] { return scene->pendingAssetLoads() == 0; }, 30000);
    window.document()->undoStack()->clear();
    return loaded;
}

// Raises the dock that holds `widget` (docks share tabs) and gives the widget the focus.
inline bool focusWidget(QWidget* widget)
{
    if (!widget)
        return false;
    for (QWidget* w = widget; w; w = w->parentWidget())
        if (auto* dock = qobject_cast<QDockWidget*>(w)) {
            dock->show();
            dock->raise();
        }
    widget->setFocus(Qt::OtherFocusReason);
    return QTest::qWaitFor([widget] { return widget->hasFocus(); }, 5000);
}

// Chooses `text` in `combo` as a user does: opens its popup and clicks the item (Mouse) or walks
// to it with the arrow keys and presses Return (Keyboard: a combo in a table cell, whose popup a
// click may miss). True when the popup closed on that item.
enum class ComboInput { Mouse, Keyboard };
inline bool chooseInCombo(QComboBox* combo, const QString& text, ComboInput input = ComboInput::Mouse)
{
    const int index = combo->findText(text);
    if (index < 0)
        return false;
    combo->showPopup();
    QAbstractItemView* view = combo->view();
    if (!QTest::qWaitForWindowExposed(view->window()))
        return false;
    if (input == ComboInput::Mouse) {
        const QModelIndex modelIndex = view->model()->index(index, combo->modelColumn(), view->rootIndex());
        view->scrollTo(modelIndex);
        QTest::mouseClick(
            view->viewport(), Qt::LeftButton, Qt::NoModifier, view->visualRect(modelIndex).center());
    } else {
        const int from = view->currentIndex().isValid() ? view->currentIndex().row() : combo->currentIndex();
        for (int row = from; row < index; ++row)
            QTest::keyClick(view, Qt::Key_Down);
        for (int row = from; row > index; --row)
            QTest::keyClick(view, Qt::Key_Up);
        QTest::keyClick(view, Qt::Key_Return);
    }
    return waitFor([&] { return !view->isVisible(); }, 2000) && combo->currentIndex() == index;
}

// Where a slider's handle is, from the style (what a user would grab).
inline QPoint sliderHandleCentre(QSlider* slider)
{
    QStyleOptionSlider option;
    option.initFrom(slider);
    option.orientation = slider->orientation();
    option.minimum = slider->minimum();
    option.maximum = slider->maximum();
    option.sliderPosition = slider->sliderPosition();
    option.sliderValue = slider->value();
    option.singleStep = slider->singleStep();
    option.pageStep = slider->pageStep();
    option.upsideDown = slider->invertedAppearance();
    option.subControls = QStyle::SC_All;
    return slider->style()
        ->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, slider)
        .center();
}

// A user's drag of a slider by `deltaX` pixels: press on the handle, several moves, release.
inline void dragSlider(QSlider* slider, int deltaX)
{
    const QPoint start = sliderHandleCentre(slider);
    QTest::mousePress(slider, Qt::LeftButton, Qt::NoModifier, start);
    constexpr int kMoves = 6;
    for (int i = 1; i <= kMoves; ++i)
        QTest::mouseMove(slider, start + QPoint(deltaX * i / kMoves, 0), 10);
    QTest::mouseRelease(slider, Qt::LeftButton, Qt::NoModifier, start + QPoint(deltaX, 0), 10);
}

} // namespace facet::test
