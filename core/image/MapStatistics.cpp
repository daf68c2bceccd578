#include "core/image/MapStatistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace facet {

MapStatistics mapStatistics(const MapImage& image)
{
    MapStatistics statistics;
    if (!image.hasPixels())
        return statistics;
    const int channels = image.channels();
    statistics.channels.resize(std::size_t(channels));
    std::vector<double> sums(std::size_t(channels), 0.0);
    for (MapChannelStatistics& channel : statistics.channels) {
        channel.minimum = std::numeric_limits<float>::max();
        channel.maximum = std::numeric_limits<float>::lowest();
    }
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            for (int c = 0; c < channels; ++c) {
                const float value = image.sample(x, y, c);
                MapChannelStatistics& channel = statistics.channels[std::size_t(c)];
                const int bin = std::isfinite(value)
                    ? std::clamp(int(std::floor(value * float(MapChannelStatistics::kBins))), 0,
                        MapChannelStatistics::kBins - 1)
                    : 0;
                ++channel.histogram[std::size_t(bin)];
                channel.minimum = std::min(channel.minimum, value);
                channel.maximum = std::max(channel.maximum, value);
                sums[std::size_t(c)] += double(value);
            }
    const double count = double(image.width()) * double(image.height());
    for (int c = 0; c < channels; ++c)
        statistics.channels[std::size_t(c)].mean = count > 0.0 ? sums[std::size_t(c)] / count : 0.0;
    return statistics;
}

int storedChannelOf(MapChannel channel, MapLayout layout)
{
    const bool alpha = layout == MapLayout::GreyAlpha || layout == MapLayout::Rgba;
    switch (layout) {
    case MapLayout::Grey:
    case MapLayout::GreyAlpha:
        if (channel == MapChannel::A)
            return alpha ? 1 : -1;
        return 0;
    case MapLayout::RedGreen:
        return channel == MapChannel::R ? 0 : channel == MapChannel::G ? 1 : -1;
    case MapLayout::Rgb:
    case MapLayout::Rgba:
        switch (channel) {
        case MapChannel::R:
        case MapChannel::Rgb:
            return 0;
        case MapChannel::G:
            return 1;
        case MapChannel::B:
            return 2;
        case MapChannel::A:
            return alpha ? 3 : -1;
        }
    }
    return -1;
}

std::vector<MapSlot> slotsReadingChannel(
    const Material& material, const std::string& path, MapLayout layout, int channel)
{
    std::vector<MapSlot> slots;
    const int colourChannels
        = channelCount(layout) - ((layout == MapLayout::GreyAlpha || layout == MapLayout::Rgba) ? 1 : 0);
    for (MapSlot slot : kAllMapSlots) {
        const MaterialMap& map = material.map(slot);
        if (map.path != path || !material.usesSlot(slot))
            continue;
        const bool reads = map.channel == MapChannel::Rgb ? channel < colourChannels
                                                          : storedChannelOf(map.channel, layout) == channel;
        if (reads)
            slots.push_back(slot);
    }
    return slots;
}

} // namespace facet
