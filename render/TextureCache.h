#pragma once
// Material textures on the GPU, keyed by (path, file timestamp, colour space) as the scene gives
// them (render/ reads no files: core loaded the Image). sRGB maps become GL_SRGB8_ALPHA8 (the
// hardware decodes before filtering), linear maps GL_RGBA16F (normal maps keep 16-bit precision);
// both mipmapped, trilinear, repeat. Rows are flipped on upload so that uv (0, 0) is the image's
// bottom-left (core/Mesh.h UV convention) while Image stores the top row first.

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <tuple>

#include "core/Image.h"

namespace facet {

class TextureCache {
public:
    TextureCache() = default;
    TextureCache(const TextureCache&) = delete;
    TextureCache& operator=(const TextureCache&) = delete;
    ~TextureCache(); // deletes the textures: the context must be current

    // The GL texture for the image, uploading it on a miss (*uploaded = true). An empty path keys
    // by the Image's address instead. 0 for a null or empty image.
    unsigned get(const std::shared_ptr<const Image>& image, const std::string& path, std::int64_t timestamp,
                 ColorEncoding colorSpace, bool* uploaded);
    // Deletes textures not used since the last call (call once per frame after drawing).
    void evictUnused();
    std::size_t size() const { return m_textures.size(); }
    void clear();

private:
    using Key = std::tuple<std::string, std::int64_t, int>;
    struct Entry {
        unsigned texture = 0;
        bool used = false;
    };
    std::map<Key, Entry> m_textures;
};

} // namespace facet
