#pragma once
// A move-only owner of one GL texture name, and float read-back of a texture level. Destroy it
// with its context (or one sharing with it) current. Public headers of render/ include no GL
// header: targets and formats are plain unsigned values of the GL enums.

#include <vector>

namespace facet {

class GLTexture {
public:
    GLTexture() = default;
    // Generates a name for `target` (GL_TEXTURE_2D, GL_TEXTURE_CUBE_MAP, ...). Needs a current context.
    static GLTexture create(unsigned target);

    GLTexture(GLTexture&& other) noexcept;
    GLTexture& operator=(GLTexture&& other) noexcept;
    GLTexture(const GLTexture&) = delete;
    GLTexture& operator=(const GLTexture&) = delete;
    ~GLTexture();

    unsigned id() const { return m_id; }
    unsigned target() const { return m_target; }
    bool isValid() const { return m_id != 0; }

private:
    unsigned m_id = 0;
    unsigned m_target = 0;
};

// RGBA floats of one level of a 2D texture, or of one face (0..5, GL order) of a cubemap: rows
// in GL order (row 0 is t = 0, the first row uploaded). `width`/`height` receive the level's size.
// Keeps the caller's texture binding and pack alignment.
std::vector<float> readTextureLevel(const GLTexture& texture, int face, int level, int* width, int* height);
// The same as raw half floats (GL_HALF_FLOAT, exact for RGBA16F textures): for the disk cache.
std::vector<unsigned short> readTextureLevelHalf(const GLTexture& texture, int face, int level, int* width, int* height);

} // namespace facet
