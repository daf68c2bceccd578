#include "render/Framebuffer.h"

#include "render/GLDebug.h"

#include <epoxy/gl.h>

#include <QtGlobal>

#include <algorithm>
#include <cstring>
#include <utility>
#include <vector>

namespace facet {

namespace {

const char* framebufferStatusName(GLenum status)
{
    switch (status) {
    case GL_FRAMEBUFFER_UNDEFINED:
        return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
        return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
        return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_UNSUPPORTED:
        return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
        return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    default:
        return "unknown framebuffer status";
    }
}

// Drains the GL error queue, returning the first error (GL_NO_ERROR if none).
GLenum takeGLError()
{
    const GLenum first = glGetError();
    for (int guard = 0; guard < 16 && glGetError() != GL_NO_ERROR; ++guard) { }
    return first;
}

const char* formatName(FramebufferFormat format)
{
    return format == FramebufferFormat::RGBA32F ? "RGBA32F" : "RGBA16F";
}

} // namespace

std::optional<Framebuffer> Framebuffer::create(
    int width, int height, FramebufferFormat format, std::string* error)
{
    const auto failWith = [error](const std::string& message) -> std::optional<Framebuffer> {
        if (error)
            *error = "Framebuffer::create: " + message;
        return std::nullopt;
    };
    const std::string sizeText = std::to_string(width) + "x" + std::to_string(height);

    GLint maxRenderbufferSize = 0;
    GLint maxTextureSize = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbufferSize);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTextureSize);
    const int maxSize = std::min(maxRenderbufferSize, maxTextureSize);
    if (width < 1 || height < 1 || width > maxSize || height > maxSize)
        return failWith("size " + sizeText + " is outside 1.." + std::to_string(maxSize));
    takeGLError(); // errors of earlier calls are not ours to report

    Framebuffer result;
    result.m_width = width;
    result.m_height = height;
    result.m_format = format;

    GLint previousFramebuffer = 0;
    GLint previousTexture = 0;
    GLint previousRenderbuffer = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previousFramebuffer);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &previousTexture);
    glGetIntegerv(GL_RENDERBUFFER_BINDING, &previousRenderbuffer);

    glGenTextures(1, &result.m_colorTexture);
    glBindTexture(GL_TEXTURE_2D, result.m_colorTexture);
    glTexImage2D(GL_TEXTURE_2D, 0, format == FramebufferFormat::RGBA32F ? GL_RGBA32F : GL_RGBA16F, width,
        height, 0, GL_RGBA, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);

    glGenRenderbuffers(1, &result.m_depthRenderbuffer);
    glBindRenderbuffer(GL_RENDERBUFFER, result.m_depthRenderbuffer);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);

    glGenFramebuffers(1, &result.m_framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, result.m_framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, result.m_colorTexture, 0);
    glFramebufferRenderbuffer(
        GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, result.m_depthRenderbuffer);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    const GLenum allocationError = takeGLError();

    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previousFramebuffer));
    glBindTexture(GL_TEXTURE_2D, GLuint(previousTexture));
    glBindRenderbuffer(GL_RENDERBUFFER, GLuint(previousRenderbuffer));

    if (allocationError != GL_NO_ERROR)
        return failWith(std::string("allocating ") + formatName(format) + " " + sizeText + " failed ("
            + glErrorName(allocationError) + ")");
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return failWith(std::string(formatName(format)) + " " + sizeText
            + " with 24-bit depth is incomplete (" + framebufferStatusName(status) + ")");
    return result;
}

Framebuffer::Framebuffer(Framebuffer&& other) noexcept
    : m_width(std::exchange(other.m_width, 0))
    , m_height(std::exchange(other.m_height, 0))
    , m_format(other.m_format)
    , m_framebuffer(std::exchange(other.m_framebuffer, 0u))
    , m_colorTexture(std::exchange(other.m_colorTexture, 0u))
    , m_depthRenderbuffer(std::exchange(other.m_depthRenderbuffer, 0u))
{
}

Framebuffer& Framebuffer::operator=(Framebuffer&& other) noexcept
{
    if (this != &other) {
        destroy();
        m_width = std::exchange(other.m_width, 0);
        m_height = std::exchange(other.m_height, 0);
        m_format = other.m_format;
        m_framebuffer = std::exchange(other.m_framebuffer, 0u);
        m_colorTexture = std::exchange(other.m_colorTexture, 0u);
        m_depthRenderbuffer = std::exchange(other.m_depthRenderbuffer, 0u);
    }
    return *this;
}

