#include "render/MipChain.h"

#include "core/image/MapImage.h"
#include "core/image/ToneMap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace facet {

namespace {

int bytesPerSample(MipFilter filter)
{
    return filter == MipFilter::Unorm8 || filter == MipFilter::Srgb8 ? 1 : 2;
}

// sRGB decode of each 8-bit code (IEC 61966-2-1, core/image/ToneMap.h).
const std::array<float, 256>& srgbDecodeTable()
{
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t {};
        for (int i = 0; i < 256; ++i)
            t[std::size_t(i)] = float(tonemap::srgbToLinear(double(i) / 255.0));
        return t;
    }();
    return table;
}

// The nearest 8-bit sRGB code of each linear value quantised to 16 bits (the steepest part of
// the curve, slope 12.92 near 0, moves 0.05 code values per step: finer than the rounding).
const std::vector<std::uint8_t>& srgbEncodeTable()
{
    static const std::vector<std::uint8_t> table = [] {
        std::vector<std::uint8_t> t(65536);
        for (int i = 0; i < 65536; ++i)
            t[std::size_t(i)] = std::uint8_t(std::lround(tonemap::linearToSrgb(double(i) / 65535.0) * 255.0));
        return t;
    }();
    return table;
}

std::uint16_t load16(const unsigned char* at)
{
    std::uint16_t value = 0;
    std::memcpy(&value, at, sizeof value);
    return value;
}

void store16(unsigned char* at, std::uint16_t value)
{
    std::memcpy(at, &value, sizeof value);
}

} // namespace

MipChain::MipChain(const unsigned char* level0, int width, int height, int channels, MipFilter filter)
    : m_level0(level0)
    , m_channels(channels)
    , m_filter(filter)
{
    const int count = levelCount(width, height);
    for (int level = 0; level < count; ++level) {
        m_sizes.emplace_back(width, height);
        width = std::max(1, width / 2);
        height = std::max(1, height / 2);
    }
    m_levels.resize(m_sizes.size());
}

int MipChain::levelCount(int width, int height)
{
    int count = 1;
    for (int side = std::max(width, height); side > 1; side /= 2)
        ++count;
    return count;
}

std::size_t MipChain::rowBytes(int level) const
{
    return std::size_t(width(level)) * std::size_t(m_channels) * std::size_t(bytesPerSample(m_filter));
}

const unsigned char* MipChain::level(int level) const
{
    return level == 0 ? m_level0 : m_levels[std::size_t(level)].data();
}

void MipChain::releaseBelow(int level)
{
    for (int l = 1; l < level && l < levels(); ++l)
        m_levels[std::size_t(l)] = {};
}

void MipChain::computeRows(int level, int rowBegin, int rowEnd)
{
    std::vector<unsigned char>& target = m_levels[std::size_t(level)];
    if (target.empty())
        target.resize(rowBytes(level) * std::size_t(height(level)));
    const unsigned char* source = this->level(level - 1);
    const int sourceWidth = width(level - 1);
    const int sourceHeight = height(level - 1);
    const std::size_t sourceRow = rowBytes(level - 1);
    const int bytes = bytesPerSample(m_filter);
    const int channels = m_channels;
    const auto& decode = srgbDecodeTable();
    const auto& encode = srgbEncodeTable();
    for (int y = rowBegin; y < rowEnd; ++y) {
        const unsigned char* row0 = source + sourceRow * std::size_t(std::min(2 * y, sourceHeight - 1));
        const unsigned char* row1 = source + sourceRow * std::size_t(std::min(2 * y + 1, sourceHeight - 1));
        unsigned char* out = target.data() + rowBytes(level) * std::size_t(y);
        for (int x = 0; x < width(level); ++x) {
            const std::size_t a
                = std::size_t(std::min(2 * x, sourceWidth - 1)) * std::size_t(channels * bytes);
            const std::size_t b
                = std::size_t(std::min(2 * x + 1, sourceWidth - 1)) * std::size_t(channels * bytes);
            for (int c = 0; c < channels; ++c) {
                const std::size_t o = std::size_t(c * bytes);
                unsigned char* result
                    = out + (std::size_t(x) * std::size_t(channels) + std::size_t(c)) * std::size_t(bytes);
                switch (m_filter) {
                case MipFilter::Srgb8:
                    if (c < 3) { // colour: averaged in linear light
                        const float linear = 0.25f
                            * (decode[row0[a + o]] + decode[row0[b + o]] + decode[row1[a + o]]
                                + decode[row1[b + o]]);
                        *result = encode[std::size_t(std::lround(std::clamp(linear, 0.0f, 1.0f) * 65535.0f))];
                        break;
                    }
                    [[fallthrough]]; // alpha: linear
                case MipFilter::Unorm8:
                    *result = std::uint8_t(
                        (unsigned(row0[a + o]) + row0[b + o] + row1[a + o] + row1[b + o] + 2) / 4);
                    break;
                case MipFilter::Unorm16:
                    store16(result,
                        std::uint16_t((std::uint32_t(load16(row0 + a + o)) + load16(row0 + b + o)
                                          + load16(row1 + a + o) + load16(row1 + b + o) + 2)
                            / 4));
                    break;
                case MipFilter::Half:
                    store16(result,
                        MapImage::toHalf(0.25f
                            * (MapImage::fromHalf(load16(row0 + a + o))
                                + MapImage::fromHalf(load16(row0 + b + o))
                                + MapImage::fromHalf(load16(row1 + a + o))
                                + MapImage::fromHalf(load16(row1 + b + o)))));
                    break;
                }
            }
        }
    }
}

} // namespace facet
