#pragma once
// The two file formats Facet encodes itself, without the image module (core/image/ImageCodec.h): OpenEXR
// (through the OpenEXR library) and PNG (through libpng). Every render, bake, sheet and export
// writes one of these; encoding them here means a command that reads no image (a render from the
// IBL disk cache, a bake of a built-in environment) never loads OpenImageIO and the ~260 libraries
// behind it (a warm 128x128 reference render spent 365-375 ms of 0.61 s loading it to write its
// file; OpenEXR's and libpng's load is not measurable). Reading is the module's, but for EXR
// (core/image/BuiltinExrDecoder.h).
//
// They write what the module's OpenImageIO writers wrote, read back the same through it: EXR
// channels Y (one channel), R G (two), R G B, R G B A; ZIP compression; half or float; an
// "oiio:ColorSpace" string attribute when tagged. PNG grey, grey + alpha, RGB, RGBA of 8 or 16
// bits; an sRGB chunk (with its gAMA and cHRM) when tagged sRGB, a gAMA of 1.0 when tagged
// Linear, the tag also as an "oiio:ColorSpace" text. The caller's attributes become EXR string
// attributes or PNG text. ImageCodecTest compares both encoders decoded, row by row.
// Internal to core/ (core/image/ImageWriter).

#include <optional>
#include <string>
#include <vector>

#include "core/image/ImageCodec.h"

namespace facet {

// The writer of `path`'s extension (.exr, .png, any case) when Facet encodes it itself; nullopt
// for the others, which the image module writes.
std::optional<CodecWriterInfo> builtinImageWriterFor(const std::string& path);

// Encodes `samples` (spec.width x spec.height x spec.channels floats, rows top first, already
// clamped to what spec.sample holds) as `writer`'s format, which builtinImageWriterFor must have
// given (writer.builtin). False with *error on failure (*sampleRefused: the format cannot
// hold spec.sample, e.g. half-float PNG).
bool encodeBuiltinImage(const CodecWriterInfo& writer, const CodecEncodeSpec& spec, const float* samples,
    std::vector<unsigned char>* encoded, bool* sampleRefused, std::string* error);

} // namespace facet
