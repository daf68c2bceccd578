#include "core/image/MapImage.h"

#include "core/image/ImageReader.h"
#include "core/image/ToneMap.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

#include <QtGlobal>

#include <glm/gtc/packing.hpp>

namespace facet {

namespace {

std::atomic<std::uint64_t> g_loads {0};

// A positive whole number from an environment variable; 0 when unset or not one (*bad says so).
long long positiveFromEnvironment(const char* name, bool* bad)
{
    const char* text = std::getenv(name);
    *bad = false;
    if (!text || !*text)
        return 0;
    char* end = nullptr;
    const long long value = std::strtoll(text, &end, 10);
    if (*end != '\0' || value <= 0) {
        *bad = true;
        return 0;
    }
    return value;
}

// Sanitises one float sample before it becomes half, as Image::sanitize does; `alpha` says
// whether the channel is coverage.
float sanitized(float value, bool alpha, ImageLoadStats& stats)
{
    if (alpha) {
        if (std::isnan(value)) {
            ++stats.nanCount;
            return 1.0f;
        }
        if (std::isinf(value))
            ++stats.infCount;
        else if (value < 0.0f)
            ++stats.negativeCount;
        return std::clamp(value, 0.0f, 1.0f);
    }
    if (std::isnan(value)) {
        ++stats.nanCount;
        return 0.0f;
    }
    if (std::isinf(value)) {
        ++stats.infCount;
        return value > 0.0f ? kLargestHalf : 0.0f;
    }
    if (value < 0.0f) {
        ++stats.negativeCount;
        return 0.0f;
    }
    // Finite but beyond binary16: the largest half, not the Inf a conversion would make.
    return std::min(value, kLargestHalf);
}

bool isAlphaChannel(MapLayout layout, int channel)
{
    return (layout == MapLayout::GreyAlpha && channel == 1) || (layout == MapLayout::Rgba && channel == 3);
}

} // namespace

const char* toString(MapSampleType type)
{
    switch (type) {
    case MapSampleType::UInt8:
        return "8-bit";
    case MapSampleType::UInt16:
        return "16-bit";
    case MapSampleType::Half:
        break;
    }
    return "half";
}

const char* toString(MapLayout layout)
{
    switch (layout) {
    case MapLayout::Grey:
        return "grey";
    case MapLayout::GreyAlpha:
        return "grey+alpha";
    case MapLayout::RedGreen:
        return "red+green";
    case MapLayout::Rgb:
        return "RGB";
    case MapLayout::Rgba:
        break;
    }
    return "RGBA";
}

MapBudget MapBudget::fromEnvironment(std::string* warning)
{
    MapBudget budget;
    bool bad = false;
    if (const long long side = positiveFromEnvironment("FACET_MAX_MAP_SIZE", &bad); side > 0)
        budget.maxSide = int(std::min<long long>(side, MapBudget::kLargestMaxSide));
    if (bad && warning)
        *warning
            = "FACET_MAX_MAP_SIZE is not a positive whole number: using " + std::to_string(kDefaultMaxSide);
    if (const long long mpixels = positiveFromEnvironment("FACET_MAX_MAP_MPIXELS", &bad); mpixels > 0)
        budget.maxPixels = std::size_t(std::min<long long>(mpixels, 1 << 20)) << 20;
    if (bad && warning)
        *warning = "FACET_MAX_MAP_MPIXELS is not a positive whole number: using "
            + std::to_string(kDefaultMaxPixels >> 20);
    return budget;
}

std::string MapBudget::check(int width, int height) const
{
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width > maxSide || height > maxSide)
        return size + " is larger than the map size limit of " + std::to_string(maxSide)
            + " pixels per side (FACET_MAX_MAP_SIZE)";
    if (std::size_t(width) * std::size_t(height) > maxPixels)
        return size + " is larger than the map size limit of " + std::to_string(maxPixels >> 20)
            + " Mpixel (FACET_MAX_MAP_MPIXELS)";
    return {};
}

MapImage::MapImage(int width, int height, MapLayout layout, MapSampleType type)
    : m_width(std::max(width, 0))
    , m_height(std::max(height, 0))
    , m_layout(layout)
    , m_type(type)
    , m_sourceChannels(channelCount(layout))
{
    Q_ASSERT(width >= 0 && height >= 0);
    m_bytes.assign(rowBytes() * std::size_t(m_height), 0);
}

