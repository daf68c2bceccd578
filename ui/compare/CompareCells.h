#pragma once
// What the Compare view draws for the project's compare layout (core/project/CompareLayout.h): one
// CompareCell per image, each a Project variant (the document's project with the cell's
// environment, camera, exposure, material or wedge value applied) with its label and its place,
// and the geometry of the cells in the widget (a near-square grid with thin gaps; the wedge's
// axis margins; A/B's split). Plain values, no GL and no widgets: the view (ui/compare/CompareView.h)
// builds these on every change and redraws the cells whose inputs differ.

#include "core/project/CompareLayout.h"
#include "core/project/Project.h"

#include <QRect>
#include <QSize>
#include <QString>

#include <cstddef>
#include <vector>

namespace facet {

struct CompareCell {
    enum class Role {
        Grid, // a cell of the environment grid (index: the grid's cell)
        A, // A/B: the current material
        B, // A/B: ABCompare::materialB
        Wedge, // a wedge cell (row, column)
        Single, // the single view's project (CompareMode::Single; the window shows its viewport)
        RealTime, // the error view: the project by the split sum
        Reference, // the error view: the project by the reference integrator (ErrorCompare::samples)
        Error, // the error view: the relative error of RealTime against Reference (or its noise)
    };
    Role role = Role::Single;
    std::size_t index = 0; // Grid: the cell of EnvironmentGrid::cells
    int row = 0; // where the cell sits in the grid (Wedge: the axis values' indices)
    int column = 0;
    Project project; // what the cell shows
    QString label; // painted over the cell: the environment's name, "A"/"B" with the material's name
};

// The cells of `project.compare.mode` in reading order. A/B in split layout gives A and B at the
// same row and column (one picture, divided at ABCompare::split).
std::vector<CompareCell> compareCells(const Project& project);

// A short name of an environment spec for labels: built-in names as they are, "uniform 1" for
// uniform:1, files and library references by base name ("night" for .../hdri/night.exr).
QString environmentLabel(const std::string& spec);

// How `count` cells sit in a near-square grid: columns = ceil(sqrt(count)), rows as needed
// (2 -> 2x1, 3 -> 2x2, 5 -> 3x2, 9 -> 3x3).
struct GridShape {
    int rows = 1;
    int columns = 1;
};
GridShape gridShapeFor(std::size_t count);
// The rows and columns the mode shows (the wedge's axes; A/B split: 1x1, side by side 1x2).
GridShape gridShapeOf(const Project& project);

// The rectangle of cell (row, column) in a widget of `size` (Qt's coordinates: origin top left),
// with `gap` pixels between cells and `margins` (left, top) kept free for axis labels.
QRect cellRect(const QSize& size, const GridShape& shape, int row, int column, int gap,
    const QSize& margins = QSize(0, 0));

// The wedge's axis margins (left: row values, top: column values), zero in the other modes.
QSize axisMargins(const Project& project);

} // namespace facet
