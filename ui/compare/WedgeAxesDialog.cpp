#include "ui/compare/WedgeAxesDialog.h"

#include "ui/compare/CompareController.h"
#include "ui/compare/WedgeAxisEditor.h"
#include "ui/widgets/WindowMessages.h"

#include <QDialogButtonBox>
#include <QGroupBox>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

namespace facet {

WedgeAxesDialog::WedgeAxesDialog(const WedgeLayout& wedge, QWidget* parent)
    : QDialog(parent)
    , m_rows(new WedgeAxisEditor(false, this))
    , m_columns(new WedgeAxisEditor(true, this))
    , m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
{
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
    okButton()->setEnabled(m_rows->isValid() && m_columns->isValid());
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

void WedgeAxesDialog::edit(CompareController& controller, const WedgeLayout& wedge, QWidget* parent)
{
    WedgeAxesDialog dialog(wedge, parent);
    if (dialog.exec() != QDialog::Accepted)
        return;
    QString error;
    if (!dialog.applyTo(controller, &error))
        QMessageBox::warning(parent, tr("Wedge Axes"), error);
}

} // namespace facet
