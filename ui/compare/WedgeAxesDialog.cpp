#include "ui/compare/WedgeAxesDialog.h"

#include "core/project/WedgeSweep.h"
#include "ui/compare/CompareController.h"
#include "ui/compare/WedgeAxisEditor.h"
#include "ui/widgets/WindowMessages.h"

#include <QDialogButtonBox>
#include <QGroupBox>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

namespace facet {

WedgeAxesDialog::WedgeAxesDialog(const Project& project, QWidget* parent)
    : QDialog(parent)
    , m_rows(new WedgeAxisEditor(false, this))
    , m_columns(new WedgeAxisEditor(true, this))
    , m_warning(new QLabel(this))
    , m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
    , m_project(project)
{
    const WedgeLayout& wedge = project.compare.wedge;
    setObjectName(QStringLiteral("wedgeAxesDialog"));
    setWindowTitle(tr("Wedge Axes"));
    m_rows->setObjectName(QStringLiteral("wedgeRowsEditor"));
    m_columns->setObjectName(QStringLiteral("wedgeColumnsEditor"));
    m_rows->setAxis(wedge.rows);
    m_columns->setAxis(wedge.columns);

    auto* layout = new QVBoxLayout(this);
    const auto group = [this, layout](const QString& title, WedgeAxisEditor* editor) {
        auto* box = new QGroupBox(title, this);
        auto* inner = new QVBoxLayout(box);
        inner->addWidget(editor);
        layout->addWidget(box);
    };
    group(tr("Rows"), m_rows);
    group(tr("Columns"), m_columns);
    m_warning->setObjectName(QStringLiteral("wedgeWarning"));
    m_warning->setWordWrap(true);
    layout->addWidget(m_warning);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_rows, &WedgeAxisEditor::edited, this, &WedgeAxesDialog::updateOk);
    connect(m_columns, &WedgeAxisEditor::edited, this, &WedgeAxesDialog::updateOk);
    updateOk();
    resize(sizeHint().expandedTo(QSize(460, 0)));
}

QPushButton* WedgeAxesDialog::okButton() const
{
    return m_buttons->button(QDialogButtonBox::Ok);
}

void WedgeAxesDialog::updateOk()
{
    const bool valid = m_rows->isValid() && m_columns->isValid();
    okButton()->setEnabled(valid);
    // The axes as they would be (each editor's, as it validated it), asked whether each sweeps
    // something in some cell.
    QStringList warnings;
    if (valid && m_rows->axis()) {
        WedgeLayout wedge;
        wedge.rows = *m_rows->axis();
        wedge.columns = m_columns->axis();
        for (const bool columnsAxis : {false, true}) {
            const std::string reason = sweepsNothing(wedge, m_project, columnsAxis);
            if (!reason.empty())
                warnings << (columnsAxis ? tr("Columns: %1 sweeps nothing: %2")
                                         : tr("Rows: %1 sweeps nothing: %2"))
                                .arg(QString::fromLatin1(
                                         toString((columnsAxis ? *wedge.columns : wedge.rows).parameter)),
                                    WindowMessages::fromCore(reason));
        }
    }
    m_warning->setText(warnings.join(u'\n'));
    m_warning->setVisible(!warnings.isEmpty());
}

bool WedgeAxesDialog::applyTo(CompareController& controller, QString* error) const
{
    std::string problem;
    if (controller.setWedge(m_rows->text(), m_columns->text(), &problem))
        return true;
    if (error)
        *error = WindowMessages::fromCore(problem);
    return false;
}

void WedgeAxesDialog::edit(CompareController& controller, const Project& project, QWidget* parent)
{
    WedgeAxesDialog dialog(project, parent);
    if (dialog.exec() != QDialog::Accepted)
        return;
    QString error;
    if (!dialog.applyTo(controller, &error))
        QMessageBox::warning(parent, tr("Wedge Axes"), error);
}

} // namespace facet
