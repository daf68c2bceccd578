#include "core/image/Image.h"

#include "core/support/AtomicFile.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include <QtGlobal>

#include "core/image/ImageReader.h"
#include "core/image/ImageWriter.h"

namespace facet {

namespace {

// The sRGB EOTF, IEC 61966-2-1:1999 section 4.2 (piecewise: linear toe below 0.04045).
float srgbToLinear(float encoded)
{
    if (encoded <= 0.04045f)
        return encoded / 12.92f;
    return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

} // namespace

Image::Image(int width, int height, glm::vec4 fill)
    : m_width(std::max(width, 0))
    , m_height(std::max(height, 0))
{
    Q_ASSERT(width >= 0 && height >= 0);
    m_pixels.assign(pixelCount(), fill);
}

void Image::toLinear()
{
    if (m_encoding == ColorEncoding::Linear)
        return;
    for (glm::vec4& pixel : m_pixels) {
        pixel.x = srgbToLinear(pixel.x);
        pixel.y = srgbToLinear(pixel.y);
        pixel.z = srgbToLinear(pixel.z);
    }
    m_encoding = ColorEncoding::Linear;
}

ImageLoadStats Image::sanitize()
{
    // Radiance is finite and non-negative; everything downstream (prefiltering, SH projection,
    // importance sampling, the half-float GPU copy) assumes it. Negative values come from
    // lossy EXR compression ringing around bright suns (DWAA/DWAB), NaN/Inf from broken
    // renders; a single one would spread over a whole prefiltered mip level.
    ImageLoadStats stats;
    for (glm::vec4& pixel : m_pixels) {
        for (int c = 0; c < 3; ++c) {
            float& value = pixel[c];
            if (std::isnan(value)) {
                value = 0.0f;
                ++stats.nanCount;
            } else if (std::isinf(value)) {
                value = value > 0.0f ? kLargestHalf : 0.0f;
                ++stats.infCount;
            } else if (value < 0.0f) {
                value = 0.0f;
                ++stats.negativeCount;
            }
        }
        // Alpha is a coverage in [0,1]: NaN means nothing sensible, so opaque; Inf and negative
        // values are counted like colour, values just above 1 (filtering overshoot) are clamped
        // without a count.
        float& alpha = pixel.w;
        if (std::isnan(alpha)) {
            alpha = 1.0f;
            ++stats.nanCount;
        } else {
            if (std::isinf(alpha))
                ++stats.infCount;
            else if (alpha < 0.0f)
                ++stats.negativeCount;
            alpha = std::clamp(alpha, 0.0f, 1.0f);
        }
    }
    return stats;
}

namespace {

// Fills what the file does not have. Two channels are grey + alpha (what PNG and TIFF mean by
// two channels), unless they are named R and G (a two-channel EXR, e.g. a normal map's X and Y),
// which stay red and green.
void fillMissingChannels(std::vector<glm::vec4>& pixels, int channels, bool twoColourChannels)
{
    for (glm::vec4& pixel : pixels) {
        switch (channels) {
        case 1:
            pixel = glm::vec4(pixel.x, pixel.x, pixel.x, 1.0f);
            break;
        case 2:
            pixel = twoColourChannels ? glm::vec4(pixel.x, pixel.y, 0.0f, 1.0f)
                                      : glm::vec4(pixel.x, pixel.x, pixel.x, pixel.y);
            break;
        case 3:
            pixel.w = 1.0f;
            break;
        default:
            break;
        }
    }
}

// For each of `outputs` bins over `inputs` source texels, where it starts: bin i covers
// [i * inputs / outputs, max(start + 1, (i + 1) * inputs / outputs)) (outputs <= inputs: the
// bins tile the source).
int binStart(int i, int inputs, int outputs)
{
    return int(std::int64_t(i) * inputs / outputs);
}

} // namespace

namespace {

// The bins of the box filter along one axis: output i averages source texels [begin[i], end[i]).
struct Bins {
    std::vector<int> begin;
    std::vector<int> end;
    Bins(int inputs, int outputs)
        : begin(std::size_t(outputs))
        , end(std::size_t(outputs))
    {
        for (int i = 0; i < outputs; ++i) {
            begin[std::size_t(i)] = binStart(i, inputs, outputs);
            end[std::size_t(i)] = std::max(begin[std::size_t(i)] + 1, binStart(i + 1, inputs, outputs));
        }
    }
};

// The box filter fed a source row at a time, top to bottom: only the output rows whose bins hold
// the current source row are being summed (one when shrinking), so filtering an 8K image into a
// 4K one holds one row of sums (64 KiB), not the whole output's (256 MiB of doubles).
class BoxFilter {
public:
    BoxFilter(int inputWidth, int inputHeight, int outputWidth, int outputHeight)
        : m_columns(inputWidth, outputWidth)
        , m_rows(inputHeight, outputHeight)
        , m_out(outputWidth, outputHeight, glm::vec4(0.0f))
    {
    }

