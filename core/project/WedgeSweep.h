#pragma once
// Whether a wedge axis sweeps anything: the one check `facet sheet` (its warning) and the window's
// Wedge Axes dialog (the note under its editors) share. An axis is valid either way; sweeping
// one that changes nothing in any cell (clearcoat roughness without a coat, normal strength
// without a normal map: WedgeAxis::noEffectReason) is worth a word, unless the other axis sets
// what it needs (a clearcoat column under clearcoatRoughness rows).

#include <span>
#include <string>

#include "core/project/CompareLayout.h"
#include "core/project/Project.h"
#include "core/project/WedgeAxis.h"

namespace facet {

// Why sweeping `axis` changes nothing in any of `cells` (a project per cell across the other axis,
// that axis's value applied), or empty when it changes something in one of them.
std::string noEffectReasonInEvery(const WedgeAxis& axis, std::span<const Project> cells);

// The same for the rows' axis (`columnsAxis` false) or the columns' of `wedge` over `project`,
// across the other axis's cells; empty for a wedge without columns asked of its columns.
std::string sweepsNothing(const WedgeLayout& wedge, const Project& project, bool columnsAxis);

} // namespace facet
