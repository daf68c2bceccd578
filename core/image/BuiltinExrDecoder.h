#pragma once
// OpenEXR files decoded by core itself, through the OpenEXR library it already links to encode
// them (core/image/BuiltinImageEncoders.h), so that reading an environment or a map from an EXR does
// not load the image module and OpenImageIO with it (core/image/ImageCodec.h: about 0.37 s and 100 MB
// of a process that reads one image). It decodes what OpenImageIO would, value for value:
// ExrReadingTest::builtinExrDecoderMatchesTheModule reads a table of files both ways.
//
// Handled: part 0 of a flat (not deep) scanline or tiled file, any compression, the data window
// as the image (as OpenImageIO reads it), channels named R, G, B, A or Y without a layer, every
// one half or every one float, none subsampled; channels ordered as OpenImageIO orders them
// (R, G, B, Y, A), colour space "Linear". Anything else (layers, luminance-chroma, mixed or
// 32-bit integer channels, deep data) is left to the module: builtinExrCodec's open returns
// null with *handled false and ImageReader opens the file through the module instead.
// Internal to core/ (core/image/ImageReader).

#include <string>

#include "core/image/ImageCodec.h"

namespace facet {

// A codec table whose open, header, read, lastError and close decode EXR files (read converts to
// Float or Half only; the writer functions are null). Its open has the module's signature; use
// openBuiltinExr to learn whether a file is one it handles.
const ImageCodec& builtinExrCodec();

// Opens `path` (an OpenEXR file by its signature) when builtinExrCodec handles it: the decoder,
// or null with *error when the file cannot be read (damaged), or null with *handled false (and
// no error) when the module should read it.
ImageDecoder* openBuiltinExr(const std::string& path, bool* handled, std::string* error);

} // namespace facet
