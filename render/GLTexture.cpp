#include <epoxy/gl.h>

#include "render/GLTexture.h"

#include <utility>

namespace facet {

GLTexture GLTexture::create(unsigned target)
{
    GLTexture texture;
    glGenTextures(1, &texture.m_id);
    texture.m_target = target;
    return texture;
}

GLTexture::GLTexture(GLTexture&& other) noexcept
    : m_id(std::exchange(other.m_id, 0u))
    , m_target(other.m_target)
{
}

GLTexture& GLTexture::operator=(GLTexture&& other) noexcept
{
    if (this != &other) {
        if (m_id)
            glDeleteTextures(1, &m_id);
        m_id = std::exchange(other.m_id, 0u);
        m_target = other.m_target;
    }
    return *this;
}

GLTexture::~GLTexture()
{
    if (m_id)
        glDeleteTextures(1, &m_id);
}

namespace {

template <typename T>
std::vector<T> readLevel(const GLTexture& texture, int face, int level, int* width, int* height, GLenum type)
{
    const GLenum binding = texture.target() == GL_TEXTURE_CUBE_MAP ? GL_TEXTURE_BINDING_CUBE_MAP : GL_TEXTURE_BINDING_2D;
    GLint previous = 0;
    glGetIntegerv(binding, &previous);
    GLint alignment = 4;
    glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
    GLint packBuffer = 0;
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &packBuffer);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glBindTexture(texture.target(), texture.id());
    const GLenum target = texture.target() == GL_TEXTURE_CUBE_MAP ? GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face)
                                                                  : texture.target();
    GLint w = 0;
    GLint h = 0;
    glGetTexLevelParameteriv(target, level, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(target, level, GL_TEXTURE_HEIGHT, &h);
    std::vector<T> pixels(std::size_t(w) * std::size_t(h) * 4);
    if (!pixels.empty())
        glGetTexImage(target, level, GL_RGBA, type, pixels.data());
    glBindTexture(texture.target(), GLuint(previous));
    glPixelStorei(GL_PACK_ALIGNMENT, alignment);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, GLuint(packBuffer));
    if (width)
        *width = w;
    if (height)
        *height = h;
    return pixels;
}

} // namespace

std::vector<float> readTextureLevel(const GLTexture& texture, int face, int level, int* width, int* height)
{
    return readLevel<float>(texture, face, level, width, height, GL_FLOAT);
}

std::vector<unsigned short> readTextureLevelHalf(const GLTexture& texture, int face, int level, int* width, int* height)
{
    return readLevel<unsigned short>(texture, face, level, width, height, GL_HALF_FLOAT);
}

} // namespace facet
