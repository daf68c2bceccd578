#include "render/GLDebug.h"

#include <epoxy/gl.h>

#include <string>

namespace facet {

namespace {

GLDebugSeverity severityOf(GLenum severity)
{
    switch (severity) {
    case GL_DEBUG_SEVERITY_HIGH:
        return GLDebugSeverity::High;
    case GL_DEBUG_SEVERITY_MEDIUM:
        return GLDebugSeverity::Medium;
    case GL_DEBUG_SEVERITY_LOW:
        return GLDebugSeverity::Low;
    default:
        return GLDebugSeverity::Notification;
    }
}

const char* severityName(GLDebugSeverity severity)
{
    switch (severity) {
    case GLDebugSeverity::High:
        return "high";
    case GLDebugSeverity::Medium:
        return "medium";
    case GLDebugSeverity::Low:
        return "low";
    case GLDebugSeverity::Notification:
        break;
    }
    return "notification";
}

const char* typeName(GLenum type)
{
    switch (type) {
    case GL_DEBUG_TYPE_ERROR:
        return "GL error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR:
        return "GL deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR:
        return "GL undefined behaviour";
    case GL_DEBUG_TYPE_PORTABILITY:
        return "GL portability";
    case GL_DEBUG_TYPE_PERFORMANCE:
        return "GL performance";
    default:
        return "GL message";
    }
}

void GLAPIENTRY onDebugMessage(GLenum /*source*/, GLenum type, GLuint /*id*/, GLenum severity, GLsizei length,
    const GLchar* message, const void* user)
{
    const auto* log = static_cast<const GLDebugLogFunction*>(user);
    if (!log || !*log)
        return;
    const GLDebugSeverity level = severityOf(severity);
    std::string text = std::string(typeName(type)) + " (" + severityName(level) + "): ";
    text.append(message, length >= 0 ? std::size_t(length) : std::char_traits<char>::length(message));
    (*log)(level, text);
}

bool hasDebugOutput()
{
    return epoxy_gl_version() >= 43 || epoxy_has_gl_extension("GL_KHR_debug");
}

} // namespace

bool enableGLDebugOutput(const GLDebugLogFunction* log)
{
    if (!hasDebugOutput())
        return false;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, log);
    return true;
}

void disableGLDebugOutput()
{
    if (!hasDebugOutput())
        return;
    glDebugMessageCallback(nullptr, nullptr);
    glDisable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDisable(GL_DEBUG_OUTPUT);
}

std::string glErrorName(unsigned error)
{
    switch (error) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "GL error " + std::to_string(error);
    }
}

} // namespace facet
