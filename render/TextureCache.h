#pragma once
// Material textures on the GPU, keyed by (path, file timestamp, colour space) as the scene gives
// them (render/ reads no files: core loaded the MapImage). Each map keeps its file's bit depth and
// channels (MapTextureFormat below: an 8-bit RGB JPEG becomes GL_RGB8 or GL_SRGB8, a grey PNG
// GL_R8 swizzled to read (g, g, g, 1), a 16-bit PNG GL_RGB16, a float EXR GL_RGB16F), mipmapped
// once per texture (on the CPU, a band at a time: render/MipChain.h), trilinear, repeat, with the
// anisotropy the caller sets (render/TextureFiltering.h). MapImage stores rows bottom to top,
// OpenGL's order, so rows go up as they are.
//
// Two ways in:
//  - get(): the whole texture now (Renderer::render on a miss; `facet render` and tests).
//  - request() + uploadSlice(): the viewport's way. request() queues the upload and does no GL
//    work; uploadSlice() uploads rows of the queued textures for a bounded time between frames
//    and finishes a texture (mipmaps) when its last row is in; isReady() says when a texture is
//    complete. A caller draws only complete textures: get() on an incomplete one finishes it
//    first, so no frame ever samples a half-uploaded texture.

#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "core/image/MapImage.h"
#include "core/material/Material.h"
#include "render/MipChain.h"

namespace facet {

// How one MapImage goes to OpenGL: the GL enums (as plain numbers: no GL header here), the
// swizzle that makes grey and grey + alpha read like RGBA (core/image/MapImage.h texel()), and the
// conversion the upload makes on the way (none for most maps).
struct MapTextureFormat {
    enum class Conversion {
        None,
        ExpandToRgb, // 8-bit sRGB grey / grey + alpha / red + green: OpenGL has no 1- or 2-channel
                     // sRGB format, so the upload expands to GL_SRGB8 (GL_SRGB8_ALPHA8 with alpha)
        SrgbToLinearHalf, // 16-bit or float read as sRGB: decoded to linear half floats on upload
                          // (OpenGL has no 16-bit sRGB format); MapImage::linearHalfFromSrgb
    };
    unsigned internalFormat = 0; // GL_SRGB8_ALPHA8, GL_R8, GL_RGB16, GL_RGBA16F, ...
    unsigned format = 0; // GL_RED, GL_RG, GL_RGB, GL_RGBA
    unsigned type = 0; // GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_HALF_FLOAT
    int uploadChannels = 4; // channels per texel of the uploaded data
    int uploadBytesPerSample = 1;
    Conversion conversion = Conversion::None;
    std::array<int, 4> swizzle {}; // GL_TEXTURE_SWIZZLE_RGBA (GL_RED, GL_ONE, ...)
    MipFilter mipFilter = MipFilter::Unorm8; // how its mipmaps are made (render/MipChain.h)
    const char* name = ""; // "GL_R8", for messages and tests

    static MapTextureFormat of(MapLayout layout, MapSampleType type, ColorEncoding colorSpace);
};

class TextureCache {
public:
    TextureCache(); // needs the GL context current (reads its limits)
    TextureCache(const TextureCache&) = delete;
    TextureCache& operator=(const TextureCache&) = delete;
    ~TextureCache(); // deletes the textures: the context must be current

    // The GL texture for the image, complete: uploaded whole on a miss (*uploaded = true), an
    // upload under way finished. An empty path keys by the MapImage's address instead. 0 for a
    // null or empty image, and for one larger than GL_MAX_TEXTURE_SIZE (problem() says why).
    unsigned get(const std::shared_ptr<const MapImage>& image, const std::string& path,
        std::int64_t timestamp, ColorEncoding colorSpace, bool* uploaded);

    // Whether get() would return a complete texture without uploading anything.
    bool isReady(const std::string& path, std::int64_t timestamp, ColorEncoding colorSpace) const;
    // The timestamp of a complete texture of `path` in `colorSpace` (any timestamp: the version
    // of a file that is being reloaded), if there is one.
    std::optional<std::int64_t> readyTimestamp(const std::string& path, ColorEncoding colorSpace) const;
    // Queues the upload of a texture that is not ready (no GL work) and keeps it (and a ready
    // one) from evictUnused() this frame. False, with problem() set, for an image that cannot be
    // a texture (larger than GL_MAX_TEXTURE_SIZE) and for a stand-in without pixels
    // (MapImage::withoutPixels) whose texture is not here: its file must be decoded again.
    bool request(const std::shared_ptr<const MapImage>& image, const std::string& path,
        std::int64_t timestamp, ColorEncoding colorSpace);

