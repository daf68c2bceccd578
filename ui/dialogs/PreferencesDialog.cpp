#include "ui/dialogs/PreferencesDialog.h"

#include "ui/widgets/CacheBudget.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>
#include <QVBoxLayout>

namespace facet {

PreferencesDialog::PreferencesDialog(std::size_t heldBytes, int heldEntries, QWidget* parent)
    : QDialog(parent)
    , m_budget(new QSpinBox(this))
{
    setWindowTitle(tr("Preferences"));
    m_budget->setObjectName(QStringLiteral("cacheBudgetSpin"));
    m_budget->setRange(CacheBudget::kMinMegabytes, CacheBudget::kMaxMegabytes);
    m_budget->setSingleStep(64);
    m_budget->setSuffix(tr(" MiB"));
    m_budget->setValue(CacheBudget::megabytes());
    m_budget->setToolTip(
        tr("The lighting (IBL sets and environment sources) of environments shown before is kept "
           "within this budget, least recently used out first, so that going back to one is "
           "instant. What a view shows is always kept. Default %1 MiB.")
            .arg(CacheBudget::kDefaultMegabytes));
    auto* held = new QLabel(tr("In use: %1 MiB (%n entries)", nullptr, heldEntries)
                                .arg(double(heldBytes) / double(1 << 20), 0, 'f', 1),
        this);
    held->setObjectName(QStringLiteral("cacheHeldLabel"));
    auto* form = new QFormLayout;
    form->addRow(tr("Lighting cache budget:"), m_budget);
    form->addRow(QString(), held);
    if (CacheBudget::fromEnvironment()) {
        m_budget->setEnabled(false);
        auto* note = new QLabel(tr("Set by FACET_CACHE_BUDGET_MB in the environment."), this);
        note->setObjectName(QStringLiteral("cacheBudgetEnvironmentNote"));
        form->addRow(QString(), note);
    }
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
}

void PreferencesDialog::accept()
{
    if (m_budget->isEnabled() && m_budget->value() != CacheBudget::megabytes())
        CacheBudget::setMegabytes(m_budget->value());
    QDialog::accept();
}

} // namespace facet
