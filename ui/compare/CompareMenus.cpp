#include "ui/compare/CompareMenus.h"

#include "core/material/MaterialPresets.h"
#include "core/project/Project.h"
#include "ui/compare/CompareCells.h"
#include "ui/compare/CompareController.h"
#include "ui/compare/WedgeAxesDialog.h"

#include <QAction>
#include <QCoreApplication>
#include <QInputDialog>
#include <QMenu>

namespace facet {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("CompareMenus", text);
}

void fillGrid(QMenu& menu, CompareController& controller, const Project& project, std::size_t index,
    const EnvironmentChoices& choices, QWidget* dialogParent)
{
    const EnvironmentGrid& grid = project.compare.environments;
    const EnvironmentCell& cell = grid.cells[index];
    QMenu* environments = menu.addMenu(tr("&Environment"));
    environments->setObjectName(QStringLiteral("cellEnvironmentMenu"));
    QMenu* add = menu.addMenu(tr("&Add Cell"));
    add->setObjectName(QStringLiteral("addCellMenu"));
    add->setEnabled(int(grid.cells.size()) < EnvironmentGrid::kMaxCells);
    for (const auto& [label, source] : choices) {
        QAction* choose = environments->addAction(label);
        choose->setCheckable(true);
        choose->setChecked(source.toStdString() == cell.source);
        QObject::connect(choose, &QAction::triggered, &controller,
            [&controller, index, source = source] { controller.setCellSource(index, source.toStdString()); });
        QObject::connect(add->addAction(label), &QAction::triggered, &controller,
            [&controller, source = source] { controller.addCell(source.toStdString()); });
    }
    QAction* remove = menu.addAction(
        tr("&Remove Cell"), &controller, [&controller, index] { controller.removeCell(index); });
    remove->setEnabled(int(grid.cells.size()) > EnvironmentGrid::kMinCells);
    menu.addSeparator();

    QAction* rotationAll = menu.addAction(tr("Rotation: Follow All"));
    rotationAll->setCheckable(true);
    rotationAll->setChecked(cell.rotationFollowsAll);
    QObject::connect(rotationAll, &QAction::triggered, &controller,
        [&controller, index] { controller.setCellRotation(index, std::nullopt); });
    menu.addAction(tr("Rotation: Own…"), &controller, [&controller, index, dialogParent, cell] {
        bool ok = false;
        const double degrees = QInputDialog::getDouble(dialogParent, tr("Cell Rotation"),
            tr("Rotation (degrees):"), cell.rotationDegrees, -360.0, 360.0, 1, &ok);
        if (ok)
            controller.setCellRotation(index, degrees);
    });
    QAction* exposureAll = menu.addAction(tr("Exposure: Follow All"));
    exposureAll->setCheckable(true);
    exposureAll->setChecked(cell.exposureFollowsAll);
    QObject::connect(exposureAll, &QAction::triggered, &controller,
        [&controller, index] { controller.setCellExposure(index, std::nullopt); });
    menu.addAction(tr("Exposure: Own Offset…"), &controller, [&controller, index, dialogParent, cell] {
        bool ok = false;
        const double ev = QInputDialog::getDouble(dialogParent, tr("Cell Exposure"),
            tr("Offset from the view's exposure (EV):"), cell.exposureOffsetEV, ViewSettings::kMinExposureEV,
            ViewSettings::kMaxExposureEV, 2, &ok);
        if (ok)
            controller.setCellExposure(index, ev);
    });
    menu.addSeparator();
    const bool linked = grid.isLinked(index);
    QAction* link = menu.addAction(linked ? tr("&Unlink Camera") : tr("&Link Camera"), &controller,
        [&controller, index, linked] { controller.setCellLinked(index, !linked); });
    link->setObjectName(QStringLiteral("cellLinkAction"));
    QAction* linkAll = menu.addAction(tr("Link All Cameras"));
    linkAll->setCheckable(true);
    linkAll->setChecked(grid.linkedCameras);
    QObject::connect(
        linkAll, &QAction::toggled, &controller, [&controller](bool on) { controller.setLinkedCameras(on); });
    menu.addSeparator();
    QAction* promote = menu.addAction(
        tr("&Promote to Single View"), &controller, [&controller, index] { controller.promoteCell(index); });
    promote->setObjectName(QStringLiteral("promoteCellAction"));
}

