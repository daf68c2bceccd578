#include "ui/compare/CompareCells.h"

#include "core/ibl/Environment.h"

#include <QCoreApplication>
#include <QFileInfo>

#include <algorithm>
#include <cmath>

namespace facet {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("CompareCells", text);
}

QString materialName(const Material& material)
{
    return material.name.empty() ? tr("Material") : QString::fromStdString(material.name);
}

// The wedge's margins for its axis labels (values like "roughness 0.25" on the left, one line
// above the columns).
constexpr int kRowAxisWidth = 112;
constexpr int kColumnAxisHeight = 20;

} // namespace

QString environmentLabel(const std::string& spec)
{
    if (spec.rfind("uniform:", 0) == 0)
        return QStringLiteral("uniform ") + QString::fromStdString(spec.substr(8));
    if (Environment::builtinFromName(spec))
        return QString::fromStdString(spec);
    // Files and library references ("library:installed/hdri/night.exr") by their base name.
    return QFileInfo(QString::fromStdString(spec)).completeBaseName();
}

std::vector<CompareCell> compareCells(const Project& project)
{
    std::vector<CompareCell> cells;
    const CompareLayout& layout = project.compare;
    switch (layout.mode) {
    case CompareMode::Single: {
        CompareCell cell;
        cell.project = project;
        cell.label = environmentLabel(project.environment.source);
        cells.push_back(std::move(cell));
        break;
    }
    case CompareMode::Environments: {
        const EnvironmentGrid& grid = layout.environments;
        const GridShape shape = gridShapeFor(grid.cells.size());
        for (std::size_t i = 0; i < grid.cells.size(); ++i) {
            CompareCell cell;
            cell.role = CompareCell::Role::Grid;
            cell.index = i;
            cell.row = int(i) / shape.columns;
            cell.column = int(i) % shape.columns;
            cell.project = project;
            cell.project.environment = grid.environmentOf(i, project);
            cell.project.camera = grid.cameraOf(i, project);
            cell.project.view.exposureEV = grid.exposureEVOf(i, project);
            QString label = environmentLabel(grid.cells[i].source);
            const EnvironmentCell& own = grid.cells[i];
            if (!own.exposureFollowsAll && own.exposureOffsetEV != 0.0)
                label += QStringLiteral(" · %1%2 EV")
                             .arg(own.exposureOffsetEV > 0 ? QStringLiteral("+") : QString())
                             .arg(own.exposureOffsetEV);
            if (!own.rotationFollowsAll)
                label += QStringLiteral(" · %1°").arg(own.rotationDegrees);
            if (!grid.isLinked(i))
                label += tr(" · unlinked");
            cell.label = label;
            cells.push_back(std::move(cell));
        }
        break;
    }
    case CompareMode::AB: {
        const bool split = layout.ab.layout == ABLayout::Split;
        CompareCell a;
        a.role = CompareCell::Role::A;
        a.project = project;
        a.label = QStringLiteral("A · ") + materialName(project.material());
        CompareCell b;
        b.role = CompareCell::Role::B;
        b.column = split ? 0 : 1;
        b.project = project;
        b.project.material() = layout.ab.materialB(project);
        QString source;
        switch (layout.ab.source) {
        case BSource::Material:
            source = materialName(b.project.material());
            break;
        case BSource::Snapshot:
            source = tr("snapshot of %1").arg(materialName(b.project.material()));
            break;
        case BSource::Preset:
            source = tr("preset %1").arg(QString::fromStdString(layout.ab.preset));
            break;
        }
        b.label = QStringLiteral("B · ") + source;
        cells.push_back(std::move(a));
        cells.push_back(std::move(b));
        break;
    }
    case CompareMode::Error: {
        // Three cells of a 2 x 2 grid (gridShapeFor(3)): wide enough for the object in a tall
        // window as in a wide one.
        const ErrorCompare& error = layout.error;
        CompareCell realTime;
        realTime.role = CompareCell::Role::RealTime;
        realTime.project = project;
        realTime.project.environment.method = IblMethod::SplitSum;
        realTime.project.environment.samples = 0;
        realTime.label = tr("Real time · split sum (%1)")
                             .arg(QString::fromLatin1(toString(project.environment.quality)));
        CompareCell reference;
        reference.role = CompareCell::Role::Reference;
        reference.column = 1;
        reference.project = project;
        reference.project.environment.method = IblMethod::Reference;
        reference.project.environment.samples = error.samples;
        reference.label = tr("Reference");
        CompareCell difference;
        difference.role = CompareCell::Role::Error;
        difference.row = 1;
        difference.project = reference.project;
        difference.label = error.showNoise ? tr("Reference noise") : tr("Relative error");
        cells.push_back(std::move(realTime));
        cells.push_back(std::move(reference));
        cells.push_back(std::move(difference));
        break;
    }
    case CompareMode::Wedge: {
        const WedgeLayout& wedge = layout.wedge;
        for (std::size_t r = 0; r < wedge.rowCount(); ++r)
            for (std::size_t c = 0; c < wedge.columnCount(); ++c) {
                CompareCell cell;
                cell.role = CompareCell::Role::Wedge;
                cell.row = int(r);
                cell.column = int(c);
                cell.index = r * wedge.columnCount() + c;
                cell.project = wedge.cellProject(project, r, c);
                // The values are printed on the axes (CompareView); the cell names both for tooltips.
                cell.label = QString::fromStdString(wedge.rows.label(r));
                if (wedge.columns)
                    cell.label += QStringLiteral(" · ") + QString::fromStdString(wedge.columns->label(c));
                cells.push_back(std::move(cell));
            }
        break;
    }
    }
    return cells;
}

