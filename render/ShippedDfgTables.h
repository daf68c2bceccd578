#pragma once
// The split-sum DFG tables Facet ships as data, so that no process computes them on the GPU for
// the settings almost every scene uses (Filament ships its DFG LUT the same way): the `default`
// IBL preset's (dfgSize 32, dfgSamples 1024), one table for each visibility term V. They are
// core/shading/DfgTable's integration (the one ibl_dfg.frag computes in float, here in double) stored as
// binary16 RGBA, the layout of the GL table (row y = roughness, texel x = n.v: scale, bias,
// albedo, W). render/ShippedDfgTables.inc holds them, written by tests/tools/WriteDfgTables.cpp:
//
//   build/ci/tests/write_dfg_tables render/ShippedDfgTables.inc
//
// Each table is found by IblSettings::dfgHash(V), which holds the DFG algorithm's version: after
// a change to the integral the shipped tables stop matching any key (IblPrecompute::dfgTable
// computes the tables again, as for any other settings) and IblSettingsTest::shippedDfgTables
// fails until the file is written again.

#include "core/shading/ShadingModel.h"

#include <cstdint>
#include <span>

namespace facet {

struct ShippedDfgTable {
    std::uint64_t dfgHash = 0; // IblSettings::dfgHash(visibility) of the settings below
    int size = 0;
    int samples = 0;
    Visibility visibility = Visibility::SmithGGXCorrelated;
    const std::uint16_t* texels = nullptr; // size * size * 4 binary16 values
};

// Every shipped table.
std::span<const ShippedDfgTable> shippedDfgTables();
// The shipped table with this dfgHash, or nullptr.
const ShippedDfgTable* findShippedDfgTable(std::uint64_t dfgHash);

} // namespace facet