MapImage MapImage::withoutPixels(const MapImage& image)
{
    MapImage standIn;
    standIn.m_width = image.m_width;
    standIn.m_height = image.m_height;
    standIn.m_layout = image.m_layout;
    standIn.m_type = image.m_type;
    standIn.m_encoding = image.m_encoding;
    standIn.m_colorSpaceName = image.m_colorSpaceName;
    standIn.m_sourceChannels = image.m_sourceChannels;
    standIn.m_sampleRange = image.m_sampleRange;
    return standIn;
}

MapImage MapImage::fromImage(const Image& image, MapLayout layout, MapSampleType type)
{
    MapImage map(image.width(), image.height(), layout, type);
    map.m_encoding = image.encoding();
    map.m_colorSpaceName = image.colorSpaceName();
    // Which of the Image's RGBA channels each stored channel takes.
    int source[4] = {0, 1, 2, 3};
    if (layout == MapLayout::GreyAlpha)
        source[1] = 3;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const glm::vec4& pixel = image.at(x, y);
            for (int c = 0; c < map.channels(); ++c)
                map.setSample(x, image.height() - 1 - y, c, pixel[source[c]]);
        }
    map.measureSampleRanges();
    return map;
}

void MapImage::measureSampleRanges()
{
    std::array<glm::vec2, 4> range;
    range.fill(glm::vec2(std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest()));
    const int n = channels();
    for (int y = 0; y < m_height; ++y)
        for (int x = 0; x < m_width; ++x)
            for (int c = 0; c < n; ++c) {
                const float value = sample(x, y, c);
                range[std::size_t(c)].x = std::min(range[std::size_t(c)].x, value);
                range[std::size_t(c)].y = std::max(range[std::size_t(c)].y, value);
            }
    m_sampleRange = isEmpty() ? std::nullopt : std::optional(range);
}

std::optional<glm::vec2> MapImage::texelRange(int component) const
{
    if (!m_sampleRange || component < 0 || component > 3)
        return std::nullopt;
    const auto stored = [this](int channel) { return (*m_sampleRange)[std::size_t(channel)]; };
    const glm::vec2 one(1.0f);
    switch (m_layout) {
    case MapLayout::Grey:
        return component < 3 ? stored(0) : one;
    case MapLayout::GreyAlpha:
        return component < 3 ? stored(0) : stored(1);
    case MapLayout::RedGreen:
        return component < 2 ? stored(component) : component == 2 ? glm::vec2(0.0f) : one;
    case MapLayout::Rgb:
        return component < 3 ? stored(component) : one;
    case MapLayout::Rgba:
        break;
    }
    return stored(component);
}

std::uint64_t MapImage::loadCount()
{
    return g_loads.load();
}

std::uint16_t MapImage::toHalf(float value)
{
    return glm::packHalf1x16(value);
}

float MapImage::fromHalf(std::uint16_t bits)
{
    return glm::unpackHalf1x16(bits);
}

std::uint16_t MapImage::linearHalfFromSrgb(float encoded)
{
    return toHalf(float(tonemap::srgbToLinear(double(encoded))));
}

float MapImage::sample(int x, int rowFromBottom, int channel) const
{
    const unsigned char* at = m_bytes.data() + offset(x, rowFromBottom, channel);
    if (m_type == MapSampleType::UInt8)
        return float(*at) / 255.0f;
    std::uint16_t bits = 0;
    std::memcpy(&bits, at, sizeof bits);
    return m_type == MapSampleType::UInt16 ? float(bits) / 65535.0f : fromHalf(bits);
}

void MapImage::setSample(int x, int rowFromBottom, int channel, float value)
{
    m_sampleRange.reset();
    unsigned char* at = m_bytes.data() + offset(x, rowFromBottom, channel);
    const float unit = std::isnan(value) ? 0.0f : std::clamp(value, 0.0f, 1.0f);
    if (m_type == MapSampleType::UInt8) {
        *at = static_cast<unsigned char>(std::lround(unit * 255.0f));
        return;
    }
    const std::uint16_t bits = m_type == MapSampleType::UInt16
        ? static_cast<std::uint16_t>(std::lround(unit * 65535.0f))
        : toHalf(value);
    std::memcpy(at, &bits, sizeof bits);
}

glm::vec4 MapImage::texel(int x, int rowFromBottom) const
{
    const auto s = [&](int c) { return sample(x, rowFromBottom, c); };
    switch (m_layout) {
    case MapLayout::Grey: {
        const float g = s(0);
        return {g, g, g, 1.0f};
    }
    case MapLayout::GreyAlpha: {
        const float g = s(0);
        return {g, g, g, s(1)};
    }
    case MapLayout::RedGreen:
        return {s(0), s(1), 0.0f, 1.0f};
    case MapLayout::Rgb:
        return {s(0), s(1), s(2), 1.0f};
    case MapLayout::Rgba:
        break;
    }
    return {s(0), s(1), s(2), s(3)};
}

