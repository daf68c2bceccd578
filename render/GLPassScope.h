#pragma once
// Scaffolding for offscreen passes that run inside a caller's frame (the IBL precompute): the GL
// state they change, restored on scope exit, and the per-run container objects they draw with.
// Internal to render/. Needs a current context and epoxy's GL declarations.

#include <epoxy/gl.h>

#include <array>

namespace facet {

// The GL state the passes change, restored on scope exit so that a caller's renderer is not
// disturbed (framebuffer, viewport, program, vertex array, unit 0's bindings, capabilities).
class GLStateGuard {
public:
    GLStateGuard()
    {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &m_drawFramebuffer);
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &m_readFramebuffer);
        glGetIntegerv(GL_VIEWPORT, m_viewport);
        glGetIntegerv(GL_CURRENT_PROGRAM, &m_program);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &m_vertexArray);
        glGetIntegerv(GL_ACTIVE_TEXTURE, &m_activeTexture);
        glActiveTexture(GL_TEXTURE0);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &m_texture2D);
        glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &m_textureCube);
        glGetIntegerv(GL_UNPACK_ALIGNMENT, &m_unpackAlignment);
        glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &m_unpackBuffer);
        for (std::size_t i = 0; i < kCapabilities.size(); ++i) {
            m_enabled[i] = glIsEnabled(kCapabilities[i]);
            glDisable(kCapabilities[i]);
        }
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    }
    ~GLStateGuard()
    {
        for (std::size_t i = 0; i < kCapabilities.size(); ++i)
            (m_enabled[i] ? glEnable : glDisable)(kCapabilities[i]);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(m_drawFramebuffer));
        glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(m_readFramebuffer));
        glViewport(m_viewport[0], m_viewport[1], m_viewport[2], m_viewport[3]);
        glUseProgram(GLuint(m_program));
        glBindVertexArray(GLuint(m_vertexArray));
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, GLuint(m_texture2D));
        glBindTexture(GL_TEXTURE_CUBE_MAP, GLuint(m_textureCube));
        glActiveTexture(GLenum(m_activeTexture));
        glPixelStorei(GL_UNPACK_ALIGNMENT, m_unpackAlignment);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, GLuint(m_unpackBuffer));
    }
    GLStateGuard(const GLStateGuard&) = delete;
    GLStateGuard& operator=(const GLStateGuard&) = delete;

private:
    static constexpr std::array<GLenum, 5> kCapabilities
        = {GL_DEPTH_TEST, GL_BLEND, GL_SCISSOR_TEST, GL_CULL_FACE, GL_STENCIL_TEST};
    GLint m_drawFramebuffer = 0, m_readFramebuffer = 0, m_viewport[4] = {}, m_program = 0, m_vertexArray = 0;
    GLint m_activeTexture = GL_TEXTURE0, m_texture2D = 0, m_textureCube = 0, m_unpackAlignment = 4,
          m_unpackBuffer = 0;
    std::array<GLboolean, kCapabilities.size()> m_enabled {};
};

// The vertex array and framebuffer of one precompute run. Container objects belong to the
// context that made them (they are not shared within a share group, unlike textures and
// programs), and one IblPrecompute serves every view of a window, each in its own context: so
// they are made per run, in the context current then (two GL calls, nothing beside a pass).
// Declared after a GLStateGuard, they go first; deleting a bound object unbinds it, and the
// guard then restores the caller's bindings.
class PassObjects {
public:
    PassObjects()
    {
        glGenVertexArrays(1, &m_vertexArray);
        glGenFramebuffers(1, &m_framebuffer);
        glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer);
        glBindVertexArray(m_vertexArray);
    }
    ~PassObjects()
    {
        glDeleteVertexArrays(1, &m_vertexArray);
        glDeleteFramebuffers(1, &m_framebuffer);
    }
    PassObjects(const PassObjects&) = delete;
    PassObjects& operator=(const PassObjects&) = delete;

private:
    GLuint m_vertexArray = 0;
    GLuint m_framebuffer = 0;
};

} // namespace facet
