#pragma once
// A float RGBA image in memory, and its loading/saving through OpenImageIO.
// Pixels are row-major from the top row (row 0 is the image's top, as files store it).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec4.hpp>

namespace facet {

// The largest finite IEEE 754 binary16 value: what the half-float copies of images (RGBA16F
// textures, half EXR files) hold at most. +Inf and finite samples beyond it become this, not the
// Inf a conversion would make, so a sanitised image survives a round trip through them unchanged.
inline constexpr float kLargestHalf = 65504.0f;

// How the numbers in an image relate to light. Colour data files are usually sRGB-encoded
// (8-bit PNG/JPEG); HDR formats and data maps (normal, roughness...) are linear.
enum class ColorEncoding { Linear, SRGB };

struct ImageLoadStats {
    std::size_t nanCount = 0; // NaN samples replaced by 0
    std::size_t infCount = 0; // +-Inf samples replaced by the largest finite half value (+) or 0 (-)
    std::size_t negativeCount = 0; // negative colour samples clamped to 0
    std::size_t total() const { return nanCount + infCount + negativeCount; }
};

class Image {
public:
    // Refused before allocating (and before decoding): a texture larger than this is a mistake
    // or an attack, not an artist's texture.
    static constexpr int kMaxDimension = 32768;
    static constexpr std::size_t kMaxPixels = std::size_t(1) << 28; // 256 Mpixel, 4 GiB as RGBA32F

    Image() = default;
    Image(int width, int height, glm::vec4 fill = glm::vec4(0.0f));

    int width() const { return m_width; }
    int height() const { return m_height; }
    bool isEmpty() const { return m_width == 0 || m_height == 0; }
    std::size_t pixelCount() const { return std::size_t(m_width) * std::size_t(m_height); }

    glm::vec4& at(int x, int y) { return m_pixels[std::size_t(y) * std::size_t(m_width) + std::size_t(x)]; }
    const glm::vec4& at(int x, int y) const
    {
        return m_pixels[std::size_t(y) * std::size_t(m_width) + std::size_t(x)];
    }
    glm::vec4* data() { return m_pixels.data(); }
    const glm::vec4* data() const { return m_pixels.data(); }

    // What the file's numbers mean (from its metadata or format); colour maps may be converted
    // to linear by the caller with toLinear().
    ColorEncoding encoding() const { return m_encoding; }
    void setEncoding(ColorEncoding encoding) { m_encoding = encoding; }
    // The file's colour-space name as OpenImageIO reported it ("sRGB", "Linear", ...), if any.
    const std::string& colorSpaceName() const { return m_colorSpaceName; }
    void setColorSpaceName(std::string name) { m_colorSpaceName = std::move(name); }
    int sourceChannels() const { return m_sourceChannels; }
    void setSourceChannels(int channels) { m_sourceChannels = channels; }

    // Decodes sRGB to linear with the exact piecewise sRGB EOTF (IEC 61966-2-1), RGB only (alpha
    // is linear already), and sets encoding() to Linear. No-op on linear images.
    void toLinear();

    // Replaces NaN, Inf and negative RGB samples (NaN -> 0, +Inf -> 65504, -Inf -> 0, negative -> 0;
    // alpha: NaN -> 1, clamped to [0,1]); returns what it did (alpha NaN/Inf/negative counted too,
    // alpha above 1 clamped silently).
    ImageLoadStats sanitize();

    // Reads any format OpenImageIO reads (subimage 0, mip level 0, the data window). Missing
    // channels are filled: 1 channel -> grey RGB, alpha 1; 2 -> grey + alpha (unless named R, G:
    // red, green, blue 0); 3 -> RGB, alpha 1; 4 or more -> the first four. Alpha is returned
    // unassociated (not premultiplied), as PNG/TIFF store it.
    // The size in the header is checked before any pixel is allocated (kMaxDimension, kMaxPixels).
    // encoding(): SRGB when the file's colour space says sRGB (or a gamma curve), Linear when it
    // says linear; without either, 8/16-bit integer files are SRGB (PNG, JPEG, WebP, TGA, TIFF as
    // painting tools write them) and float files (EXR, HDR, float TIFF) Linear. Nothing is
    // converted: a caller that wants linear values calls toLinear().
    // The pixels are sanitize()d. On failure returns nullopt and sets `error` to
    // "Image::load: <path>: <reason>". `stats` receives what sanitisation replaced; a caller
    // shows it as a warning.
    static std::optional<Image> load(
        const std::string& path, std::string* error, ImageLoadStats* stats = nullptr);

    // Reads `path` a band of rows at a time into a box-filtered copy (each output pixel the mean
    // of the source pixels under it; the bins of Image::boxFiltered), never holding the whole
    // image: a thumbnail of an 8K HDRI costs a band, not 512 MiB of floats. `sizeFor(width,
    // height)` gives the output size from the file's; the samples are load()'s (sanitised), and
    // sRGB-encoded files are decoded to linear first when `linear` (as Environment::load does).
    // *sourceWidth / *sourceHeight get the file's size, `stats` what sanitisation replaced.
    // Memory: the output, one band of about a million source texels and a row of sums. Errors as
    // load()'s.
    static std::optional<Image> loadBoxFiltered(const std::string& path, bool linear,
        const std::function<std::pair<int, int>(int width, int height)>& sizeFor, std::string* error,
        int* sourceWidth = nullptr, int* sourceHeight = nullptr, ImageLoadStats* stats = nullptr);
    // The same filter over an image in memory.
    Image boxFiltered(int width, int height) const;

    // Writes through OpenImageIO by extension: .exr gets linear half floats (RGBA, or RGB when
    // `alpha` is false; values clamped to the finite half range), .hdr/.pfm floats, every other
    // format 8 bits with the values as they are, clamped to [0,1] (the caller encodes; an SRGB
    // image is tagged sRGB; alpha is written unassociated, and dropped where the format has none).
    // OpenImageIO encodes into memory and the bytes go through writeFileAtomically
    // (core/support/AtomicFile.h: a checked "<path>.tmp-XXXXXX" in the same folder, then a rename), so a
    // failed write, a full disk included, never leaves half a file nor harms an existing one.
    // Formats OpenImageIO cannot encode into memory (sgi, ico, rla, fits, heif) are refused.
    // Errors: "Image::save: <path>: <reason>", e.g. "...: cannot write: No space left on device".
    // `attributes`: string metadata for formats that hold it (EXR header attributes, PNG text),
    // e.g. a contact sheet's cell layout.
    bool save(const std::string& path, std::string* error, bool alpha = true,
        const std::vector<std::pair<std::string, std::string>>& attributes = {}) const;

private:
    int m_width = 0;
    int m_height = 0;
    std::vector<glm::vec4> m_pixels;
    ColorEncoding m_encoding = ColorEncoding::Linear;
    std::string m_colorSpaceName;
    int m_sourceChannels = 4;
};

} // namespace facet