    // Source row `y` (the input's width of texels); rows come in order.
    void addRow(const glm::vec4* row, int y)
    {
        flushRowsEndingBy(y);
        const int outputWidth = m_out.width();
        for (int j = m_next; j < m_out.height() && m_rows.begin[std::size_t(j)] <= y; ++j) {
            while (int(m_pending.size()) <= j - m_next)
                m_pending.emplace_back(std::size_t(outputWidth), glm::dvec4(0.0));
            std::vector<glm::dvec4>& sums = m_pending[std::size_t(j - m_next)];
            for (int x = 0; x < outputWidth; ++x) {
                glm::dvec4 sum(0.0);
                for (int sx = m_columns.begin[std::size_t(x)]; sx < m_columns.end[std::size_t(x)]; ++sx)
                    sum += glm::dvec4(row[sx]);
                sums[std::size_t(x)] += sum;
            }
        }
    }

    Image finish()
    {
        flushRowsEndingBy(std::numeric_limits<int>::max());
        return std::move(m_out);
    }

private:
    void flushRowsEndingBy(int y)
    {
        while (m_next < m_out.height() && m_rows.end[std::size_t(m_next)] <= y) {
            if (!m_pending.empty()) {
                const double rowCount
                    = double(m_rows.end[std::size_t(m_next)] - m_rows.begin[std::size_t(m_next)]);
                const std::vector<glm::dvec4>& sums = m_pending.front();
                for (int x = 0; x < m_out.width(); ++x) {
                    const double count
                        = double(m_columns.end[std::size_t(x)] - m_columns.begin[std::size_t(x)]) * rowCount;
                    m_out.at(x, m_next) = glm::vec4(sums[std::size_t(x)] / count);
                }
                m_pending.pop_front();
            }
            ++m_next;
        }
    }

