#include "core/image/BuiltinImageEncoders.h"

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstring>
#include <exception>

#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <half.h>
#include <png.h>

#include "core/support/AsciiText.h"

namespace facet {

namespace {

std::string lowerExtension(const std::string& path)
{
    const std::size_t dot = path.find_last_of('.');
    const std::size_t slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return {};
    return asciiLowercase(path.substr(dot + 1));
}

// OpenEXR writes through an Imf::OStream; this one fills a byte vector (it seeks back to write
// the line offsets, so a write may land inside what is there).
class MemoryStream final : public Imf::OStream {
public:
    explicit MemoryStream(std::vector<unsigned char>& bytes)
        : Imf::OStream("memory")
        , m_bytes(bytes)
    {
    }
    void write(const char c[], int n) override
    {
        const std::size_t end = std::size_t(m_position) + std::size_t(n);
        if (end > m_bytes.size())
            m_bytes.resize(end);
        std::memcpy(m_bytes.data() + m_position, c, std::size_t(n));
        m_position = end;
    }
    uint64_t tellp() override { return m_position; }
    void seekp(uint64_t position) override { m_position = position; }

private:
    std::vector<unsigned char>& m_bytes;
    uint64_t m_position = 0;
};

// The channel names OpenImageIO gives a new image of n channels (ImageSpec::default_channel_names).
std::vector<std::string> exrChannelNames(int channels)
{
    if (channels == 1)
        return {"Y"};
    static const char* const kNames[] = {"R", "G", "B", "A"};
    return std::vector<std::string>(kNames, kNames + std::clamp(channels, 0, 4));
}

bool encodeExr(const CodecEncodeSpec& spec, const float* samples, std::vector<unsigned char>* encoded,
    bool* sampleRefused, std::string* error)
{
    if (spec.sample != CodecSample::Half && spec.sample != CodecSample::Float) {
        *sampleRefused = true;
        return false;
    }
    const Imf::PixelType type = spec.sample == CodecSample::Half ? Imf::HALF : Imf::FLOAT;
    Imf::Header header(spec.width, spec.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    const std::vector<std::string> names = exrChannelNames(spec.channels);
    for (const std::string& name : names)
        header.channels().insert(name, Imf::Channel(type));
    if (!spec.colorSpaceName.empty())
        header.insert("oiio:ColorSpace", Imf::StringAttribute(spec.colorSpaceName));
    for (const auto& [name, value] : spec.attributes)
        header.insert(name, Imf::StringAttribute(value));

    // OpenEXR converts no sample type: half samples are made here (Imath's rounding to nearest
    // even, what OpenImageIO's conversion uses too).
    const std::size_t count = std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.channels);
    std::vector<half> halves;
    if (type == Imf::HALF)
        halves.assign(samples, samples + count);
    char* base = type == Imf::HALF ? reinterpret_cast<char*>(halves.data())
                                   : reinterpret_cast<char*>(const_cast<float*>(samples));
    const std::size_t sampleSize = type == Imf::HALF ? sizeof(half) : sizeof(float);
    const std::size_t xStride = sampleSize * std::size_t(spec.channels);
    const std::size_t yStride = xStride * std::size_t(spec.width);
    Imf::FrameBuffer frame;
    for (std::size_t c = 0; c < names.size(); ++c)
        frame.insert(names[c], Imf::Slice(type, base + c * sampleSize, xStride, yStride));
    std::vector<unsigned char> bytes;
    try {
        MemoryStream stream(bytes);
        Imf::OutputFile file(stream, header);
        file.setFrameBuffer(frame);
        file.writePixels(spec.height);
    } catch (const std::exception& e) {
        *error = std::string("encoding failed: ") + e.what();
        return false;
    }
    *encoded = std::move(bytes);
    return true;
}

struct PngWrite {
    std::vector<unsigned char>* bytes = nullptr;
    std::string error;
};

void pngWrite(png_structp png, png_bytep data, png_size_t length)
{
    auto* write = static_cast<PngWrite*>(png_get_io_ptr(png));
    write->bytes->insert(write->bytes->end(), data, data + length);
}

void pngFlush(png_structp)
{
}

[[noreturn]] void pngError(png_structp png, png_const_charp message)
{
    static_cast<PngWrite*>(png_get_error_ptr(png))->error = message ? message : "libpng error";
    png_longjmp(png, 1);
}

void pngWarning(png_structp, png_const_charp)
{
}

bool encodePng(const CodecEncodeSpec& spec, const float* samples, std::vector<unsigned char>* encoded,
    bool* sampleRefused, std::string* error)
{
    if (spec.sample != CodecSample::UInt8 && spec.sample != CodecSample::UInt16) {
        *sampleRefused = true;
        return false;
    }
    static const int kColorTypes[]
        = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA};
    const bool wide = spec.sample == CodecSample::UInt16;
    const std::size_t rowSamples = std::size_t(spec.width) * std::size_t(spec.channels);
    // The samples as the file holds them (big-endian for 16 bits), quantized to the nearest step.
    std::vector<unsigned char> rows(rowSamples * std::size_t(spec.height) * (wide ? 2 : 1));
    const float scale = wide ? 65535.0f : 255.0f;
    for (std::size_t i = 0; i < rowSamples * std::size_t(spec.height); ++i) {
        const auto value = unsigned(std::clamp(samples[i], 0.0f, 1.0f) * scale + 0.5f);
        if (wide) {
            rows[2 * i] = static_cast<unsigned char>(value >> 8);
            rows[2 * i + 1] = static_cast<unsigned char>(value & 0xffu);
        } else {
            rows[i] = static_cast<unsigned char>(value);
        }
    }

