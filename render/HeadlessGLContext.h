#pragma once
// An OpenGL 4.1+ core context that needs no display server: EGL on a GPU device (NVIDIA's
// EGL_EXT_platform_device) or Mesa's surfaceless platform, with no config and no surface.
// GL functions (libepoxy) resolve for it once it is current. Qt cannot adopt such a context
// (docs/architecture.md, "OpenGL without a display"), so the headless subcommands and the *GLTest executables
// draw with it.

#include "render/GLDebug.h"
#include "render/GLInfo.h"

#include <memory>
#include <optional>
#include <string>

namespace facet {

struct HeadlessGLContextOptions {
    // Requests a debug context and routes its KHR_debug messages to `debugLog` (stderr if empty).
    bool debug = false;
    GLDebugLogFunction debugLog;
};

class HeadlessGLContext {
public:
    static constexpr int kRequiredMajor = 4;
    static constexpr int kRequiredMinor = 1;

    // Creates the context and makes it current on the calling thread. Tries GPU devices first, then
    // Mesa's surfaceless platform, then software devices; asks for 4.5 core, then 4.1 core. On
    // failure returns nullopt and sets `error` to "HeadlessGLContext::create: <step> failed (<EGL
    // error>) on <display>", or, when the driver offers less than 4.1 core (e.g. under
    // MESA_GL_VERSION_OVERRIDE=3.3), to a message naming the version it offers.
    static std::optional<HeadlessGLContext> create(std::string* error);
    static std::optional<HeadlessGLContext> create(
        const HeadlessGLContextOptions& options, std::string* error);

    HeadlessGLContext(HeadlessGLContext&& other) noexcept;
    HeadlessGLContext& operator=(HeadlessGLContext&& other) noexcept;
    HeadlessGLContext(const HeadlessGLContext&) = delete;
    HeadlessGLContext& operator=(const HeadlessGLContext&) = delete;
    // Destroys the context (releasing it first if it is current on this thread) and terminates the
    // EGL display once no other HeadlessGLContext uses it. GL objects of this context must be
    // deleted before, while it is current.
    ~HeadlessGLContext();

    // Makes the context current on the calling thread (any thread; one at a time). False on a
    // moved-from context or when EGL refuses (the context is current on another thread).
    bool makeCurrent();
    // Releases whatever EGL OpenGL context is current on the calling thread.
    void doneCurrent();
    bool isCurrent() const;

    // What the context is, queried once at creation.
    const GLInfo& info() const { return m_info; }
    // Which EGL display serves it, e.g. "Mesa surfaceless platform (EGL 1.5, Mesa Project)".
    const std::string& displayDescription() const { return m_displayDescription; }

private:
    HeadlessGLContext() = default;
    void destroy();

    // EGLDisplay, EGLContext, EGLSurface: opaque here so that users need no EGL headers.
    void* m_display = nullptr;
    void* m_context = nullptr;
    void* m_surface = nullptr; // a 1x1 pbuffer, only where EGL_KHR_surfaceless_context is missing
    GLInfo m_info;
    std::string m_displayDescription;
    std::unique_ptr<GLDebugLogFunction> m_debugLog; // GL holds its address: heap, so moves keep it
};

} // namespace facet