Framebuffer::~Framebuffer()
{
    destroy();
}

void Framebuffer::destroy()
{
    // A moved-from (or never completed) framebuffer owns nothing and makes no GL call, so it
    // may die without a current context.
    if (m_framebuffer)
        glDeleteFramebuffers(1, &m_framebuffer);
    if (m_colorTexture)
        glDeleteTextures(1, &m_colorTexture);
    if (m_depthRenderbuffer)
        glDeleteRenderbuffers(1, &m_depthRenderbuffer);
    m_framebuffer = m_colorTexture = m_depthRenderbuffer = 0;
    m_width = m_height = 0;
}

void Framebuffer::bind() const
{
    Q_ASSERT(m_framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer);
    glViewport(0, 0, m_width, m_height);
}

void Framebuffer::clear(const glm::vec4& color, float depth) const
{
    bind();
    glClearColor(color.x, color.y, color.z, color.w);
    glClearDepth(double(depth));
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

namespace {

// Reads a rectangle (origin bottom-left, GL's) of `framebuffer`'s colour (`type`: GL_FLOAT or
// GL_UNSIGNED_BYTE, RGBA) into `out`, bottom row first, keeping the caller's GL_READ_FRAMEBUFFER,
// read buffer and pixel-pack state. `checkErrors`: false when GL reported an error (a
// multisampled framebuffer); the errors earlier calls left pending are consumed to tell, so only a
// read of a framebuffer Facet did not make (the window's) checks, and GLDebug still sees the
// errors of everything else.
bool readRegion(
    GLuint framebuffer, int x, int y, int width, int height, GLenum type, void* out, bool checkErrors)
{
    GLint previousReadFramebuffer = 0;
    GLint previousPackBuffer = 0;
    GLint previousPackAlignment = 4;
    GLint previousPackRowLength = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previousReadFramebuffer);
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &previousPackBuffer);
    glGetIntegerv(GL_PACK_ALIGNMENT, &previousPackAlignment);
    glGetIntegerv(GL_PACK_ROW_LENGTH, &previousPackRowLength);
    if (checkErrors)
        while (glGetError() != GL_NO_ERROR) { }

    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glReadBuffer(framebuffer == 0 ? GL_BACK : GL_COLOR_ATTACHMENT0);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    // GL_FLOAT read-back of a float target returns the stored values unclamped.
    glReadPixels(x, y, width, height, GL_RGBA, type, out);
    const bool ok = !checkErrors || glGetError() == GL_NO_ERROR;

    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(previousReadFramebuffer));
    glBindBuffer(GL_PIXEL_PACK_BUFFER, GLuint(previousPackBuffer));
    glPixelStorei(GL_PACK_ALIGNMENT, previousPackAlignment);
    glPixelStorei(GL_PACK_ROW_LENGTH, previousPackRowLength);
    return ok;
}

} // namespace

Image Framebuffer::readPixels() const
{
    Q_ASSERT(m_framebuffer);
    const std::size_t rowFloats = std::size_t(m_width) * 4;
    std::vector<float> bottomUp(rowFloats * std::size_t(m_height));
    readRegion(m_framebuffer, 0, 0, m_width, m_height, GL_FLOAT, bottomUp.data(), false);

    Image image(m_width, m_height);
    static_assert(sizeof(glm::vec4) == 4 * sizeof(float), "Image rows are packed RGBA floats");
    for (int row = 0; row < m_height; ++row) {
        const float* source = bottomUp.data() + std::size_t(m_height - 1 - row) * rowFloats;
        std::memcpy(&image.at(0, row), source, rowFloats * sizeof(float));
    }
    return image;
}

std::optional<glm::vec4> Framebuffer::readPixel(int x, int row) const
{
    Q_ASSERT(m_framebuffer);
    if (x < 0 || row < 0 || x >= m_width || row >= m_height)
        return std::nullopt;
    glm::vec4 value(0.0f);
    readRegion(m_framebuffer, x, m_height - 1 - row, 1, 1, GL_FLOAT, &value, false);
    return value;
}

std::optional<glm::u8vec4> readDisplayPixel(unsigned framebuffer, int x, int yFromBottom)
{
    glm::u8vec4 value(0);
    if (x < 0 || yFromBottom < 0
        || !readRegion(framebuffer, x, yFromBottom, 1, 1, GL_UNSIGNED_BYTE, &value, true))
        return std::nullopt;
    return value;
}

} // namespace facet