    struct SliceResult {
        int completed = 0; // textures finished in this slice
        std::size_t bytes = 0; // bytes uploaded (every level)
        double milliseconds = 0.0; // GL work finished (glFinish)
    };
    // Uploads bands of rows (about 1 MiB each, mipmap levels made on the way) of the queued
    // textures, oldest first, until about `budgetMs` have passed (at least one band). Needs the
    // context current.
    SliceResult uploadSlice(double budgetMs);
    bool hasPendingUploads() const { return !m_queue.empty(); }
    int pendingUploads() const { return int(m_queue.size()); }

    // GL_TEXTURE_MAX_ANISOTROPY of every texture, now and later (clamped to the implementation's
    // maximum; 1 without the extension). Cheap when unchanged: call it every frame.
    void setMaxAnisotropy(float level);
    float maxAnisotropy() const { return m_anisotropy; }
    // Trilinear (GL_LINEAR_MIPMAP_LINEAR) or the nearer mip level (GL_LINEAR_MIPMAP_NEAREST) for
    // every texture, now and later; the default is TextureFiltering::trilinear for this GL.
    void setTrilinear(bool trilinear);
    bool trilinear() const { return m_trilinear; }

    // The sampler object of a map's sampler (core/material/Material.h TextureSampler): its wraps, its
    // filters (Auto: this cache's trilinear choice and anisotropy, as the textures' own state), or
    // 0 for the default sampler, which the textures' own state already is. Made once per distinct
    // sampler and kept in step with setMaxAnisotropy and setTrilinear; needs the context current.
    unsigned samplerFor(const TextureSampler& sampler);

    // Why the last refused image could not be a texture ("TextureCache: <path>: ...").
    const std::string& problem() const { return m_problem; }

    // Deletes textures neither used nor requested since the last call (call once per frame
    // after drawing); a queued upload that is no longer requested is dropped with it.
    void evictUnused();
    // Counts the texture of `path` (that version, that colour space), if here, as used this
    // frame without drawing it: a grid cell kept from an earlier frame still shows it.
    void touch(const std::string& path, std::int64_t timestamp, ColorEncoding colorSpace);
    std::size_t size() const { return m_textures.size(); }
    void clear();

    // Level-0 texels uploaded since the cache was made (tests, benchmarks).
    std::uint64_t bytesUploaded() const { return m_bytesUploaded; }

private:
    using Key = std::tuple<std::string, std::int64_t, int>;
    struct Entry {
        unsigned texture = 0;
        bool used = false;
        bool complete = false;
        std::shared_ptr<const MapImage> image; // until complete
        // For an image without a path (keyed by its address): which image it was made from. Once
        // that image is gone another can be made at its address, and the entry is stale.
        std::weak_ptr<const MapImage> identity;
        MapTextureFormat format;
        std::vector<unsigned char> converted; // level 0 in the upload format, when it converts
        std::unique_ptr<MipChain> mips; // the levels, until complete
        int level = 0; // the level under way
        int nextRow = 0; // its rows uploaded
    };
    static Key keyFor(const std::shared_ptr<const MapImage>& image, const std::string& path,
        std::int64_t timestamp, ColorEncoding colorSpace);
    // The entry of `key`, or end() (a stale entry of a path-less image is deleted on the way).
    std::map<Key, Entry>::iterator findCurrent(
        const Key& key, const std::shared_ptr<const MapImage>& image, const std::string& path);
    bool fits(const MapImage& image, const std::string& path);
    bool hasPixels(const MapImage& image, const std::string& path); // a stand-in cannot be uploaded
    Entry& begin(const Key& key, const std::shared_ptr<const MapImage>& image, ColorEncoding colorSpace);
    void convertRows(Entry& entry, int row, int rows);
    std::size_t uploadBand(Entry& entry);
    bool uploadStep(Entry& entry, std::size_t* bytes); // one band; true when the texture is complete
    void finish(Entry& entry);
    void removeFromQueue(const Key& key);

    void applySamplerState(unsigned id, const TextureSampler& sampler) const;
    std::map<Key, Entry> m_textures;
    std::map<std::array<int, 4>, std::pair<unsigned, TextureSampler>> m_samplers;
    std::deque<Key> m_queue; // uploads under way, oldest first
    int m_maxTextureSize = 0;
    float m_maxSupportedAnisotropy = 1.0f; // 1: no anisotropic filtering extension
    bool m_textureStorage = false; // glTexStorage2D (GL 4.2, ARB_texture_storage)
    float m_anisotropy = 1.0f;
    bool m_trilinear = true;
    std::string m_problem;
    std::uint64_t m_bytesUploaded = 0;
};

} // namespace facet
