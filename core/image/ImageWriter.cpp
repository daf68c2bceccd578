#include "core/image/ImageWriter.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "core/image/BuiltinImageEncoders.h"
#include "core/image/ImageCodec.h"
#include "core/image/ImageReader.h"
#include "core/support/AtomicFile.h"

namespace facet {

namespace {

CodecSample sampleOf(FileSampleFormat format)
{
    switch (format) {
    case FileSampleFormat::UInt16:
        return CodecSample::UInt16;
    case FileSampleFormat::Half:
        return CodecSample::Half;
    case FileSampleFormat::Float:
        return CodecSample::Float;
    case FileSampleFormat::UInt8:
        break;
    }
    return CodecSample::UInt8;
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

bool imageWriterFor(const std::string& path, CodecWriterInfo* info, const char* function, std::string* error)
{
    if (const std::optional<CodecWriterInfo> builtin = builtinImageWriterFor(path)) {
        *info = *builtin; // EXR and PNG: no module to load
        return true;
    }
    std::string problem;
    const ImageCodec* codec = imageCodec(&problem);
    if (!codec || !codec->writer(path, info, &problem)) {
        setImageError(error, function, path, problem);
        return false;
    }
    return true;
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
        // How a failed write is noticed: the encoder writes into memory (core's EXR and PNG
        // encoders; OpenImageIO through an IOVecOutput proxy, "oiio:ioproxy"), and the bytes go to disk
        // through writeFileAtomically, which checks every write, fsyncs, compares the size on disk and only
        // then renames over `path`. Letting OIIO write the file itself cannot be trusted: its PNG writer
        // reports success on a full disk and leaves a 0-byte file (issue 12, "A rendered PNG can be lost";
        // its file writers do not check what fwrite/fclose return). The alternative, re-reading the written
        // temporary to validate it, costs a full decode and still trusts each decoder to notice a truncation.
        // Encoding in memory cannot fail silently, and costs one copy of the encoded file (smaller than the
        // float buffer below). With OIIO 2.4.7 the bytes are identical to what the writer puts in a file
        // (compared for exr, png, hdr, jpg, tif, tga, bmp, webp, ppm). The writer is chosen by the extension
        // of `path`.
        CodecWriterInfo writer;
        if (!imageWriterFor(path, &writer, function, error))
            return false;
        // A few writers (sgi, ico, rla, fits, heif in OIIO 2.4) only write to a file by name;
        // they are refused rather than written unchecked.
        if (!writer.inMemory) {
            setImageError(error, function, path,
                "cannot write " + writer.formatName
                    + " files safely (OpenImageIO cannot encode them in memory to check the write); "
                      "use .exr, .png, .hdr, .tif, .jpg or .tga");
            return false;
        }

        CodecEncodeSpec fileSpec;
        fileSpec.width = spec.width;
        fileSpec.height = spec.height;
        fileSpec.channels = spec.channels;
        fileSpec.sample = sampleOf(spec.sampleFormat);
        const bool hasAlpha = spec.alpha && (spec.channels == 2 || spec.channels == 4);
        fileSpec.alphaChannel = hasAlpha ? spec.channels - 1 : -1;
        if (isFloat(spec.sampleFormat))
            fileSpec.colorSpaceName = "Linear";
        else if (spec.encoding == ColorEncoding::SRGB) // the caller encoded the values
            fileSpec.colorSpaceName = "sRGB";
        else if (spec.tagLinear)
            fileSpec.colorSpaceName = "Linear";
        fileSpec.attributes = spec.attributes;

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

        std::string problem;
        bool sampleRefused = false;
        // EXR and PNG are encoded here (core/image/BuiltinImageEncoders.h), the rest by the module
        // (imageWriterFor loaded it).
        const bool encoded = writer.builtin
            ? encodeBuiltinImage(writer, fileSpec, buffer.data(), result, &sampleRefused, &problem)
            : imageCodec(nullptr)->encode(path, fileSpec, buffer.data(), result, &sampleRefused, &problem);
        if (!encoded) {
            // A writer that cannot hold the samples asked for changes them (TGA: 8 bits): refuse
            // instead, the caller promised the user a bit depth.
            setImageError(error, function, path,
                sampleRefused
                    ? writer.formatName + " files cannot hold " + toString(spec.sampleFormat) + " samples"
                    : problem);
            return false;
        }
        return true;
    } catch (...) {
        setImageErrorFromException(error, function, path, "writing");
    }
    return false;
}

} // namespace facet
