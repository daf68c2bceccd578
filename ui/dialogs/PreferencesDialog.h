#pragma once
// Edit > Preferences: the settings that belong to this computer rather than to a project. For now
// the cache budget (ui/widgets/CacheBudget.h): how much memory the window keeps for the lighting of
// environments shown before, with what it holds now.

#include <QDialog>

#include <cstddef>

class QLabel;
class QSpinBox;

namespace facet {

class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    // `heldBytes` / `heldEntries`: what the window's IBL cache holds now (the view's last frame).
    PreferencesDialog(std::size_t heldBytes, int heldEntries, QWidget* parent = nullptr);

    QSpinBox* cacheBudgetSpin() const { return m_budget; }

    // Stores what the dialog shows (OK).
    void accept() override;

private:
    QSpinBox* m_budget;
};

} // namespace facet
