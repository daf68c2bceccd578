#pragma once
// Decoding and encoding image files, behind an interface whose one implementation (over
// OpenImageIO, core/imageio/OiioImageCodec.cpp) is a module of its own, libfacet_imageio.so,
// loaded the first time an image is resized, read in a format other than EXR, or written in a
// format other than EXR and PNG (core decodes EXR and encodes EXR and PNG itself:
// core/image/BuiltinExrDecoder.h, core/image/BuiltinImageEncoders.h). OpenImageIO and what it links are
// 260 of the 282 shared libraries facet would otherwise load at start (121 MB of a 146 MB peak
// resident, and most of a process's start-up): `facet --version`, `--help`, a command that reads
// and writes no image and the window until its first image do not pay for them (docs/benchmarks.md,
// "Start-up"). It is not loaded ahead on another thread: the dynamic loader's lock would make
// the GL driver's loading and every new thread wait for it (measured: slower, not faster).
//
// The interface holds only standard types, so the module needs nothing of facet_core. Everything
// Facet decides about files (which are refused before a decoder sees them, sizes, limits, colour
// encodings, clamping, writing atomically) stays in core (ImageReader, ImageWriter); the module
// only translates to and from OpenImageIO. Internal to core/: callers use Image, MapImage and
// writeImageFile.

#include <cstddef>
#include <exception>
#include <new>
#include <string>
#include <utility>
#include <vector>

namespace facet {

// The module and core are built together; a module of another build is refused by this number.
inline constexpr int kImageCodecInterfaceVersion = 1;

// A sample type, as a file stores it or as a caller asks for it (UInt8, UInt16, Half, Float).
enum class CodecSample { UInt8, Int8, UInt16, Int16, UInt32, Int32, Half, Float, Double, Other };

// What a file's header says (subimage 0, mip level 0, the data window).
struct CodecHeader {
    int width = 0;
    int height = 0;
    int depth = 1;
    int channels = 0;
    CodecSample sample = CodecSample::Other;
    std::string colorSpaceName; // as the reader names it ("sRGB", "Linear", ...), or ""
    std::vector<std::string> channelNames;
};

// The writer a file name's extension picks.
struct CodecWriterInfo {
    std::string formatName; // "openexr", "png", "hdr", ...
    bool alpha = false; // can store an alpha channel
    bool inMemory = false; // can encode into memory (writeImageFile writes the bytes itself)
    bool builtin = false; // encoded by core itself, no module (core/image/BuiltinImageEncoders.h)
};

// What to encode: samples already converted to what the file holds (core/image/ImageWriter).
struct CodecEncodeSpec {
    int width = 0;
    int height = 0;
    int channels = 0;
    CodecSample sample = CodecSample::UInt8; // UInt8, UInt16, Half or Float
    int alphaChannel = -1; // unassociated alpha's channel, or -1
    std::string colorSpaceName; // the tag to write, or "" for none
    std::vector<std::pair<std::string, std::string>> attributes;
};

// One opened file (or memory buffer) with its header read: the module's, opaque here.
struct ImageDecoder;

// The module's functions. A table of plain functions, not a class with virtual functions: the
// module keeps its symbols to itself (loaded RTLD_LOCAL), so the two sides would each have their
// own copy of a class's type information, and UndefinedBehaviorSanitizer's vptr check (which
// compares those copies by address) would call every call across a mistake.
struct ImageCodec {
    int interfaceVersion = 0;
    // Opens `name` (the reader chosen by its contents and extension), or, when `memory` is not
    // null, the `size` bytes there under that name (the extension picks the reader; the bytes
    // must outlive the decoder). Unassociated alpha stays as stored. nullptr with *error.
    ImageDecoder* (*open)(
        const std::string& name, const unsigned char* memory, std::size_t size, std::string* error);
    // What the file's header says.
    const CodecHeader& (*header)(const ImageDecoder* decoder);
    // Rows [begin, end) of the first `channels` channels, converted to `as`, stored at the
    // strides in bytes (pixel to pixel, row to row; 0 for contiguous). begin 0 and end the
    // height reads the whole image (tiled files too). False: lastError says why.
    bool (*read)(ImageDecoder* decoder, int begin, int end, int channels, CodecSample as, void* data,
        std::ptrdiff_t xstride, std::ptrdiff_t ystride);
    // The last failure's message (may span lines), or "".
    std::string (*lastError)(ImageDecoder* decoder);
    // Closes the file and frees the decoder.
    void (*close)(ImageDecoder* decoder);
    // False with *error when no writer handles `path`'s extension.
    bool (*writer)(const std::string& path, CodecWriterInfo* info, std::string* error);
    // Encodes width x height x channels floats (rows top first) into *encoded in the format
    // `path`'s extension picks. False with *error, or with *sampleRefused when the writer would
    // store other samples than spec.sample (TGA has 8 bits only).
    bool (*encode)(const std::string& path, const CodecEncodeSpec& spec, const float* samples,
        std::vector<unsigned char>* encoded, bool* sampleRefused, std::string* error);
    // Resizes width x height x channels floats to outWidth x outHeight with OpenImageIO's default
    // filters (a wide Blackman-Harris going down, Lanczos going up). False with *error.
    bool (*resize)(const float* samples, int width, int height, int channels, float* out, int outWidth,
        int outHeight, std::string* error);
};

// An exception's message, for a codec's lastError or *error (exceptions cross no codec boundary):
// "out of memory" for std::bad_alloc, the exception's text, else "unknown error while <doing>".
inline std::string codecExceptionMessage(std::exception_ptr exception, const char* doing)
{
    try {
        std::rethrow_exception(exception);
    } catch (const std::bad_alloc&) {
        return "out of memory";
    } catch (const std::exception& e) {
        return e.what();
    } catch (...) {
        return std::string("unknown error while ") + doing;
    }
}

// The module's one exported symbol: extern "C" const facet::ImageCodec* facetImageCodec().
inline constexpr const char* kImageCodecEntryPoint = "facetImageCodec";

// The codec, loading the module on the first call (thread-safe; later calls return at once).
// nullptr with *error "image input/output module <path>: <why>" when the module cannot be
// loaded: every image read or write then fails with that message.
const ImageCodec* imageCodec(std::string* error);
// Whether the module has been loaded in this process (tests).
bool imageCodecLoaded();
// Where the module is looked for: $FACET_IMAGEIO_MODULE when set, else
// <the executable's folder>/../lib/facet/libfacet_imageio.so (the build tree and an
// installation have the same layout).
std::string imageCodecModulePath();

} // namespace facet
