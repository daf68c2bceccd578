#pragma once
// Compare > Wedge's "Wedge Axes…" (the Compare view's context menu on a wedge cell): the rows'
// axis and the columns' axis (or none) each in a WedgeAxisEditor (ui/compare/WedgeAxisEditor.h: a
// parameter combo and a values list, typed or filled from "from / to / steps"). OK is disabled
// while either axis is not one; accepting sets both as ONE undoable edit
// (CompareController::setWedge). An axis that would sweep nothing in any cell (clearcoat roughness
// without a coat, normal strength without a normal map) is named under the editors, as `facet
// sheet` warns of it (core/project/WedgeSweep); it is still an axis OK accepts.

#include "core/project/Project.h"

#include <QDialog>

class QDialogButtonBox;
class QLabel;
class QPushButton;

namespace facet {

class CompareController;
class WedgeAxisEditor;

class WedgeAxesDialog : public QDialog {
    Q_OBJECT
public:
    // Starts from `project`'s wedge axes; the warning asks of `project`'s current material.
    explicit WedgeAxesDialog(const Project& project, QWidget* parent = nullptr);

    WedgeAxisEditor* rows() const { return m_rows; }
    WedgeAxisEditor* columns() const { return m_columns; }
    QPushButton* okButton() const;
    // "Rows: clearcoatRoughness sweeps nothing: ..." for each such axis; hidden when none.
    QLabel* warningLabel() const { return m_warning; }

    // Sets the edited axes on the document through `controller` (one undo step). False with
    // *error (the window's wording) when they are not axes, which OK being disabled prevents.
    bool applyTo(CompareController& controller, QString* error) const;

    // Opens the dialog for `project`'s wedge and applies what is accepted; a refusal goes to a
    // message box.
    static void edit(CompareController& controller, const Project& project, QWidget* parent);

private:
    void updateOk();

    WedgeAxisEditor* m_rows;
    WedgeAxisEditor* m_columns;
    QLabel* m_warning;
    QDialogButtonBox* m_buttons;
    Project m_project;
};

} // namespace facet
