#pragma once
// A material map's pixels as the file stores them: its own channel count (grey, grey + alpha,
// red + green, RGB, RGBA) and bit depth (8-bit, 16-bit, or half float for float files), so an
// 8-bit 2048² JPEG costs 12 MiB in memory instead of 64 MiB as float RGBA, and goes to the GPU
// as 8 bits (render/TextureCache). Environments stay float (core/image/Image).
//
// Rows are stored bottom to top (OpenGL's order): row 0 is the image's BOTTOM row, so texture
// coordinate (0, 0) is texel (0, 0) (core/mesh/Mesh.h UV convention) and a band of rows uploads
// without a copy. Files store the top row first; load() flips.
//
// What a texture read returns (texel(); the GPU reads the same through the swizzle
// render/TextureCache sets): grey g -> (g, g, g, 1); grey + alpha -> (g, g, g, a); red + green ->
// (r, g, 0, 1); RGB -> (r, g, b, 1); RGBA as stored. 8- and 16-bit samples are unsigned
// normalised (v / 255, v / 65535), half samples are IEEE 754 binary16.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "core/image/Image.h"

namespace facet {

enum class MapSampleType : std::uint8_t { UInt8, UInt16, Half };
enum class MapLayout : std::uint8_t { Grey, GreyAlpha, RedGreen, Rgb, Rgba };

constexpr int channelCount(MapLayout layout)
{
    switch (layout) {
    case MapLayout::Grey:
        return 1;
    case MapLayout::GreyAlpha:
    case MapLayout::RedGreen:
        return 2;
    case MapLayout::Rgb:
        return 3;
    case MapLayout::Rgba:
        break;
    }
    return 4;
}
constexpr int bytesPerSample(MapSampleType type)
{
    return type == MapSampleType::UInt8 ? 1 : 2;
}
const char* toString(MapSampleType type); // "8-bit", "16-bit", "half"
const char* toString(MapLayout layout); // "grey", "grey+alpha", "red+green", "RGB", "RGBA"

// The largest map Facet decodes: a map beyond it is refused from its header, before a pixel is
// allocated or decoded, with a message naming the file (docs/app.md, "Texture maps: limits").
// 8192 per side and 64 Mpixel by default (an 8192² RGBA8 map: 256 MiB in memory, ~340 MiB on the
// GPU with its mipmaps). FACET_MAX_MAP_SIZE (pixels per side, at most 16384: the
// GL_MAX_TEXTURE_SIZE every OpenGL 4.x implementation offers, so a map within the budget is a map
// the GPU takes) and FACET_MAX_MAP_MPIXELS (millions of pixels) change it.
struct MapBudget {
    static constexpr int kDefaultMaxSide = 8192;
    static constexpr int kLargestMaxSide = 16384;
    static constexpr std::size_t kDefaultMaxPixels = std::size_t(64) << 20;

    int maxSide = kDefaultMaxSide;
    std::size_t maxPixels = kDefaultMaxPixels;

    // The defaults, changed by the environment variables above where they hold a positive whole
    // number (a bad value is ignored and named in *warning).
    static MapBudget fromEnvironment(std::string* warning = nullptr);
    // Empty when a width x height map fits, else the problem, e.g. "16384x16384 is larger than
    // the map size limit of 8192 pixels per side (FACET_MAX_MAP_SIZE)".
    std::string check(int width, int height) const;
};

class MapImage {
public:
    MapImage() = default;
    // width x height texels of zeros.
    MapImage(int width, int height, MapLayout layout, MapSampleType type);
    // `image`'s pixels (top row first, as Image stores them) in `layout` and `type`: channels the
    // layout has not are dropped (grey keeps red, grey + alpha red and alpha), values quantised
    // (round to nearest; integers clamped to [0, 1]). For tests and callers that made pixels.
    static MapImage fromImage(const Image& image, MapLayout layout, MapSampleType type);

    int width() const { return m_width; }
    int height() const { return m_height; }
    bool isEmpty() const { return m_width == 0 || m_height == 0; }
    // Whether the samples are here. A stand-in (withoutPixels) has the size, layout and sample
    // type of the map the GPU holds but no samples: the window keeps one for a map whose texture
    // is complete, so that the decoded copy's memory is freed (ui/viewport/SceneController
    // releaseMapPixels); reading its samples is an error.
    bool hasPixels() const { return !m_bytes.empty(); }
    static MapImage withoutPixels(const MapImage& image);
    std::size_t pixelCount() const { return std::size_t(m_width) * std::size_t(m_height); }
    MapLayout layout() const { return m_layout; }
    int channels() const { return channelCount(m_layout); }
    MapSampleType sampleType() const { return m_type; }
    std::size_t bytesPerTexel() const
    {
        return std::size_t(channels()) * std::size_t(bytesPerSample(m_type));
    }
    std::size_t rowBytes() const { return bytesPerTexel() * std::size_t(m_width); }
    std::size_t byteSize() const { return m_bytes.size(); }

