#pragma once
// An offscreen float render target: a colour texture (RGBA16F or RGBA32F) and a 24-bit depth
// renderbuffer, with read-back into a facet::Image. The renderer draws into one of these; the
// viewport and the headless commands only present or save what it holds.

#include "core/image/Image.h"

#include <glm/ext/vector_uint4_sized.hpp>
#include <glm/vec4.hpp>

#include <optional>
#include <string>

namespace facet {

enum class FramebufferFormat {
    RGBA16F, // half floats: the renderer's working format (range +-65504, 11-bit precision)
    RGBA32F, // full floats: reference renders, accuracy tests
};

class Framebuffer {
public:
    // Needs a current GL context. Returns nullopt with `error` set to "Framebuffer::create: ..." for
    // a size outside [1, GL_MAX_RENDERBUFFER_SIZE], an allocation failure or an incomplete framebuffer.
    // Leaves the previous GL_FRAMEBUFFER binding in place.
    static std::optional<Framebuffer> create(
        int width, int height, FramebufferFormat format, std::string* error);

    Framebuffer(Framebuffer&& other) noexcept;
    Framebuffer& operator=(Framebuffer&& other) noexcept;
    Framebuffer(const Framebuffer&) = delete;
    Framebuffer& operator=(const Framebuffer&) = delete;
    // Deletes the GL objects: the context that created them (or one sharing with it) must be current.
    ~Framebuffer();

    int width() const { return m_width; }
    int height() const { return m_height; }
    FramebufferFormat format() const { return m_format; }
    // GL names, for the renderer and for presenting (sampling or blitting the colour texture).
    unsigned int framebufferId() const { return m_framebuffer; }
    unsigned int colorTexture() const { return m_colorTexture; }

    // Binds it as GL_FRAMEBUFFER (draw and read) and sets the viewport to its full size.
    void bind() const;
    // Clears colour (unclamped: float targets keep 3.5 or -2) and depth; binds it first.
    void clear(const glm::vec4& color, float depth = 1.0f) const;
    // Reads the colour attachment as float RGBA, top row first (GL's rows are bottom-up). Keeps the
    // caller's GL_READ_FRAMEBUFFER and pixel-pack state.
    Image readPixels() const;
    // One texel, x from the left, `row` from the TOP (as readPixels() orders them); nullopt
    // outside the target.
    std::optional<glm::vec4> readPixel(int x, int row) const;

private:
    Framebuffer() = default;
    void destroy();

    int m_width = 0;
    int m_height = 0;
    FramebufferFormat m_format = FramebufferFormat::RGBA16F;
    unsigned int m_framebuffer = 0;
    unsigned int m_colorTexture = 0;
    unsigned int m_depthRenderbuffer = 0;
};

// One pixel of an 8-bit framebuffer (a window's, a widget's: what the screen shows), x from the
// left, y from the BOTTOM (GL's); `framebuffer` 0 reads the default one's back buffer. nullopt
// when it cannot be read (a multisampled framebuffer, a pixel outside it on some drivers).
// Keeps the caller's read framebuffer and pixel-pack state.
std::optional<glm::u8vec4> readDisplayPixel(unsigned framebuffer, int x, int yFromBottom);

} // namespace facet
