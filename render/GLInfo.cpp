#include "render/GLInfo.h"

#include <epoxy/gl.h>

#include <algorithm>

#include "core/support/AsciiText.h"

namespace facet {

std::string GLInfo::summary() const
{
    if (!isValid())
        return "OpenGL unavailable";
    std::string text = "OpenGL " + version;
    if (!renderer.empty())
        text += ", " + renderer;
    return text;
}

bool isSoftwareRendererName(const std::string& renderer)
{
    const std::string name = asciiLowercase(renderer);
    for (const char* software :
        {"llvmpipe", "softpipe", "software rasterizer", "swrast", "swiftshader", "gdi generic"})
        if (name.find(software) != std::string::npos)
            return true;
    return false;
}

static std::string glString(GLenum name)
{
    const auto* text = reinterpret_cast<const char*>(glGetString(name));
    return text ? std::string(text) : std::string();
}

GLInfo queryCurrentGLInfo()
{
    GLInfo info;
    // epoxy_gl_version() returns 0 without a current context; calling GL then would abort.
    const int epoxyVersion = epoxy_gl_version();
    if (epoxyVersion == 0)
        return info;

    info.version = glString(GL_VERSION);
    info.renderer = glString(GL_RENDERER);
    info.vendor = glString(GL_VENDOR);
    info.shadingLanguageVersion = glString(GL_SHADING_LANGUAGE_VERSION);
    // GL_MAJOR_VERSION exists from 3.0; epoxy parsed GL_VERSION for older contexts.
    if (epoxyVersion >= 30) {
        glGetIntegerv(GL_MAJOR_VERSION, &info.major);
        glGetIntegerv(GL_MINOR_VERSION, &info.minor);
    } else {
        info.major = epoxyVersion / 10;
        info.minor = epoxyVersion % 10;
    }
    if (info.atLeast(3, 2)) {
        GLint profileMask = 0;
        glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profileMask);
        info.coreProfile = (profileMask & GL_CONTEXT_CORE_PROFILE_BIT) != 0;
    }
    info.hasCompute = info.atLeast(4, 3) || epoxy_has_gl_extension("GL_ARB_compute_shader");
    info.hasDebugOutput = info.atLeast(4, 3) || epoxy_has_gl_extension("GL_KHR_debug");
    if (info.atLeast(4, 6) || epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic")
        || epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic")) {
        GLfloat maxAnisotropy = 1.0f;
        glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &maxAnisotropy);
        info.maxAnisotropy = std::max(1.0f, maxAnisotropy);
    }
    info.softwareRasterizer = isSoftwareRendererName(info.renderer);
    return info;
}

} // namespace facet