    // The samples, rows bottom to top, channels interleaved, no padding; 16-bit and half samples
    // in the machine's byte order.
    const unsigned char* data() const { return m_bytes.data(); }
    unsigned char* data()
    {
        m_sampleRange.reset(); // written through: the range is no longer known
        return m_bytes.data();
    }
    const unsigned char* row(int rowFromBottom) const
    {
        return m_bytes.data() + rowBytes() * std::size_t(rowFromBottom);
    }

    // Stored sample `channel` (< channels()) of texel (x, row from the bottom), as a float.
    float sample(int x, int rowFromBottom, int channel) const;
    void setSample(int x, int rowFromBottom, int channel, float value); // quantised as fromImage
    // What a linear texture read returns for the texel (layout expanded, see the top).
    glm::vec4 texel(int x, int rowFromBottom) const;
    // The smallest and largest value component `component` (0-3) of texel() takes over the map,
    // as stored (no colour decoding): known for maps made by load() and fromImage() (and kept by
    // withoutPixels), nullopt once the samples were written otherwise. The renderer reads a
    // roughness map's smallest value from it (render/Renderer.cpp, the split sum's sharp lobes).
    std::optional<glm::vec2> texelRange(int component) const;
    // Measures the stored samples' ranges (load() and fromImage() call it).
    void measureSampleRanges();

    // As Image: what the file's numbers mean, its colour-space name, its channel count.
    ColorEncoding encoding() const { return m_encoding; }
    void setEncoding(ColorEncoding encoding) { m_encoding = encoding; }
    const std::string& colorSpaceName() const { return m_colorSpaceName; }
    int sourceChannels() const { return m_sourceChannels; }

    // Reads a map as the file stores it: 8-bit files stay 8-bit, 16-bit ones 16-bit, float ones
    // (half, float, double) become half floats, other integers 16-bit; 1 channel is grey, 2 grey
    // + alpha (red + green when named R, G), 3 RGB, 4 or more the first four. Alpha unassociated.
    // Embedded glTF images ("asset.glb#images/N") are read from memory (core/image/ImageReader.h).
    // Refused from the header, before any pixel is allocated: a size beyond `budget` (and
    // Image::kMaxDimension), volumes, images without channels. Half samples are sanitised as
    // Image::sanitize does (NaN, Inf, negative colour; alpha NaN -> 1, clamped to [0, 1]; finite
    // values beyond the half range clamped to 65504), counted in `stats`; integer samples need
    // nothing. Errors: "MapImage::load: <path>: <reason>".
    static std::optional<MapImage> load(const std::string& path, std::string* error,
        ImageLoadStats* stats = nullptr, const MapBudget& budget = MapBudget::fromEnvironment());

    // How many times load() has been called in this process, from any thread (tests: "each file
    // is decoded once", whoever asks for it).
    static std::uint64_t loadCount();

    // binary16 <-> float (glm's packHalf1x16: round to nearest).
    static std::uint16_t toHalf(float value);
    static float fromHalf(std::uint16_t bits);
    // The half float a texture holds for an sRGB-encoded `encoded` value that is not 8-bit: the
    // upload decodes 16-bit and half sRGB maps to linear half floats (OpenGL has no 16-bit sRGB
    // format), and the CPU twin reads the same (core/shading/MaterialInputs.h).
    static std::uint16_t linearHalfFromSrgb(float encoded);

private:
    std::size_t offset(int x, int rowFromBottom, int channel) const
    {
        return rowBytes() * std::size_t(rowFromBottom) + bytesPerTexel() * std::size_t(x)
            + std::size_t(channel) * std::size_t(bytesPerSample(m_type));
    }

    int m_width = 0;
    int m_height = 0;
    MapLayout m_layout = MapLayout::Rgba;
    MapSampleType m_type = MapSampleType::UInt8;
    std::vector<unsigned char> m_bytes;
    ColorEncoding m_encoding = ColorEncoding::Linear;
    std::string m_colorSpaceName;
    int m_sourceChannels = 4;
    std::optional<std::array<glm::vec2, 4>> m_sampleRange; // per stored channel: min, max
};

} // namespace facet
