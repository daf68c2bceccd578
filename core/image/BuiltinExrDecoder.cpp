#include "core/image/BuiltinExrDecoder.h"

#include <algorithm>
#include <array>
#include <exception>
#include <memory>
#include <mutex>
#include <new>
#include <thread>
#include <vector>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfPartType.h>
#include <ImfThreading.h>

namespace facet {

namespace {

// The channel names handled, in the order OpenImageIO's OpenEXR reader gives them (its
// "special" names: R, G, B before Y, A after).
constexpr std::array<const char*, 5> kChannelOrder = {"R", "G", "B", "Y", "A"};

struct ExrDecoder {
    std::unique_ptr<Imf::InputFile> file;
    Imath::Box2i dataWindow;
    CodecHeader header;
    std::string error;
};

ExrDecoder* decoderOf(ImageDecoder* decoder)
{
    return reinterpret_cast<ExrDecoder*>(decoder);
}

const ExrDecoder* decoderOf(const ImageDecoder* decoder)
{
    return reinterpret_cast<const ExrDecoder*>(decoder);
}

// OpenEXR's thread pool, as OpenImageIO sizes it for its reads: one thread per core.
void startThreads()
{
    static std::once_flag once;
    std::call_once(
        once, [] { Imf::setGlobalThreadCount(int(std::max(1u, std::thread::hardware_concurrency()))); });
}

// Whether the header is one this decoder reads, and its channels in output order.
bool handles(const Imf::Header& header, CodecHeader* out)
{
    if (header.hasType() && (header.type() == Imf::DEEPSCANLINE || header.type() == Imf::DEEPTILE))
        return false;
    const Imf::ChannelList& channels = header.channels();
    std::array<const Imf::Channel*, kChannelOrder.size()> found {};
    int count = 0;
    for (auto it = channels.begin(); it != channels.end(); ++it) {
        const auto known = std::find_if(kChannelOrder.begin(), kChannelOrder.end(),
            [&](const char* name) { return std::string(it.name()) == name; });
        const Imf::Channel& channel = it.channel();
        if (known == kChannelOrder.end() || channel.xSampling != 1 || channel.ySampling != 1
            || (channel.type != Imf::HALF && channel.type != Imf::FLOAT))
            return false;
        found[std::size_t(known - kChannelOrder.begin())] = &channel;
        ++count;
    }
    if (count == 0)
        return false;
    // Y with colour channels is OpenEXR's luminance-chroma or something stranger: the module's.
    const bool colour = found[0] || found[1] || found[2];
    if (found[3] && colour)
        return false;
    Imf::PixelType type = Imf::NUM_PIXELTYPES;
    for (std::size_t i = 0; i < kChannelOrder.size(); ++i) {
        if (!found[i])
            continue;
        if (type != Imf::NUM_PIXELTYPES && found[i]->type != type)
            return false; // mixed: OpenImageIO would widen them; the module reads those
        type = found[i]->type;
        out->channelNames.emplace_back(kChannelOrder[i]);
    }
    const Imath::Box2i& window = header.dataWindow();
    out->width = window.max.x - window.min.x + 1;
    out->height = window.max.y - window.min.y + 1;
    out->depth = 1;
    out->channels = count;
    out->sample = type == Imf::HALF ? CodecSample::Half : CodecSample::Float;
    out->colorSpaceName = "Linear";
    return true;
}

ImageDecoder* open(const std::string& name, const unsigned char* memory, std::size_t, std::string* error)
{
    if (memory) {
        *error = "the built-in EXR decoder reads files only";
        return nullptr;
    }
    bool handled = true;
    ImageDecoder* decoder = openBuiltinExr(name, &handled, error);
    if (!decoder && !handled)
        *error = "the built-in EXR decoder does not read this file's layout";
    return decoder;
}

const CodecHeader& header(const ImageDecoder* decoder)
{
    return decoderOf(decoder)->header;
}

bool read(ImageDecoder* handle, int begin, int end, int channels, CodecSample as, void* data,
    std::ptrdiff_t xstride, std::ptrdiff_t ystride)
{
    ExrDecoder* decoder = decoderOf(handle);
    const CodecHeader& header = decoder->header;
    if (as != CodecSample::Float && as != CodecSample::Half) {
        decoder->error = "the built-in EXR decoder converts to float or half only";
        return false;
    }
    if (begin < 0 || end > header.height || begin >= end || channels < 1 || channels > header.channels) {
        decoder->error = "rows or channels out of range";
        return false;
    }
    try {
        const Imf::PixelType type = as == CodecSample::Float ? Imf::FLOAT : Imf::HALF;
        const std::size_t sampleBytes = as == CodecSample::Float ? 4 : 2;
        const std::size_t xs = xstride ? std::size_t(xstride) : sampleBytes * std::size_t(channels);
        const std::size_t ys = ystride ? std::size_t(ystride) : xs * std::size_t(header.width);
        const Imath::Box2i& window = decoder->dataWindow;
        // The rows read, in the file's coordinates; `data` holds the first of them.
        const Imath::Box2i rows(
            Imath::V2i(window.min.x, window.min.y + begin), Imath::V2i(window.max.x, window.min.y + end - 1));
        Imf::FrameBuffer frame;
        for (int c = 0; c < channels; ++c)
            frame.insert(header.channelNames[std::size_t(c)],
                Imf::Slice::Make(
                    type, static_cast<unsigned char*>(data) + std::size_t(c) * sampleBytes, rows, xs, ys));
        decoder->file->setFrameBuffer(frame);
        decoder->file->readPixels(rows.min.y, rows.max.y);
        return true;
    } catch (...) {
        decoder->error = codecExceptionMessage(std::current_exception(), "reading");
    }
    return false;
}

std::string lastError(ImageDecoder* decoder)
{
    return decoderOf(decoder)->error;
}

void close(ImageDecoder* decoder)
{
    delete decoderOf(decoder);
}

} // namespace

const ImageCodec& builtinExrCodec()
{
    static const ImageCodec codec {
        kImageCodecInterfaceVersion, open, header, read, lastError, close, nullptr, nullptr, nullptr};
    return codec;
}

ImageDecoder* openBuiltinExr(const std::string& path, bool* handled, std::string* error)
{
    *handled = true;
    try {
        startThreads();
        auto decoder = std::make_unique<ExrDecoder>();
        decoder->file = std::make_unique<Imf::InputFile>(path.c_str());
        if (!handles(decoder->file->header(), &decoder->header)) {
            *handled = false;
            return nullptr;
        }
        decoder->dataWindow = decoder->file->header().dataWindow();
        return reinterpret_cast<ImageDecoder*>(decoder.release());
    } catch (...) {
        *error = codecExceptionMessage(std::current_exception(), "reading");
    }
    return nullptr;
}

} // namespace facet