std::optional<MapImage> MapImage::load(
    const std::string& path, std::string* error, ImageLoadStats* stats, const MapBudget& budget)
{
    constexpr const char* kFunction = "MapImage::load";
    ++g_loads;
    if (stats)
        *stats = {};
    try {
        std::optional<ImageReader> reader = ImageReader::open(path, kFunction, error);
        if (!reader)
            return std::nullopt;
        const CodecHeader& spec = reader->header();
        // Only the header has been read: refuse what is too large before allocating anything.
        if (!reader->checkHeader(kFunction, error))
            return std::nullopt;
        if (const std::string problem = budget.check(spec.width, spec.height); !problem.empty()) {
            setImageError(error, kFunction, path, problem);
            return std::nullopt;
        }
        if (spec.width > Image::kMaxDimension || spec.height > Image::kMaxDimension) {
            setImageError(error, kFunction, path,
                std::to_string(spec.width) + "x" + std::to_string(spec.height) + " exceeds the limit of "
                    + std::to_string(Image::kMaxDimension) + " pixels per side");
            return std::nullopt;
        }
        if (!reader->checkSizeAgainstFile(kFunction, error))
            return std::nullopt;

        MapSampleType type = MapSampleType::UInt16;
        switch (spec.sample) {
        case CodecSample::UInt8:
            type = MapSampleType::UInt8;
            break;
        case CodecSample::Half:
        case CodecSample::Float:
        case CodecSample::Double:
            type = MapSampleType::Half;
            break;
        default:
            break; // 16-bit, and the rare other integers (signed, 32-bit) as 16-bit unsigned
        }
        MapLayout layout = MapLayout::Rgba;
        switch (std::min(spec.channels, 4)) {
        case 1:
            layout = MapLayout::Grey;
            break;
        case 2:
            layout = reader->twoColourChannels() ? MapLayout::RedGreen : MapLayout::GreyAlpha;
            break;
        case 3:
            layout = MapLayout::Rgb;
            break;
        default:
            break;
        }

        MapImage map(spec.width, spec.height, layout, type);
        map.m_sourceChannels = spec.channels;
        map.m_colorSpaceName = reader->colorSpaceName();
        map.m_encoding = reader->encoding();
        const int channels = map.channels();

        if (type == MapSampleType::Half) {
            // Float files are read as float, sanitised (as environments are), then halved: a
            // conversion straight to half would turn large finite values into Inf.
            std::vector<float> floats(map.pixelCount() * std::size_t(channels));
            if (!reader->readAll(channels, CodecSample::Float, floats.data(), 0, 0, kFunction, error))
                return std::nullopt;
            ImageLoadStats replaced;
            const std::size_t rowSamples = std::size_t(map.width()) * std::size_t(channels);
            std::vector<std::uint16_t> halves(rowSamples);
            for (int y = 0; y < map.height(); ++y) {
                const float* source = floats.data() + std::size_t(y) * rowSamples;
                for (std::size_t i = 0; i < rowSamples; ++i)
                    halves[i] = toHalf(sanitized(
                        source[i], isAlphaChannel(layout, int(i % std::size_t(channels))), replaced));
                std::memcpy(map.m_bytes.data() + map.rowBytes() * std::size_t(map.height() - 1 - y),
                    halves.data(), map.rowBytes());
            }
            if (stats)
                *stats = replaced;
        } else {
            // Straight into the texels (OIIO converts other integer types to 16-bit), then
            // flipped in place so that row 0 is the bottom.
            const CodecSample as = type == MapSampleType::UInt8 ? CodecSample::UInt8 : CodecSample::UInt16;
            if (!reader->readAll(channels, as, map.m_bytes.data(), 0, 0, kFunction, error))
                return std::nullopt;
            std::vector<unsigned char> swap(map.rowBytes());
            for (int y = 0; y < map.height() / 2; ++y) {
                unsigned char* top = map.m_bytes.data() + map.rowBytes() * std::size_t(y);
                unsigned char* bottom
                    = map.m_bytes.data() + map.rowBytes() * std::size_t(map.height() - 1 - y);
                std::memcpy(swap.data(), top, swap.size());
                std::memcpy(top, bottom, swap.size());
                std::memcpy(bottom, swap.data(), swap.size());
            }
        }
        map.measureSampleRanges();
        return map;
    } catch (...) {
        setImageErrorFromException(error, kFunction, path, "reading");
    }
    return std::nullopt;
}

} // namespace facet
