#pragma once
// What an OpenGL context offers: version, renderer, the features Facet's render paths choose by.

#include <string>

namespace facet {

struct GLInfo {
    std::string version; // GL_VERSION, e.g. "4.5 (Core Profile) Mesa 22.3.6"
    std::string renderer; // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string vendor; // GL_VENDOR
    std::string shadingLanguageVersion; // GL_SHADING_LANGUAGE_VERSION
    int major = 0; // GL_MAJOR_VERSION
    int minor = 0; // GL_MINOR_VERSION
    bool coreProfile = false; // GL_CONTEXT_CORE_PROFILE_BIT set in GL_CONTEXT_PROFILE_MASK
    bool hasCompute = false; // GL 4.3 or ARB_compute_shader
    bool hasDebugOutput = false; // GL 4.3 or KHR_debug
    // GL_MAX_TEXTURE_MAX_ANISOTROPY (GL 4.6, ARB/EXT_texture_filter_anisotropic); 1: none.
    float maxAnisotropy = 1.0f;
    // Rendering on the CPU (Mesa's llvmpipe, softpipe, swrast; SwiftShader; Microsoft's GDI
    // Generic), from GL_RENDERER: every texel fetched costs CPU time, so Facet filters less there
    // (render/TextureFiltering.h).
    bool softwareRasterizer = false;

    bool isValid() const { return major > 0; }
    bool atLeast(int wantedMajor, int wantedMinor) const
    {
        return major > wantedMajor || (major == wantedMajor && minor >= wantedMinor);
    }
    // One line for logs, status bars and About boxes: "OpenGL 4.5 (Core Profile) Mesa 22.3.6, llvmpipe
    // (...)".
    std::string summary() const;
};

// Whether a GL_RENDERER string names a software rasteriser (see GLInfo::softwareRasterizer).
bool isSoftwareRendererName(const std::string& renderer);

// Queries the context current on the calling thread, whichever created it (EGL, GLX through Qt).
// Returns an invalid GLInfo (major == 0) when no context is current.
GLInfo queryCurrentGLInfo();

} // namespace facet
