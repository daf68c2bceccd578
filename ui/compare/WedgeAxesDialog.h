#pragma once
// Compare > Wedge's "Wedge Axes…" (the Compare view's context menu on a wedge cell): the rows'
// axis and the columns' axis (or none) each in a WedgeAxisEditor (ui/compare/WedgeAxisEditor.h: a
// parameter combo and a values list, typed or filled from "from / to / steps"). OK is disabled
// while either axis is not one; accepting sets both as ONE undoable edit
// (CompareController::setWedge).

#include "core/project/CompareLayout.h"

#include <QDialog>

class QDialogButtonBox;
class QPushButton;

namespace facet {

class CompareController;
class WedgeAxisEditor;

class WedgeAxesDialog : public QDialog {
    Q_OBJECT
public:
    // Starts from `wedge`'s axes.
    explicit WedgeAxesDialog(const WedgeLayout& wedge, QWidget* parent = nullptr);

    WedgeAxisEditor* rows() const { return m_rows; }
    WedgeAxisEditor* columns() const { return m_columns; }
    QPushButton* okButton() const;

    // Sets the edited axes on the document through `controller` (one undo step). False with
    // *error (the window's wording) when they are not axes, which OK being disabled prevents.
    bool applyTo(CompareController& controller, QString* error) const;

    // Opens the dialog for `wedge` and applies what is accepted; a refusal goes to a message box.
    static void edit(CompareController& controller, const WedgeLayout& wedge, QWidget* parent);

private:
    void updateOk();

    WedgeAxisEditor* m_rows;
    WedgeAxisEditor* m_columns;
    QDialogButtonBox* m_buttons;
};

} // namespace facet