void fillAB(QMenu& menu, CompareController& controller, const Project& project)
{
    const ABCompare& ab = project.compare.ab;
    QMenu* b = menu.addMenu(tr("&B Shows"));
    for (std::size_t m = 0; m < project.materials.size(); ++m) {
        const Material& material = project.materials[m];
        QAction* action = b->addAction(
            material.name.empty() ? tr("Material %1").arg(m + 1) : QString::fromStdString(material.name));
        action->setCheckable(true);
        action->setChecked(ab.source == BSource::Material && ab.material == int(m));
        QObject::connect(
            action, &QAction::triggered, &controller, [&controller, m] { controller.setBMaterial(int(m)); });
    }
    b->addSeparator();
    b->addAction(
        tr("&Snapshot of the Current Material"), &controller, [&controller] { controller.takeSnapshot(); });
    QMenu* presets = b->addMenu(tr("&Preset"));
    for (const MaterialPreset& preset : builtinPresets()) {
        QAction* action = presets->addAction(QString::fromStdString(preset.displayName));
        action->setCheckable(true);
        action->setChecked(ab.source == BSource::Preset && ab.preset == preset.id);
        QObject::connect(action, &QAction::triggered, &controller,
            [&controller, id = preset.id] { controller.setBPreset(id); });
    }
    menu.addSeparator();
    QAction* split = menu.addAction(
        tr("S&plit"), &controller, [&controller] { controller.setABLayout(ABLayout::Split); });
    split->setCheckable(true);
    split->setChecked(ab.layout == ABLayout::Split);
    QAction* sideBySide = menu.addAction(
        tr("Side by S&ide"), &controller, [&controller] { controller.setABLayout(ABLayout::SideBySide); });
    sideBySide->setCheckable(true);
    sideBySide->setChecked(ab.layout == ABLayout::SideBySide);
    menu.addSeparator();
    menu.addAction(tr("S&wap A and B"), &controller, [&controller] { controller.swap(); });
}

void fillWedge(QMenu& menu, CompareController& controller, const Project& project, QWidget* dialogParent)
{
    QAction* axes = menu.addAction(tr("Wedge &Axes…"), &controller,
        [&controller, dialogParent, project] { WedgeAxesDialog::edit(controller, project, dialogParent); });
    axes->setObjectName(QStringLiteral("wedgeAxesAction"));
}

// The error view's settings (ErrorCompare): what the heat map shows, its scale, the samples.
void fillError(QMenu& menu, CompareController& controller, const Project& project)
{
    const ErrorCompare& error = project.compare.error;
    QAction* noise = menu.addAction(tr("Show Reference &Noise"), &controller,
        [&controller, showNoise = error.showNoise] { controller.setErrorShowsNoise(!showNoise); });
    noise->setObjectName(QStringLiteral("errorShowNoiseAction"));
    noise->setCheckable(true);
    noise->setChecked(error.showNoise);
    QMenu* scales = menu.addMenu(tr("Error &Scale"));
    for (double scale : ErrorCompare::kScaleChoices) {
        QAction* action = scales->addAction(tr("0 to %1%").arg(scale * 100.0, 0, 'g', 3), &controller,
            [&controller, scale] { controller.setErrorScale(scale); });
        action->setCheckable(true);
        action->setChecked(error.scale == scale);
    }
    QMenu* samples = menu.addMenu(tr("Reference &Samples"));
    samples->setObjectName(QStringLiteral("errorSamplesMenu"));
    for (int count : {256, 1024, 4096, 16384}) {
        QAction* action = samples->addAction(tr("%1 per pixel").arg(count), &controller,
            [&controller, count] { controller.setErrorSamples(count); });
        action->setCheckable(true);
        action->setChecked(error.samples == count);
    }
}

} // namespace

void CompareMenus::fill(QMenu& menu, CompareController& controller, const Project& project,
    const CompareCell& cell, const EnvironmentChoices& choices, QWidget* dialogParent)
{
    switch (cell.role) {
    case CompareCell::Role::Grid:
        fillGrid(menu, controller, project, cell.index, choices, dialogParent);
        break;
    case CompareCell::Role::A:
    case CompareCell::Role::B:
        fillAB(menu, controller, project);
        break;
    case CompareCell::Role::Wedge:
        fillWedge(menu, controller, project, dialogParent);
        break;
    case CompareCell::Role::RealTime:
    case CompareCell::Role::Reference:
    case CompareCell::Role::Error:
        fillError(menu, controller, project);
        break;
    case CompareCell::Role::Single:
        break;
    }
}

} // namespace facet
