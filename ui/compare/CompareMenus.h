#pragma once
// The Compare view's context menus (what a right click on a cell offers), built on demand; every
// action is a CompareController edit (undoable):
//   grid cell   Environment ▸ (the library), Add Cell ▸, Remove Cell, Rotation (follow all /
//               own…), Exposure (follow all / own…), Unlink / Link Camera, Link All Cameras,
//               Promote to Single View
//   A/B         B ▸ (materials of the project, Snapshot of Current, presets), Split / Side by
//               Side, Swap A and B
//   wedge       Wedge Axes… (ui/compare/WedgeAxesDialog.h: a parameter and values per axis)

#include <QString>

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

class QMenu;
class QWidget;

namespace facet {

class CompareController;
struct CompareCell;
struct Project;

// (label, environment source) pairs, in the library's order.
using EnvironmentChoices = std::vector<std::pair<QString, QString>>;
using EnvironmentChoicesFunction = std::function<EnvironmentChoices()>;

namespace CompareMenus {

// Fills `menu` for `cell` of `project`'s compare mode. `dialogParent` parents the value dialogs.
void fill(QMenu& menu, CompareController& controller, const Project& project, const CompareCell& cell,
    const EnvironmentChoices& choices, QWidget* dialogParent);

} // namespace CompareMenus

} // namespace facet
