// The image codec over OpenImageIO: built as libfacet_imageio.so, the one place OpenImageIO is
// linked, and loaded by core/image/ImageCodec.cpp the first time an image is read or written. It
// translates between core/image/ImageCodec.h's types and OpenImageIO's and decides nothing else.

#include <algorithm>
#include <cstring>
#include <exception>
#include <memory>
#include <new>
#include <utility>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include "core/image/ImageCodec.h"

namespace facet {
namespace {

// Each sample type and OpenImageIO's base type for it.
constexpr std::pair<CodecSample, OIIO::TypeDesc::BASETYPE> kSampleTypes[] = {
    {CodecSample::UInt8, OIIO::TypeDesc::UINT8},
    {CodecSample::Int8, OIIO::TypeDesc::INT8},
    {CodecSample::UInt16, OIIO::TypeDesc::UINT16},
    {CodecSample::Int16, OIIO::TypeDesc::INT16},
    {CodecSample::UInt32, OIIO::TypeDesc::UINT32},
    {CodecSample::Int32, OIIO::TypeDesc::INT32},
    {CodecSample::Half, OIIO::TypeDesc::HALF},
    {CodecSample::Float, OIIO::TypeDesc::FLOAT},
    {CodecSample::Double, OIIO::TypeDesc::DOUBLE},
};

CodecSample sampleOf(OIIO::TypeDesc type)
{
    for (const auto& [sample, base] : kSampleTypes)
        if (type.basetype == base)
            return sample;
    return CodecSample::Other;
}

// (Other, which no caller asks for, reads as float.)
OIIO::TypeDesc typeOf(CodecSample sample)
{
    for (const auto& [known, base] : kSampleTypes)
        if (known == sample)
            return base;
    return OIIO::TypeDesc::FLOAT;
}

} // namespace

// The opaque decoder of core/image/ImageCodec.h.
struct ImageDecoder {
    std::unique_ptr<OIIO::Filesystem::IOMemReader> memory; // what `input` reads an embedded image from
    std::unique_ptr<OIIO::ImageInput> input;
    CodecHeader header;
    std::string exception; // an exception's message, when a read threw
};

namespace {

ImageDecoder* open(const std::string& name, const unsigned char* memory, std::size_t size, std::string* error)
{
    try {
        auto decoder = std::make_unique<ImageDecoder>();
        if (memory)
            decoder->memory = std::make_unique<OIIO::Filesystem::IOMemReader>(memory, size);
        // Leave unassociated alpha as the file stores it: OIIO would otherwise premultiply
        // PNG/TIFF/TGA colour by alpha on read.
        OIIO::ImageSpec config;
        config.attribute("oiio:UnassociatedAlpha", 1);
        // OIIO 2.4's open(name, config, ioproxy) ignores the proxy when a config is given: the
        // proxy travels in the config instead (a pointer to the pointer, TypeDesc::PTR).
        void* proxy = decoder->memory.get();
        if (proxy)
            config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
        decoder->input = OIIO::ImageInput::open(name, &config);
        if (!decoder->input) {
            *error = OIIO::geterror();
            return nullptr;
        }
        const OIIO::ImageSpec& spec = decoder->input->spec();
        decoder->header.width = spec.width;
        decoder->header.height = spec.height;
        decoder->header.depth = spec.depth;
        decoder->header.channels = spec.nchannels;
        decoder->header.sample = sampleOf(spec.format);
        decoder->header.colorSpaceName = spec.get_string_attribute("oiio:ColorSpace");
        decoder->header.channelNames = spec.channelnames;
        return decoder.release();
    } catch (...) {
        *error = codecExceptionMessage(std::current_exception(), "reading");
    }
    return nullptr;
}

const CodecHeader& header(const ImageDecoder* decoder)
{
    return decoder->header;
}

bool read(ImageDecoder* decoder, int begin, int end, int channels, CodecSample as, void* data,
    std::ptrdiff_t xstride, std::ptrdiff_t ystride)
{
    try {
        const OIIO::stride_t xs = xstride ? OIIO::stride_t(xstride) : OIIO::AutoStride;
        const OIIO::stride_t ys = ystride ? OIIO::stride_t(ystride) : OIIO::AutoStride;
        if (begin == 0 && end == decoder->header.height)
            return decoder->input->read_image(0, 0, 0, channels, typeOf(as), data, xs, ys);
        const OIIO::ImageSpec& spec = decoder->input->spec();
        if (spec.tile_width <= 0)
            return decoder->input->read_scanlines(
                0, 0, spec.y + begin, spec.y + end, 0, 0, channels, typeOf(as), data, xs, ys);
        // A band of a tiled file: OpenImageIO 2.4's read_scanlines divides by a scanline chunk a
        // tiled file does not have (SIGFPE), so the rows of tiles that hold the band are read
        // whole and the band copied out of them.
        const int first = begin / spec.tile_height * spec.tile_height;
        const int last = std::min((end + spec.tile_height - 1) / spec.tile_height * spec.tile_height, spec.height);
        const OIIO::TypeDesc type = typeOf(as);
        const std::size_t pixelBytes = type.size() * std::size_t(channels);
        const std::size_t rowBytes = pixelBytes * std::size_t(spec.width);
        std::vector<unsigned char> tiles(rowBytes * std::size_t(last - first));
        if (!decoder->input->read_tiles(0, 0, spec.x, spec.x + spec.width, spec.y + first, spec.y + last, spec.z,
                spec.z + 1, 0, channels, type, tiles.data()))
            return false;
        const std::ptrdiff_t xout = xs == OIIO::AutoStride ? std::ptrdiff_t(pixelBytes) : std::ptrdiff_t(xs);
        const std::ptrdiff_t yout = ys == OIIO::AutoStride ? xout * spec.width : std::ptrdiff_t(ys);
        for (int y = begin; y < end; ++y)
            for (int x = 0; x < spec.width; ++x)
                std::memcpy(static_cast<unsigned char*>(data) + std::ptrdiff_t(y - begin) * yout + std::ptrdiff_t(x) * xout,
                    tiles.data() + std::size_t(y - first) * rowBytes + std::size_t(x) * pixelBytes, pixelBytes);
        return true;
    } catch (...) {
        decoder->exception = codecExceptionMessage(std::current_exception(), "reading");
    }
    return false;
}

std::string lastError(ImageDecoder* decoder)
{
    std::string message = decoder->input->geterror();
    if (message.empty())
        message = std::exchange(decoder->exception, {});
    return message;
}

void close(ImageDecoder* decoder)
{
    if (!decoder)
        return;
    decoder->input->close();
    decoder->input.reset(); // before the memory it may read from
    delete decoder;
}

bool writer(const std::string& path, CodecWriterInfo* info, std::string* error)
{
    try {
        std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path);
        if (!output) {
            *error = OIIO::geterror();
            return false;
        }
        info->formatName = output->format_name();
        info->alpha = output->supports("alpha") != 0;
        info->inMemory = output->supports("ioproxy") != 0;
        return true;
    } catch (...) {
        *error = codecExceptionMessage(std::current_exception(), "writing");
    }
    return false;
}

bool encode(const std::string& path, const CodecEncodeSpec& spec, const float* samples,
    std::vector<unsigned char>* encoded, bool* sampleRefused, std::string* error)
{
    *sampleRefused = false;
    try {
        // The bytes and the proxy before the writer: a writer left open by an early return closes
        // as it is destroyed, and closing writes (TGA's footer): into a proxy still alive. (With
        // the proxy declared after, a refused TGA wrote through a dead one: found by ASan.)
        std::vector<unsigned char> bytes;
        OIIO::Filesystem::IOVecOutput memory(bytes);
        std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path);
        if (!output) {
            *error = OIIO::geterror();
            return false;
        }
        OIIO::ImageSpec fileSpec(spec.width, spec.height, spec.channels, typeOf(spec.sample));
        fileSpec.alpha_channel = spec.alphaChannel;
        if (!spec.colorSpaceName.empty())
            fileSpec.attribute("oiio:ColorSpace", spec.colorSpaceName);
        // Integer samples are never premultiplied: keep OIIO from dividing them by alpha.
        if (spec.sample == CodecSample::UInt8 || spec.sample == CodecSample::UInt16)
            fileSpec.attribute("oiio:UnassociatedAlpha", 1);
        if (std::string(output->format_name()) == "openexr")
            fileSpec.attribute("compression", "zip");
        for (const auto& [name, value] : spec.attributes)
            fileSpec.attribute(name, value);

        OIIO::Filesystem::IOProxy* proxy = &memory;
        fileSpec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
        if (!output->open(path, fileSpec)) {
            *error = "cannot encode: " + output->geterror();
            return false;
        }
        if (output->spec().format != fileSpec.format) {
            *sampleRefused = true;
            return false;
        }
        const bool written = output->write_image(OIIO::TypeDesc::FLOAT, samples);
        std::string reason = written ? std::string() : output->geterror();
        const bool closed = output->close();
        if (reason.empty() && !closed)
            reason = output->geterror();
        if (!written || !closed) {
            *error = "encoding failed: " + reason;
            return false;
        }
        output.reset();
        *encoded = std::move(bytes);
        return true;
    } catch (...) {
        *error = codecExceptionMessage(std::current_exception(), "writing");
    }
    return false;
}

bool resize(const float* samples, int width, int height, int channels, float* out, int outWidth,
    int outHeight, std::string* error)
{
    try {
        const OIIO::ImageSpec sourceSpec(width, height, channels, OIIO::TypeDesc::FLOAT);
        const OIIO::ImageBuf source(sourceSpec, const_cast<float*>(samples));
        OIIO::ImageBuf resized(OIIO::ImageSpec(outWidth, outHeight, channels, OIIO::TypeDesc::FLOAT));
        if (!OIIO::ImageBufAlgo::resize(resized, source)
            || !resized.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, out)) {
            *error = resized.geterror();
            return false;
        }
        return true;
    } catch (...) {
        *error = codecExceptionMessage(std::current_exception(), "resizing");
    }
    return false;
}

} // namespace
} // namespace facet

extern "C" __attribute__((visibility("default"))) const facet::ImageCodec* facetImageCodec()
{
    static const facet::ImageCodec codec {facet::kImageCodecInterfaceVersion, facet::open, facet::header,
        facet::read, facet::lastError, facet::close, facet::writer, facet::encode, facet::resize};
    return &codec;
}
