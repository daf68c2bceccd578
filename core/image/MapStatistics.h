#pragma once
// What a map's channels hold, for the Texture Maps dock's Inspect Map (docs/app.md "Texture
// Maps"): per stored channel a histogram of the values as stored (no colour decoding: the numbers
// a painter wrote), their smallest, largest and mean value, and which of a material's slots read
// that channel of the file (an ORM texture: R feeds occlusion, G roughness, B metallic).

#include <array>
#include <string>
#include <vector>

#include "core/image/MapImage.h"
#include "core/material/Material.h"

namespace facet {

struct MapChannelStatistics {
    static constexpr int kBins = 256;
    // Texels whose value v falls in [i / kBins, (i + 1) / kBins); values below 0 count in bin 0
    // and values of 1 or more (half-float maps) in the last.
    std::array<std::uint64_t, kBins> histogram {};
    float minimum = 0.0f;
    float maximum = 0.0f;
    double mean = 0.0;
};

struct MapStatistics {
    std::vector<MapChannelStatistics> channels; // one per stored channel (MapImage::channels())
};

// The statistics of every stored channel of `image` (empty for a stand-in without pixels).
MapStatistics mapStatistics(const MapImage& image);

// The stored channel each MapChannel reads of a map in `layout` (grey's "r", "g" and "b" all read
// its one channel; "a" of a layout without alpha reads none: -1).
int storedChannelOf(MapChannel channel, MapLayout layout);

// Which of `material`'s slots read stored channel `channel` (of a map in `layout`) of the file
// at `path`: a slot reading "rgb" reads every colour channel. In MapSlot order.
std::vector<MapSlot> slotsReadingChannel(
    const Material& material, const std::string& path, MapLayout layout, int channel);

} // namespace facet
