#include "ui/document/UndoShortcutRouter.h"

#include <QAbstractSpinBox>
#include <QComboBox>
#include <QEvent>
#include <QKeyEvent>
#include <QKeySequence>
#include <QLineEdit>

namespace facet {

namespace {

const char* const kRouted = "facetUndoRouted";

bool isUndoOrRedo(const QKeyEvent& key)
{
    // Edit > Redo's keys: Ctrl+Shift+Z and Ctrl+Y (MainWindow::createEditMenu).
    const QKeyCombination keys = key.keyCombination();
    return key.matches(QKeySequence::Undo) || key.matches(QKeySequence::Redo)
        || keys == QKeyCombination(Qt::ControlModifier | Qt::ShiftModifier, Qt::Key_Z)
        || keys == QKeyCombination(Qt::ControlModifier, Qt::Key_Y);
}

// The text field behind a focus widget: a line edit itself, a spin box's (the spin box is the
// focus widget and hands its ShortcutOverride to the field directly, past any event filter), or
// an editable combo box's.
QLineEdit* fieldOf(QObject* widget)
{
    if (auto* edit = qobject_cast<QLineEdit*>(widget))
        return edit;
    if (auto* spin = qobject_cast<QAbstractSpinBox*>(widget))
        return spin->findChild<QLineEdit*>();
    if (auto* combo = qobject_cast<QComboBox*>(widget))
        return combo->isEditable() ? combo->lineEdit() : nullptr;
    return nullptr;
}

} // namespace

UndoShortcutRouter::UndoShortcutRouter(QObject* parent)
    : QObject(parent)
{
}

bool UndoShortcutRouter::eventFilter(QObject* watched, QEvent* event)
{
    const QEvent::Type type = event->type();
    if (type != QEvent::FocusIn && type != QEvent::ShortcutOverride)
        return QObject::eventFilter(watched, event);
    QLineEdit* field = fieldOf(watched);
    if (!field)
        return QObject::eventFilter(watched, event);
    if (type == QEvent::FocusIn) {
        // Its text is the document's: nothing of its own to undo yet. Its edits are committed by
        // its widget's editingFinished (Enter, or focus leaving it), connected once.
        field->setModified(false);
        if (!watched->property(kRouted).toBool()) {
            watched->setProperty(kRouted, true);
            if (auto* spin = qobject_cast<QAbstractSpinBox*>(watched))
                connect(
                    spin, &QAbstractSpinBox::editingFinished, field, [field] { field->setModified(false); });
            else
                connect(field, &QLineEdit::editingFinished, field, [field] { field->setModified(false); });
        }
    } else if (isUndoOrRedo(*static_cast<QKeyEvent*>(event)) && !field->isModified()) {
        // Not the field's to take: the shortcut (Edit > Undo / Redo) gets the keys.
        event->ignore();
        return true;
    }
    return QObject::eventFilter(watched, event);
}

} // namespace facet
