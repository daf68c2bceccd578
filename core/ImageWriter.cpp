#include "core/ImageWriter.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "core/AtomicFile.h"
#include "core/ImageReader.h"

namespace facet {

namespace {

constexpr float kLargestHalf = 65504.0f; // the largest finite IEEE 754 binary16 value

OIIO::TypeDesc typeOf(FileSampleFormat format)
{
    switch (format) {
    case FileSampleFormat::UInt16:
        return OIIO::TypeDesc::UINT16;
    case FileSampleFormat::Half:
        return OIIO::TypeDesc::HALF;
    case FileSampleFormat::Float:
        return OIIO::TypeDesc::FLOAT;
    case FileSampleFormat::UInt8:
        break;
    }
    return OIIO::TypeDesc::UINT8;
}

bool isFloat(FileSampleFormat format)
{
    return format == FileSampleFormat::Half || format == FileSampleFormat::Float;
}

} // namespace

const char* toString(FileSampleFormat format)
{
    switch (format) {
    case FileSampleFormat::UInt16:
        return "16-bit";
    case FileSampleFormat::Half:
        return "half float";
    case FileSampleFormat::Float:
        return "float";
    case FileSampleFormat::UInt8:
        break;
    }
    return "8-bit";
}

bool writeImageFile(const std::string& path, const ImageFileSpec& spec, const float* pixels,
    const char* function, std::string* error)
{
    std::vector<unsigned char> encoded;
    if (!encodeImageFile(path, spec, pixels, function, &encoded, error))
        return false;
    std::string problem;
    if (!writeFileAtomically(path,
            std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()), &problem)) {
        setImageError(error, function, path, "cannot write: " + problem);
        return false;
    }
    return true;
}

bool encodeImageFile(const std::string& path, const ImageFileSpec& spec, const float* pixels,
    const char* function, std::vector<unsigned char>* result, std::string* error)
{
    if (spec.width <= 0 || spec.height <= 0 || spec.channels < 1 || spec.channels > 4 || !pixels) {
        setImageError(error, function, path, "the image is empty");
        return false;
    }
    try {
        // How a failed write is noticed: OpenImageIO encodes into memory (an IOVecOutput proxy,
        // "oiio:ioproxy"), and the bytes go to disk through writeFileAtomically, which checks
        // every write, fsyncs, compares the size on disk and only then renames over `path`.
        // Letting OIIO write the file itself cannot be trusted: its PNG writer reports success
        // on a full disk and leaves a 0-byte file (issue 12, "A rendered PNG can be lost"; its
        // file writers do not check what fwrite/fclose return). The alternative, re-reading the
        // written temporary to validate it, costs a full decode and still trusts each decoder to
        // notice a truncation. Encoding in memory cannot fail silently, and costs one copy of the
        // encoded file (smaller than the float buffer below). With OIIO 2.4.7 the bytes are
        // identical to what the writer puts in a file (compared for exr, png, hdr, jpg, tif, tga,
        // bmp, webp, ppm). The writer is chosen by the extension of `path`.
        std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path);
        if (!output) {
            setImageError(error, function, path, OIIO::geterror());
            return false;
        }
        const std::string formatName = output->format_name();
        // A few writers (sgi, ico, rla, fits, heif in OIIO 2.4) only write to a file by name;
        // they are refused rather than written unchecked.
        if (!output->supports("ioproxy")) {
            setImageError(error, function, path,
                "cannot write " + formatName
                    + " files safely (OpenImageIO cannot encode them in memory to check the write); "
                      "use .exr, .png, .hdr, .tif, .jpg or .tga");
            return false;
        }

        OIIO::ImageSpec fileSpec(spec.width, spec.height, spec.channels, typeOf(spec.sampleFormat));
        const bool hasAlpha = spec.alpha && (spec.channels == 2 || spec.channels == 4);
        fileSpec.alpha_channel = hasAlpha ? spec.channels - 1 : -1;
        if (isFloat(spec.sampleFormat)) {
            fileSpec.attribute("oiio:ColorSpace", "Linear");
        } else {
            // The caller encoded the values; only an sRGB claim is written.
            if (spec.encoding == ColorEncoding::SRGB)
                fileSpec.attribute("oiio:ColorSpace", "sRGB");
            else if (spec.tagLinear)
                fileSpec.attribute("oiio:ColorSpace", "Linear");
            // The colour values are not premultiplied: keep OIIO from dividing them by alpha.
            fileSpec.attribute("oiio:UnassociatedAlpha", 1);
        }
        if (formatName == "openexr")
            fileSpec.attribute("compression", "zip");
        for (const auto& [name, value] : spec.attributes)
            fileSpec.attribute(name, value);

        // Convert to what the file can hold ourselves, so nothing depends on OIIO's choices:
        // finite values beyond the half range would become Inf in an EXR, and integer files
        // hold [0,1] (NaN stored as 0).
        const std::size_t count
            = std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.channels);
        std::vector<float> buffer(pixels, pixels + count);
        for (float& value : buffer) {
            if (spec.sampleFormat == FileSampleFormat::Half)
                value = std::isnan(value) ? value : std::clamp(value, -kLargestHalf, kLargestHalf);
            else if (!isFloat(spec.sampleFormat))
                value = std::isnan(value) ? 0.0f : std::clamp(value, 0.0f, 1.0f);
        }

        std::vector<unsigned char> encoded;
        OIIO::Filesystem::IOVecOutput memory(encoded);
        OIIO::Filesystem::IOProxy* proxy = &memory;
        fileSpec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
        if (!output->open(path, fileSpec)) {
            setImageError(error, function, path, "cannot encode: " + output->geterror());
            return false;
        }
        // A writer that cannot hold the samples asked for changes them (TGA: 8 bits): refuse
        // instead, the caller promised the user a bit depth.
        if (output->spec().format != fileSpec.format) {
            setImageError(error, function, path,
                formatName + " files cannot hold " + toString(spec.sampleFormat) + " samples");
            return false;
        }
        const bool written = output->write_image(OIIO::TypeDesc::FLOAT, buffer.data());
        std::string reason = written ? std::string() : output->geterror();
        const bool closed = output->close();
        if (reason.empty() && !closed)
            reason = output->geterror();
        if (!written || !closed) {
            setImageError(error, function, path, "encoding failed: " + reason);
            return false;
        }
        output.reset();
        *result = std::move(encoded);
        return true;
    } catch (...) {
        setImageErrorFromException(error, function, path, "writing");
    }
    return false;
}

} // namespace facet
