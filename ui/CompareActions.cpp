#include "ui/CompareActions.h"

#include "core/Project.h"
#include "ui/CompareController.h"
#include "ui/Document.h"

#include <QAction>
#include <QActionGroup>
#include <QKeySequence>
#include <QListWidget>
#include <QMenu>
#include <QStackedWidget>
#include <QToolBar>

namespace facet {

CompareActions::CompareActions(
    Document* document, CompareController* controller, QStackedWidget* central, QWidget* parent)
    : QObject(parent)
    , m_document(document)
    , m_central(central)
    , m_menu(new QMenu(tr("&Compare"), parent))
    , m_toolBar(new QToolBar(tr("Compare"), parent))
    , m_modes(new QActionGroup(this))
{
    m_menu->setObjectName(QStringLiteral("compareMenu"));
    m_toolBar->setObjectName(QStringLiteral("compareToolBar"));
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    struct Entry {
        CompareMode mode;
        QString text;
        const char* name;
        Qt::Key key;
    };
    const Entry entries[] = {
        {CompareMode::Single, tr("&Single View"), "compareSingleAction", Qt::Key_1},
        {CompareMode::Environments, tr("&Environment Grid"), "compareEnvironmentsAction", Qt::Key_2},
        {CompareMode::AB, tr("&A/B"), "compareABAction", Qt::Key_3},
        {CompareMode::Wedge, tr("&Wedge"), "compareWedgeAction", Qt::Key_4},
    };
    for (const Entry& entry : entries) {
        QAction* action = m_menu->addAction(entry.text);
        action->setObjectName(QLatin1String(entry.name));
        action->setCheckable(true);
        action->setData(int(entry.mode));
        // Alt+1..4: the number keys alone apply presets (Edit > Apply Preset).
        action->setShortcut(QKeySequence(Qt::ALT | entry.key));
        m_modes->addAction(action);
        m_toolBar->addAction(action);
        connect(action, &QAction::triggered, controller,
            [controller, mode = entry.mode] { controller->setMode(mode); });
    }
    m_menu->addSeparator();
    m_swap = m_menu->addAction(tr("S&wap A and B"), controller, &CompareController::swap);
    m_swap->setObjectName(QStringLiteral("compareSwapAction"));
    m_swap->setShortcut(QKeySequence(Qt::ALT | Qt::Key_S));
    m_toolBar->addAction(m_swap);
    connect(m_document, &Document::changed, this, &CompareActions::sync);
    sync();
}

QAction* CompareActions::modeAction(CompareMode mode) const
{
    for (QAction* action : m_modes->actions())
        if (action->data().toInt() == int(mode))
            return action;
    return nullptr;
}

void CompareActions::sync()
{
    const CompareMode mode = m_document->project().compare.mode;
    if (QAction* action = modeAction(mode); action && !action->isChecked())
        action->setChecked(true);
    m_swap->setEnabled(mode == CompareMode::AB);
    m_central->setCurrentIndex(mode == CompareMode::Single ? 0 : 1);
}

EnvironmentChoices CompareActions::choicesOf(const QListWidget* library)
{
    EnvironmentChoices choices;
    for (int row = 0; row < library->count(); ++row) {
        const QListWidgetItem* item = library->item(row);
        choices.emplace_back(item->text(), item->data(Qt::UserRole).toString());
    }
    return choices;
}

} // namespace facet
