#pragma once
// An image file opened through the image codec (core/image/ImageCodec.h) with only its header read: what
// Image::load (float RGBA, environments) and MapImage::load (material maps in their own bit depth) share. It
// refuses what must never be read (a folder, a device, a FIFO), reads an image embedded in a glTF asset
// ("asset.glb#images/2", core/gltf/GltfImport.h) from memory, and keeps alpha unassociated (as
// PNG/TIFF store it: a cut-out base colour keeps its colour where alpha is 0).
//
// Internal to core/: callers use Image or MapImage.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/image/Image.h"
#include "core/image/ImageCodec.h"

namespace facet {

class ImageReader {
public:
    // Opens `path` and reads its header. nullopt with *error "<function>: <path>: <reason>" (or
    // "<function>: readGltfImage: ..." for an embedded image that cannot be read).
    static std::optional<ImageReader> open(const std::string& path, const char* function, std::string* error);

    ImageReader(ImageReader&&) = default;
    ImageReader& operator=(ImageReader&&) = default;
    ~ImageReader();

    const CodecHeader& header() const { return codec()->header(m_decoder.get()); }
    // Reads rows [begin, end) as ImageCodec::read does; false with *error
    // "<function>: <path>: <the decoder's message>".
    bool read(int begin, int end, int channels, CodecSample as, void* data, std::ptrdiff_t xstride,
        std::ptrdiff_t ystride, const char* function, std::string* error);
    // The whole image.
    bool readAll(int channels, CodecSample as, void* data, std::ptrdiff_t xstride, std::ptrdiff_t ystride,
        const char* function, std::string* error)
    {
        return read(0, header().height, channels, as, data, xstride, ystride, function, error);
    }
    // The file's colour-space name as OpenImageIO reported it ("sRGB", "Linear", ...), if any.
    const std::string& colorSpaceName() const { return header().colorSpaceName; }
    // What the numbers mean: SRGB when the colour space says sRGB (or a gamma curve), Linear when
    // it says linear; without either, 8/16-bit integer files are SRGB and float files Linear.
    ColorEncoding encoding() const;
    // Two channels named R and G (a two-channel EXR, e.g. a normal map's X and Y): red and green,
    // not grey + alpha (what PNG and TIFF mean by two channels).
    bool twoColourChannels() const;

    // Checks the header's size before anything is allocated: positive, flat (depth 1), with
    // channels. False with *error as open() words it.
    bool checkHeader(const char* function, std::string* error) const;
    // Whether the file is large enough to hold the pixels its header claims (no codec packs more
    // than kMaxPixelsPerByte into a byte): a cut-short or crafted file is refused before its
    // claim is allocated. Called after the caller's own size limits, whose messages say more.
    bool checkSizeAgainstFile(const char* function, std::string* error) const;

private:
    ImageReader() = default;

    std::string m_path;
    long long m_fileSize = -1; // of the file at m_path (-1: embedded, or unknown)
    bool m_exr = false; // the file's signature is OpenEXR's
    // The memory an embedded image is decoded from; must outlive m_decoder.
    std::unique_ptr<std::vector<unsigned char>> m_embedded;
    struct Close {
        const ImageCodec* codec;
        void operator()(ImageDecoder* decoder) const { codec->close(decoder); }
    };
    std::unique_ptr<ImageDecoder, Close> m_decoder {nullptr, Close {nullptr}};
    const ImageCodec* codec() const { return m_decoder.get_deleter().codec; }
};

// "<function>: <path>: <problem>" on one line (OIIO's messages can span several lines).
void setImageError(
    std::string* error, const char* function, const std::string& path, const std::string& problem);
// The same for the exception being handled (call it in a catch block): "out of memory" for
// std::bad_alloc, the exception's text, else "unknown error while <doing>" ("reading", "writing").
void setImageErrorFromException(
    std::string* error, const char* function, const std::string& path, const char* doing);

} // namespace facet
