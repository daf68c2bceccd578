#include <epoxy/gl.h>

#include "render/TextureCache.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace facet {

namespace {

unsigned upload(const Image& image, ColorEncoding colorSpace)
{
    const int width = image.width();
    const int height = image.height();
    // The upload binds on the active unit: put back what was bound there, so uploading a texture
    // never unbinds another one (a renderer binding map i - 1 and then uploading map i must find
    // map i - 1 still bound).
    GLint previous = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    if (colorSpace == ColorEncoding::SRGB) {
        // Encoded values in [0, 1], quantised to 8 bits (what an sRGB file holds anyway).
        std::vector<unsigned char> bytes(std::size_t(width) * std::size_t(height) * 4);
        for (int y = 0; y < height; ++y) {
            const glm::vec4* row = &image.at(0, height - 1 - y);
            unsigned char* out = &bytes[std::size_t(y) * std::size_t(width) * 4];
            for (int x = 0; x < width; ++x)
                for (int c = 0; c < 4; ++c)
                    out[x * 4 + c] = static_cast<unsigned char>(std::lround(std::clamp(row[x][c], 0.0f, 1.0f) * 255.0f));
        }
        glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    } else {
        std::vector<glm::vec4> flipped(image.pixelCount());
        for (int y = 0; y < height; ++y)
            std::copy_n(&image.at(0, height - 1 - y), width, &flipped[std::size_t(y) * std::size_t(width)]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, width, height, 0, GL_RGBA, GL_FLOAT, flipped.data());
    }
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    if (epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic")
        || epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic")) {
        GLfloat maxAnisotropy = 1.0f;
        glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &maxAnisotropy);
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, std::min(8.0f, maxAnisotropy));
    }
    glBindTexture(GL_TEXTURE_2D, GLuint(previous));
    return texture;
}

} // namespace

TextureCache::~TextureCache() { clear(); }

void TextureCache::clear()
{
    for (auto& [key, entry] : m_textures)
        glDeleteTextures(1, &entry.texture);
    m_textures.clear();
}

unsigned TextureCache::get(const std::shared_ptr<const Image>& image, const std::string& path, std::int64_t timestamp,
                           ColorEncoding colorSpace, bool* uploaded)
{
    if (uploaded)
        *uploaded = false;
    if (!image || image->isEmpty())
        return 0;
    std::string name = path;
    if (name.empty()) {
        char address[64];
        std::snprintf(address, sizeof address, "<image %p>", static_cast<const void*>(image.get()));
        name = address;
    }
    const Key key {name, timestamp, int(colorSpace)};
    auto found = m_textures.find(key);
    if (found == m_textures.end()) {
        found = m_textures.emplace(key, Entry {upload(*image, colorSpace), false}).first;
        if (uploaded)
            *uploaded = true;
    }
    found->second.used = true;
    return found->second.texture;
}

void TextureCache::evictUnused()
{
    for (auto it = m_textures.begin(); it != m_textures.end();) {
        if (!it->second.used) {
            glDeleteTextures(1, &it->second.texture);
            it = m_textures.erase(it);
        } else {
            it->second.used = false;
            ++it;
        }
    }
}

} // namespace facet
