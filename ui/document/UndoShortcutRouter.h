#pragma once
// Undo and redo reach the document from every field once its edit is committed (issue 30: with
// a number field focused, Ctrl+Z did nothing: QLineEdit, and so every spin box and slider field,
// takes Ctrl+Z and Ctrl+Shift+Z for its own text even when it has nothing of its own to undo).
// Installed on the application by MainWindow: while a text field (a line edit, a spin box's or an
// editable combo box's) has an uncommitted change (typed, Enter not pressed, focus not left) the
// keys edit its text as usual; otherwise the ShortcutOverride is refused, so Edit > Undo and Redo
// (the document's QUndoStack) take them. A field's edit is committed by its widget's
// editingFinished (Enter, or focus leaving it); a field that gains focus starts committed (its
// text is the document's). Buttons, check boxes, plain combo boxes and sliders never took the keys.
// tests/AuthoringUiTest.cpp has a row per kind of editor.

#include <QObject>

namespace facet {

class UndoShortcutRouter : public QObject {
    Q_OBJECT
public:
    explicit UndoShortcutRouter(QObject* parent = nullptr);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
};

} // namespace facet
