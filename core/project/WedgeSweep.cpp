#include "core/project/WedgeSweep.h"

#include <vector>

namespace facet {

std::string noEffectReasonInEvery(const WedgeAxis& axis, std::span<const Project> cells)
{
    std::string reason;
    for (const Project& cell : cells) {
        reason = axis.noEffectReason(cell);
        if (reason.empty())
            return reason;
    }
    return reason;
}

std::string sweepsNothing(const WedgeLayout& wedge, const Project& project, bool columnsAxis)
{
    if (columnsAxis && !wedge.columns)
        return {};
    // The cells across the other axis (this axis at its first value).
    std::vector<Project> cells;
    const std::size_t count = columnsAxis ? wedge.rowCount() : wedge.columnCount();
    for (std::size_t i = 0; i < count; ++i)
        cells.push_back(columnsAxis ? wedge.cellProject(project, i, 0) : wedge.cellProject(project, 0, i));
    return noEffectReasonInEvery(columnsAxis ? *wedge.columns : wedge.rows, cells);
}

} // namespace facet