    Bins m_columns;
    Bins m_rows;
    Image m_out;
    int m_next = 0; // the first output row not finished
    std::deque<std::vector<glm::dvec4>> m_pending; // sums of output rows m_next, m_next + 1, ...
};

} // namespace

Image Image::boxFiltered(int width, int height) const
{
    width = std::max(width, 1);
    height = std::max(height, 1);
    BoxFilter filter(m_width, m_height, width, height);
    for (int y = 0; y < m_height; ++y)
        filter.addRow(&at(0, y), y);
    Image out = filter.finish();
    out.m_encoding = m_encoding;
    return out;
}

std::optional<Image> Image::loadBoxFiltered(const std::string& path, bool linear,
    const std::function<std::pair<int, int>(int width, int height)>& sizeFor, std::string* error,
    int* sourceWidth, int* sourceHeight, ImageLoadStats* stats)
{
    constexpr const char* kFunction = "Image::loadBoxFiltered";
    if (stats)
        *stats = {};
    try {
        std::optional<ImageReader> reader = ImageReader::open(path, kFunction, error);
        if (!reader || !reader->checkHeader(kFunction, error))
            return std::nullopt;
        const CodecHeader& spec = reader->header();
        if (spec.width > kMaxDimension || spec.height > kMaxDimension) {
            setImageError(error, kFunction, path,
                "image too large: " + std::to_string(spec.width) + "x" + std::to_string(spec.height)
                    + " exceeds the limit of " + std::to_string(kMaxDimension) + " pixels per side");
            return std::nullopt;
        }
        if (!reader->checkSizeAgainstFile(kFunction, error))
            return std::nullopt;
        if (sourceWidth)
            *sourceWidth = spec.width;
        if (sourceHeight)
            *sourceHeight = spec.height;
        const auto [width, height] = sizeFor(spec.width, spec.height);
        BoxFilter filter(spec.width, spec.height, std::max(width, 1), std::max(height, 1));

        // Bands of about a million texels (16 MiB as float RGBA), whatever the image's size.
        const int bandRows
            = std::clamp(int((std::size_t(1) << 20) / std::size_t(spec.width)), 1, spec.height);
        Image band(spec.width, bandRows, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
        band.m_encoding = reader->encoding();
        const int readChannels = std::min(spec.channels, 4);
        const std::ptrdiff_t xstride = sizeof(glm::vec4);
        const std::ptrdiff_t ystride = xstride * std::ptrdiff_t(spec.width);
        for (int start = 0; start < spec.height; start += bandRows) {
            const int count = std::min(bandRows, spec.height - start);
            if (!reader->read(start, start + count, readChannels, CodecSample::Float, band.data(), xstride,
                    ystride, kFunction, error))
                return std::nullopt;
            fillMissingChannels(band.m_pixels, spec.channels, reader->twoColourChannels());
            const ImageLoadStats replaced = band.sanitize();
            if (stats) {
                stats->nanCount += replaced.nanCount;
                stats->infCount += replaced.infCount;
                stats->negativeCount += replaced.negativeCount;
            }
            if (linear && band.m_encoding == ColorEncoding::SRGB)
                band.toLinear(); // (sets the band's encoding: the next bands are read as linear)
            for (int r = 0; r < count; ++r)
                filter.addRow(&band.at(0, r), start + r);
            band.m_encoding = reader->encoding();
        }
        Image out = filter.finish();
        out.m_encoding = linear ? ColorEncoding::Linear : reader->encoding();
        out.m_sourceChannels = spec.channels;
        out.m_colorSpaceName = reader->colorSpaceName();
        return out;
    } catch (...) {
        setImageErrorFromException(error, kFunction, path, "reading");
    }
    return std::nullopt;
}

std::optional<Image> Image::load(const std::string& path, std::string* error, ImageLoadStats* stats)
{
    constexpr const char* kFunction = "Image::load";
    if (stats)
        *stats = {};
    try {
        std::optional<ImageReader> reader = ImageReader::open(path, kFunction, error);
        if (!reader)
            return std::nullopt;
        const CodecHeader& spec = reader->header();

        // Only the header has been read so far: check what it claims before allocating a
        // single pixel, so a crafted or corrupt header cannot make us ask for terabytes.
        if (!reader->checkHeader(kFunction, error))
            return std::nullopt;
        if (spec.width > kMaxDimension || spec.height > kMaxDimension) {
            setImageError(error, kFunction, path,
                "image too large: " + std::to_string(spec.width) + "x" + std::to_string(spec.height)
                    + " exceeds the limit of " + std::to_string(kMaxDimension) + " pixels per side");
            return std::nullopt;
        }
        const std::size_t pixels = std::size_t(spec.width) * std::size_t(spec.height);
        if (pixels > kMaxPixels) {
            setImageError(error, kFunction, path,
                "image too large: " + std::to_string(spec.width) + "x" + std::to_string(spec.height)
                    + " exceeds the limit of " + std::to_string(kMaxPixels) + " pixels");
            return std::nullopt;
        }
        if (!reader->checkSizeAgainstFile(kFunction, error))
            return std::nullopt;

        Image image(spec.width, spec.height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
        image.m_sourceChannels = spec.channels;
        image.m_colorSpaceName = reader->colorSpaceName();
        image.m_encoding = reader->encoding();

        // Read at most four channels straight into the RGBA pixels (the stride skips the rest),
        // so a file with dozens of AOV channels costs no more memory than an RGBA one.
        const int readChannels = std::min(spec.channels, 4);
        const std::ptrdiff_t xstride = sizeof(glm::vec4);
        const std::ptrdiff_t ystride = xstride * std::ptrdiff_t(spec.width);
        if (!reader->readAll(
                readChannels, CodecSample::Float, image.data(), xstride, ystride, kFunction, error))
            return std::nullopt;
        fillMissingChannels(image.m_pixels, spec.channels, reader->twoColourChannels());

        const ImageLoadStats replaced = image.sanitize();
        if (stats)
            *stats = replaced;
        return image;
    } catch (...) {
        setImageErrorFromException(error, kFunction, path, "reading");
    }
    return std::nullopt;
}

bool Image::save(const std::string& path, std::string* error, bool alpha,
    const std::vector<std::pair<std::string, std::string>>& attributes) const
{
    constexpr const char* kFunction = "Image::save";
    if (isEmpty()) {
        setImageError(error, kFunction, path, "the image is empty");
        return false;
    }
    try {
        // The format decides the samples: EXR half floats, HDR/PFM floats, the rest 8 bits.
        CodecWriterInfo writer;
        if (!imageWriterFor(path, &writer, kFunction, error))
            return false;
        const bool isExr = writer.formatName == "openexr";
        // Formats that store floats and nothing else; everything else gets 8 bits.
        const bool isFloatOnly = writer.formatName == "hdr" || writer.formatName == "pfm";
        const bool writeAlpha = alpha && writer.alpha;

        ImageFileSpec spec;
        spec.width = m_width;
        spec.height = m_height;
        spec.channels = writeAlpha ? 4 : 3;
        spec.sampleFormat = isExr ? FileSampleFormat::Half
            : isFloatOnly         ? FileSampleFormat::Float
                                  : FileSampleFormat::UInt8;
        spec.encoding = isExr || isFloatOnly ? ColorEncoding::Linear : m_encoding;
        spec.attributes = attributes;

        const int channels = spec.channels;
        std::vector<float> buffer(pixelCount() * std::size_t(channels));
        for (std::size_t i = 0; i < pixelCount(); ++i)
            for (int c = 0; c < channels; ++c)
                buffer[i * std::size_t(channels) + std::size_t(c)] = m_pixels[i][c];
        return writeImageFile(path, spec, buffer.data(), kFunction, error);
    } catch (...) {
        setImageErrorFromException(error, kFunction, path, "writing");
    }
    return false;
}

} // namespace facet