    std::vector<unsigned char> bytes;
    PngWrite state {&bytes, {}};
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, pngError, pngWarning);
    if (!png) {
        *error = "encoding failed: libpng could not start";
        return false;
    }
    png_infop info = png_create_info_struct(png);
    // Everything that can fail below is between setjmp and the end: libpng returns here on error.
    std::vector<png_text> texts;
    std::vector<std::pair<std::string, std::string>> textStorage;
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        *error = "encoding failed: " + state.error;
        return false;
    }
    png_set_write_fn(png, &state, pngWrite, pngFlush);
    png_set_IHDR(png, info, png_uint_32(spec.width), png_uint_32(spec.height), wide ? 16 : 8,
        kColorTypes[std::clamp(spec.channels, 1, 4) - 1], PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
        PNG_FILTER_TYPE_DEFAULT);
    if (spec.colorSpaceName == "sRGB")
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_ABSOLUTE);
    else if (spec.colorSpaceName == "Linear")
        png_set_gAMA(png, info, 1.0);
    if (!spec.colorSpaceName.empty())
        textStorage.emplace_back("oiio:ColorSpace", spec.colorSpaceName);
    for (const auto& attribute : spec.attributes)
        textStorage.push_back(attribute);
    for (auto& [key, text] : textStorage) {
        png_text entry {};
        entry.compression = PNG_TEXT_COMPRESSION_NONE;
        entry.key = key.data();
        entry.text = text.data();
        entry.text_length = text.size();
        texts.push_back(entry);
    }
    if (!texts.empty())
        png_set_text(png, info, texts.data(), int(texts.size()));
    png_write_info(png, info);
    const std::size_t rowBytes = rowSamples * (wide ? 2 : 1);
    for (int y = 0; y < spec.height; ++y)
        png_write_row(png, rows.data() + std::size_t(y) * rowBytes);
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    *encoded = std::move(bytes);
    return true;
}

} // namespace

std::optional<CodecWriterInfo> builtinImageWriterFor(const std::string& path)
{
    const std::string extension = lowerExtension(path);
    if (extension == "exr")
        return CodecWriterInfo {"openexr", true, true, true};
    if (extension == "png")
        return CodecWriterInfo {"png", true, true, true};
    return std::nullopt;
}

bool encodeBuiltinImage(const CodecWriterInfo& writer, const CodecEncodeSpec& spec, const float* samples,
    std::vector<unsigned char>* encoded, bool* sampleRefused, std::string* error)
{
    *sampleRefused = false;
    if (!writer.builtin) {
        *error = "not a format Facet encodes itself";
        return false;
    }
    if (spec.width <= 0 || spec.height <= 0 || spec.channels < 1 || spec.channels > 4) {
        *error = "cannot encode: the image is empty or has more than 4 channels";
        return false;
    }
    return writer.formatName == "openexr" ? encodeExr(spec, samples, encoded, sampleRefused, error)
                                          : encodePng(spec, samples, encoded, sampleRefused, error);
}

} // namespace facet
