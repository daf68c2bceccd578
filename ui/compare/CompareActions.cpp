#include "ui/compare/CompareActions.h"

#include "core/project/Project.h"
#include "ui/compare/CompareController.h"
#include "ui/docks/EnvironmentDock.h"
#include "ui/document/Document.h"

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
    , m_controller(controller)
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
        {CompareMode::Error, tr("E&rror View"), "compareErrorAction", Qt::Key_5},
    };
    for (const Entry& entry : entries) {
        QAction* action = m_menu->addAction(entry.text);
        action->setObjectName(QLatin1String(entry.name));
        action->setCheckable(true);
        action->setData(int(entry.mode));
        // Alt+1..5: Ctrl+1..9 apply presets (Edit > Apply Preset).
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
    m_compareSelected
        = m_menu->addAction(tr("Compare Se&lected Environments"), this, &CompareActions::compareSelected);
    m_compareSelected->setObjectName(QStringLiteral("compareSelectedAction"));
    m_compareSelected->setStatusTip(
        tr("Show the environments selected in the Environment Library (2 to %1) in the "
           "environment grid")
            .arg(EnvironmentGrid::kMaxCells));
    m_compareSelected->setEnabled(false);

    // The error view's settings (ErrorCompare): what the heat map shows and its scale.
    m_menu->addSeparator();
    m_showNoise = m_menu->addAction(tr("Show Reference &Noise"));
    m_showNoise->setObjectName(QStringLiteral("compareShowNoiseAction"));
    m_showNoise->setCheckable(true);
    m_showNoise->setStatusTip(
        tr("The error view's heat map shows the reference's own noise estimate instead of "
           "the real-time image's error: where the noise is not well below the error, "
           "the error is not measured yet"));
    connect(m_showNoise, &QAction::triggered, controller, &CompareController::setErrorShowsNoise);
    m_errorScaleMenu = m_menu->addMenu(tr("Error &Scale"));
    m_errorScaleMenu->setObjectName(QStringLiteral("compareErrorScaleMenu"));
    m_errorScales = new QActionGroup(this);
    for (double scale : ErrorCompare::kScaleChoices) {
        QAction* action = m_errorScaleMenu->addAction(tr("0 to %1%").arg(scale * 100.0, 0, 'g', 3));
        action->setCheckable(true);
        action->setData(scale);
        m_errorScales->addAction(action);
        connect(action, &QAction::triggered, controller,
            [controller, scale] { controller->setErrorScale(scale); });
    }
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
    const ErrorCompare& error = m_document->project().compare.error;
    m_showNoise->setEnabled(mode == CompareMode::Error);
    m_showNoise->setChecked(error.showNoise);
    m_errorScaleMenu->setEnabled(mode == CompareMode::Error);
    for (QAction* action : m_errorScales->actions())
        action->setChecked(action->data().toDouble() == error.scale);
    m_central->setCurrentIndex(mode == CompareMode::Single ? 0 : 1);
}

void CompareActions::setEnvironmentDock(EnvironmentDock* dock)
{
    m_environmentDock = dock;
    QListWidget* library = dock->library();
    library->setContextMenuPolicy(Qt::ActionsContextMenu);
    library->addAction(m_compareSelected);
    connect(dock, &EnvironmentDock::selectionChanged, this, &CompareActions::syncCompareSelected);
    syncCompareSelected(int(dock->selectedSources().size()));
}

void CompareActions::syncCompareSelected(int selectedCount)
{
    m_compareSelected->setEnabled(selectedCount >= EnvironmentGrid::kMinCells);
}

void CompareActions::compareSelected()
{
    if (!m_environmentDock)
        return;
    const QStringList selected = m_environmentDock->selectedSources();
    std::vector<std::string> sources;
    for (const QString& source : selected)
        sources.push_back(source.toStdString());
    const int cells = m_controller->compareEnvironments(sources);
    if (cells > 0 && cells < int(selected.size()))
        Q_EMIT message(tr("Comparing the first %1 of the %2 selected environments: the grid holds at most %1")
                           .arg(cells)
                           .arg(selected.size()));
}

EnvironmentChoices CompareActions::choicesOf(const QListWidget* library)
{
    EnvironmentChoices choices;
    for (int row = 0; row < library->count(); ++row) {
        const QListWidgetItem* item = library->item(row);
        // The label without the resolution line the library adds under it.
        choices.emplace_back(
            item->text().section(QLatin1Char('\n'), 0, 0), item->data(Qt::UserRole).toString());
    }
    return choices;
}

} // namespace facet