GridShape gridShapeFor(std::size_t count)
{
    GridShape shape;
    if (count <= 1)
        return shape;
    shape.columns = int(std::ceil(std::sqrt(double(count))));
    shape.rows = int((count + std::size_t(shape.columns) - 1) / std::size_t(shape.columns));
    return shape;
}

GridShape gridShapeOf(const Project& project)
{
    const CompareLayout& layout = project.compare;
    switch (layout.mode) {
    case CompareMode::Single:
        return {};
    case CompareMode::Environments:
        return gridShapeFor(layout.environments.cells.size());
    case CompareMode::AB:
        return layout.ab.layout == ABLayout::Split ? GridShape {} : GridShape {1, 2};
    case CompareMode::Wedge:
        return GridShape {int(layout.wedge.rowCount()), int(layout.wedge.columnCount())};
    case CompareMode::Error:
        return gridShapeFor(3);
    }
    return {};
}

QRect cellRect(const QSize& size, const GridShape& shape, int row, int column, int gap, const QSize& margins)
{
    // Integer edges so neighbouring cells tile the area exactly (a cell's width may differ by one
    // pixel from its neighbour's).
    const int width = std::max(0, size.width() - margins.width());
    const int height = std::max(0, size.height() - margins.height());
    const auto edge
        = [gap](int extent, int count, int i) { return int(std::lround(double(extent + gap) * i / count)); };
    const int left = margins.width() + edge(width, shape.columns, column);
    const int right = margins.width() + edge(width, shape.columns, column + 1) - gap;
    const int top = margins.height() + edge(height, shape.rows, row);
    const int bottom = margins.height() + edge(height, shape.rows, row + 1) - gap;
    return QRect(QPoint(left, top), QPoint(std::max(left, right - 1), std::max(top, bottom - 1)));
}

QSize axisMargins(const Project& project)
{
    if (project.compare.mode != CompareMode::Wedge)
        return QSize(0, 0); // not QSize(): that is (-1, -1)
    return QSize(kRowAxisWidth, project.compare.wedge.columns ? kColumnAxisHeight : 0);
}

} // namespace facet
