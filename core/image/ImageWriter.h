#pragma once
// Writing pixels to an image file, checked: what Image::save (float RGBA: renders, bakes, sheets) and the
// texture-set export (core/export/TextureSetExport: 1 to 4 channels, 8 or 16 bits, half or float) share. EXR
// and PNG are encoded by core itself (core/image/BuiltinImageEncoders.h: no OpenImageIO to load), other
// formats by the image codec (OpenImageIO); either encodes into memory and the bytes go to disk through
// writeFileAtomically (core/support/AtomicFile.h), so a failed write, a full disk included, never leaves half
// a file nor harms an existing one (see encodeImageFile for why OIIO may not write the file itself).

#include <string>
#include <utility>
#include <vector>

#include "core/image/Image.h" // ColorEncoding

namespace facet {

struct CodecWriterInfo;

// How each sample is stored in the file.
enum class FileSampleFormat { UInt8, UInt16, Half, Float };
const char* toString(FileSampleFormat format); // "8-bit", "16-bit", "half float", "float"

struct ImageFileSpec {
    int width = 0;
    int height = 0;
    int channels = 4; // 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA
    FileSampleFormat sampleFormat = FileSampleFormat::UInt8;
    // The colour-space tag: integer files tagged sRGB only when SRGB (an untagged PNG is read as
    // sRGB anyway, and a gAMA 1.0 chunk confuses viewers), float files always "Linear".
    ColorEncoding encoding = ColorEncoding::Linear;
    // Integer files with Linear encoding: also write the "Linear" claim (a PNG gets a gAMA chunk of
    // 1.0) for readers that go by the tag. Renders leave it off; exported data maps (normal, ORM)
    // set it, so the file says what it holds.
    bool tagLinear = false;
    // The last channel of a 2- or 4-channel image is alpha, unassociated (never premultiplied).
    // False: every channel is data (a packed mask map), which OIIO then keeps as it is too.
    bool alpha = true;
    // String metadata for formats that hold it (EXR header attributes, PNG text).
    std::vector<std::pair<std::string, std::string>> attributes;
};

// The writer `path`'s extension picks (its format's name, whether it stores alpha, whether it can
// encode into memory). False with *error "<function>: <path>: <reason>" when there is none or
// the image codec cannot be loaded.
bool imageWriterFor(const std::string& path, CodecWriterInfo* info, const char* function, std::string* error);

// Writes width x height x channels floats (rows top first, channels interleaved) to `path`, the
// format chosen by its extension. Integer formats store the values clamped to [0, 1] and rounded
// to the nearest step (NaN as 0); half floats are clamped to the finite half range. False with
// *error "<function>: <path>: <reason>": a format OIIO cannot write into memory (sgi, ico, rla,
// fits, heif), one that cannot hold the sample format or channel count (the writer's own
// message), or the write (e.g. "cannot write: No space left on device").
bool writeImageFile(const std::string& path, const ImageFileSpec& spec, const float* pixels,
    const char* function, std::string* error);
// The same encoding into memory (the format still chosen by `path`'s extension, nothing
// written): an image embedded in a .glb (core/gltf/GltfExport).
bool encodeImageFile(const std::string& path, const ImageFileSpec& spec, const float* pixels,
    const char* function, std::vector<unsigned char>* encoded, std::string* error);

} // namespace facet
