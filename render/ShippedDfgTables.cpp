#include "render/ShippedDfgTables.h"

#include <algorithm>

namespace facet {

namespace {
#include "render/ShippedDfgTables.inc"
} // namespace

std::span<const ShippedDfgTable> shippedDfgTables()
{
    return kShippedDfgTables;
}

const ShippedDfgTable* findShippedDfgTable(std::uint64_t dfgHash)
{
    const auto tables = shippedDfgTables();
    const auto it = std::find_if(
        tables.begin(), tables.end(), [&](const ShippedDfgTable& table) { return table.dfgHash == dfgHash; });
    return it == tables.end() ? nullptr : &*it;
}

} // namespace facet
