#include "render/HeadlessGLContext.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <map>
#include <mutex>
#include <string_view>
#include <utility>
#include <vector>

// EGL_EXT_device_drm_render_node is newer than the registry libepoxy 1.5.10 was generated from.
#ifndef EGL_DRM_RENDER_NODE_FILE_EXT
#define EGL_DRM_RENDER_NODE_FILE_EXT 0x3377
#endif

namespace facet {

namespace {

const char* eglErrorName(EGLint error)
{
    switch (error) {
    case EGL_SUCCESS:
        return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
        return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
        return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
        return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
        return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
        return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
        return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE:
        return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY:
        return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
        return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP:
        return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW:
        return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER:
        return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
        return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST:
        return "EGL_CONTEXT_LOST";
    default:
        return "unknown EGL error";
    }
}

std::string lastEglError()
{
    return eglErrorName(eglGetError());
}

// Whether a space-separated EGL list (extensions, client APIs) holds `token` exactly.
bool hasToken(const char* list, std::string_view token)
{
    if (!list)
        return false;
    std::string_view rest(list);
    while (!rest.empty()) {
        const std::size_t space = rest.find(' ');
        if (rest.substr(0, space) == token)
            return true;
        if (space == std::string_view::npos)
            break;
        rest.remove_prefix(space + 1);
    }
    return false;
}

// eglGetPlatformDisplay returns one EGLDisplay per (platform, native display) and eglTerminate
// ends every context on it, so displays are terminated when the last of our contexts goes.
std::mutex g_displayMutex;
std::map<EGLDisplay, int> g_displayUsers;

void retainDisplay(EGLDisplay display)
{
    const std::lock_guard lock(g_displayMutex);
    ++g_displayUsers[display];
}

void releaseDisplay(EGLDisplay display)
{
    const std::lock_guard lock(g_displayMutex);
    const auto user = g_displayUsers.find(display);
    if (user == g_displayUsers.end() || --user->second > 0)
        return;
    g_displayUsers.erase(user);
    eglTerminate(display);
}

struct CandidateDisplay {
    EGLDisplay display = EGL_NO_DISPLAY;
    std::string label; // "EGL device 0 (/dev/dri/renderD128)", "Mesa surfaceless platform"
    std::string failed; // set when even eglGetPlatformDisplay failed
};

// The displays to try, best first: GPU devices (NVIDIA, or any driver exposing
// EGL_EXT_platform_device), Mesa's surfaceless platform (which picks a GPU through its render
// node or falls back to llvmpipe), then software devices.
std::vector<CandidateDisplay> candidateDisplays(std::string* problem)
{
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!clientExtensions) {
        *problem = "eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS) failed (" + lastEglError()
            + "): this EGL has no client extensions, so no display without a window system";
        return {};
    }
    if (!hasToken(clientExtensions, "EGL_EXT_platform_base")) {
        *problem
            = std::string("EGL has no EGL_EXT_platform_base (client extensions: ") + clientExtensions + ")";
        return {};
    }

    std::vector<CandidateDisplay> gpuDevices;
    std::vector<CandidateDisplay> softwareDevices;
    const bool canEnumerateDevices = hasToken(clientExtensions, "EGL_EXT_platform_device")
        && (hasToken(clientExtensions, "EGL_EXT_device_enumeration")
            || hasToken(clientExtensions, "EGL_EXT_device_base"));
    if (canEnumerateDevices) {
        const bool canQueryDevices = hasToken(clientExtensions, "EGL_EXT_device_query")
            || hasToken(clientExtensions, "EGL_EXT_device_base");
        EGLint deviceCount = 0;
        if (eglQueryDevicesEXT(0, nullptr, &deviceCount) && deviceCount > 0) {
            std::vector<EGLDeviceEXT> devices(std::size_t(deviceCount), nullptr);
            if (!eglQueryDevicesEXT(deviceCount, devices.data(), &deviceCount))
                deviceCount = 0;
            for (EGLint index = 0; index < deviceCount; ++index) {
                const EGLDeviceEXT device = devices[std::size_t(index)];
                const char* deviceExtensions
                    = canQueryDevices ? eglQueryDeviceStringEXT(device, EGL_EXTENSIONS) : nullptr;
                const bool software = hasToken(deviceExtensions, "EGL_MESA_device_software");
                const char* node = nullptr;
                if (hasToken(deviceExtensions, "EGL_EXT_device_drm_render_node"))
                    node = eglQueryDeviceStringEXT(device, EGL_DRM_RENDER_NODE_FILE_EXT);
                if (!node && hasToken(deviceExtensions, "EGL_EXT_device_drm"))
                    node = eglQueryDeviceStringEXT(device, EGL_DRM_DEVICE_FILE_EXT);
                CandidateDisplay candidate;
                candidate.label = "EGL device " + std::to_string(index) + " ("
                    + (node ? std::string(node) : std::string(software ? "software" : "no DRM node")) + ")";
                candidate.display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
                if (candidate.display == EGL_NO_DISPLAY)
                    candidate.failed
                        = "eglGetPlatformDisplayEXT failed (" + lastEglError() + ") on " + candidate.label;
                (software ? softwareDevices : gpuDevices).push_back(std::move(candidate));
            }
        }
    }

    std::vector<CandidateDisplay> candidates = std::move(gpuDevices);
    if (hasToken(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        CandidateDisplay candidate;
        candidate.label = "Mesa surfaceless platform";
        candidate.display
            = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (candidate.display == EGL_NO_DISPLAY)
            candidate.failed
                = "eglGetPlatformDisplayEXT failed (" + lastEglError() + ") on " + candidate.label;
        candidates.push_back(std::move(candidate));
    }
    for (CandidateDisplay& candidate : softwareDevices)
        candidates.push_back(std::move(candidate));
    if (candidates.empty())
        *problem = std::string("EGL offers neither EGL_EXT_platform_device with a device nor "
                               "EGL_MESA_platform_surfaceless (client extensions: ")
            + clientExtensions + ")";
    return candidates;
}

struct CreatedContext {
    EGLContext context = EGL_NO_CONTEXT;
    EGLSurface surface = EGL_NO_SURFACE;
};

// Which OpenGL a display offers when 4.1 core is refused, for the error message: a 3.2+ core
// context if it makes one, else a legacy one. Empty if neither works.
std::string offeredVersion(EGLDisplay display, EGLConfig config, EGLSurface surface)
{
    const EGLint core32[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 2,
        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext probe = eglCreateContext(display, config, EGL_NO_CONTEXT, core32);
    if (probe == EGL_NO_CONTEXT)
        probe = eglCreateContext(display, config, EGL_NO_CONTEXT, nullptr);
    if (probe == EGL_NO_CONTEXT)
        return {};
    std::string version;
    if (eglMakeCurrent(display, surface, surface, probe)) {
        const GLInfo info = queryCurrentGLInfo();
        version = info.version + " (" + info.renderer + ")";
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    eglDestroyContext(display, probe);
    return version;
}

// Initialises `display` and makes a current 4.5 or 4.1 core context on it. On failure the display
// is released and `failure` names the step; `offered` gets the version a too-old driver offers.
std::optional<CreatedContext> createOnDisplay(
    EGLDisplay display, const std::string& label, bool debug, std::string* failure, std::string* offered)
{
    EGLint eglMajor = 0;
    EGLint eglMinor = 0;
    if (!eglInitialize(display, &eglMajor, &eglMinor)) {
        *failure = "eglInitialize failed (" + lastEglError() + ") on " + label;
        return std::nullopt;
    }
    retainDisplay(display);
    const auto fail = [&](std::string why) -> std::optional<CreatedContext> {
        *failure = std::move(why) + " on " + label;
        releaseDisplay(display);
        return std::nullopt;
    };

    const char* clientApis = eglQueryString(display, EGL_CLIENT_APIS);
    if (!hasToken(clientApis, "OpenGL"))
        return fail(
            std::string("no desktop OpenGL (client APIs: ") + (clientApis ? clientApis : "none") + ")");
    if (!eglBindAPI(EGL_OPENGL_API))
        return fail("eglBindAPI(EGL_OPENGL_API) failed (" + lastEglError() + ")");

    const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
    const bool eglAtLeast15 = eglMajor > 1 || (eglMajor == 1 && eglMinor >= 5);
    const bool canAskVersion = eglAtLeast15 || hasToken(extensions, "EGL_KHR_create_context");
    const bool noConfig = hasToken(extensions, "EGL_KHR_no_config_context")
        || hasToken(extensions, "EGL_MESA_configless_context");
    const bool surfaceless = hasToken(extensions, "EGL_KHR_surfaceless_context");
    if (!canAskVersion)
        return fail("neither EGL 1.5 nor EGL_KHR_create_context, so no core profile can be requested");

    // Without EGL_KHR_no_config_context, or without EGL_KHR_surfaceless_context (then a 1x1
    // pbuffer stands in for the missing surface), the context needs a config.
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!noConfig || !surfaceless) {
        const EGLint wanted[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
            EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_NONE};
        EGLint configCount = 0;
        if (!eglChooseConfig(display, wanted, &config, 1, &configCount))
            return fail("eglChooseConfig failed (" + lastEglError() + ")");
        if (configCount < 1)
            return fail("eglChooseConfig found no OpenGL pbuffer config");
    }
    EGLSurface surface = EGL_NO_SURFACE;
    if (!surfaceless) {
        const EGLint size[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
        surface = eglCreatePbufferSurface(display, config, size);
        if (surface == EGL_NO_SURFACE)
            return fail("eglCreatePbufferSurface failed (" + lastEglError() + ")");
    }

    struct Version {
        int major;
        int minor;
    };
    std::string refusals;
    EGLContext context = EGL_NO_CONTEXT;
    for (const Version version : {Version {4, 5}, Version {4, 1}}) {
        std::vector<EGLint> attributes = {EGL_CONTEXT_MAJOR_VERSION, version.major, EGL_CONTEXT_MINOR_VERSION,
            version.minor, EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT};
        if (debug && hasToken(extensions, "EGL_KHR_create_context"))
            attributes.insert(attributes.end(), {EGL_CONTEXT_FLAGS_KHR, EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR});
        else if (debug && eglAtLeast15)
            attributes.insert(attributes.end(), {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE});
        attributes.push_back(EGL_NONE);
        context = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes.data());
        if (context != EGL_NO_CONTEXT)
            break;
        refusals += (refusals.empty() ? "" : " and ") + std::to_string(version.major) + "."
            + std::to_string(version.minor) + " core (" + lastEglError() + ")";
    }
    if (context == EGL_NO_CONTEXT) {
        const std::string version = offeredVersion(display, config, surface);
        if (!version.empty())
            *offered = label + " offers only OpenGL " + version;
        if (surface != EGL_NO_SURFACE)
            eglDestroySurface(display, surface);
        return fail("eglCreateContext failed for " + refusals);
    }
    if (!eglMakeCurrent(display, surface, surface, context)) {
        const std::string error = lastEglError();
        eglDestroyContext(display, context);
        if (surface != EGL_NO_SURFACE)
            eglDestroySurface(display, surface);
        return fail("eglMakeCurrent failed (" + error + ")");
    }
    return CreatedContext {context, surface};
}

std::string describeDisplay(EGLDisplay display, const std::string& label)
{
    const char* version = eglQueryString(display, EGL_VERSION);
    const char* vendor = eglQueryString(display, EGL_VENDOR);
    return label + " (EGL " + (version ? version : "?") + ", " + (vendor ? vendor : "unknown vendor") + ")";
}

} // namespace

std::optional<HeadlessGLContext> HeadlessGLContext::create(std::string* error)
{
    return create(HeadlessGLContextOptions {}, error);
}

std::optional<HeadlessGLContext> HeadlessGLContext::create(
    const HeadlessGLContextOptions& options, std::string* error)
{
    const auto failWith = [error](const std::string& message) -> std::optional<HeadlessGLContext> {
        if (error)
            *error = "HeadlessGLContext::create: " + message;
        return std::nullopt;
    };

    std::string problem;
    const std::vector<CandidateDisplay> candidates = candidateDisplays(&problem);
    if (candidates.empty())
        return failWith(problem);

    std::vector<std::string> failures;
    std::string offered;
    for (const CandidateDisplay& candidate : candidates) {
        if (!candidate.failed.empty()) {
            failures.push_back(candidate.failed);
            continue;
        }
        std::string failure;
        std::string offeredHere;
        std::optional<CreatedContext> created
            = createOnDisplay(candidate.display, candidate.label, options.debug, &failure, &offeredHere);
        if (offered.empty())
            offered = offeredHere; // the preferred display's offer names the version to expect
        if (!created) {
            failures.push_back(failure);
            continue;
        }

        HeadlessGLContext result;
        result.m_display = candidate.display;
        result.m_context = created->context;
        result.m_surface = created->surface;
        result.m_displayDescription = describeDisplay(candidate.display, candidate.label);
        result.m_info = queryCurrentGLInfo();
        // A driver may hand out less than it was asked for; refuse it here rather than at the
        // first missing function.
        if (!result.m_info.atLeast(kRequiredMajor, kRequiredMinor) || !result.m_info.coreProfile) {
            if (offered.empty())
                offered = candidate.label + " offers only OpenGL " + result.m_info.version + " ("
                    + result.m_info.renderer + ")"
                    + (result.m_info.coreProfile ? "" : ", not a core profile");
            failures.push_back(
                "the context reports OpenGL " + result.m_info.version + " on " + candidate.label);
            continue; // `result` releases the context and the display
        }
        if (options.debug) {
            result.m_debugLog = std::make_unique<GLDebugLogFunction>(options.debugLog);
            if (!*result.m_debugLog)
                *result.m_debugLog = [](GLDebugSeverity, std::string_view message) {
                    std::fprintf(stderr, "%.*s\n", int(message.size()), message.data());
                };
            enableGLDebugOutput(result.m_debugLog.get());
        }
        return result;
    }

    if (!offered.empty())
        return failWith("OpenGL " + std::to_string(kRequiredMajor) + "." + std::to_string(kRequiredMinor)
            + " core profile is required; " + offered);
    std::string message
        = failures.size() == 1 ? std::string() : std::string("no EGL display gave an OpenGL context: ");
    for (std::size_t index = 0; index < failures.size(); ++index)
        message += (index ? "; " : "") + failures[index];
    return failWith(message);
}

HeadlessGLContext::HeadlessGLContext(HeadlessGLContext&& other) noexcept
    : m_display(std::exchange(other.m_display, nullptr))
    , m_context(std::exchange(other.m_context, nullptr))
    , m_surface(std::exchange(other.m_surface, nullptr))
    , m_info(std::move(other.m_info))
    , m_displayDescription(std::move(other.m_displayDescription))
    , m_debugLog(std::move(other.m_debugLog))
{
}

HeadlessGLContext& HeadlessGLContext::operator=(HeadlessGLContext&& other) noexcept
{
    if (this != &other) {
        destroy();
        m_display = std::exchange(other.m_display, nullptr);
        m_context = std::exchange(other.m_context, nullptr);
        m_surface = std::exchange(other.m_surface, nullptr);
        m_info = std::move(other.m_info);
        m_displayDescription = std::move(other.m_displayDescription);
        m_debugLog = std::move(other.m_debugLog);
    }
    return *this;
}

HeadlessGLContext::~HeadlessGLContext()
{
    destroy();
}

void HeadlessGLContext::destroy()
{
    if (!m_context)
        return;
    if (isCurrent()) {
        eglBindAPI(EGL_OPENGL_API);
        eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    eglDestroyContext(m_display, m_context);
    if (m_surface)
        eglDestroySurface(m_display, m_surface);
    releaseDisplay(m_display);
    m_display = m_context = m_surface = nullptr;
    m_debugLog.reset();
}

bool HeadlessGLContext::makeCurrent()
{
    if (!m_context)
        return false;
    // The bound API is per thread; this thread may not have bound OpenGL yet.
    eglBindAPI(EGL_OPENGL_API);
    const EGLSurface surface = m_surface ? EGLSurface(m_surface) : EGL_NO_SURFACE;
    return eglMakeCurrent(m_display, surface, surface, m_context) == EGL_TRUE;
}

void HeadlessGLContext::doneCurrent()
{
    if (!m_display)
        return;
    eglBindAPI(EGL_OPENGL_API);
    eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

bool HeadlessGLContext::isCurrent() const
{
    if (!m_context)
        return false;
    eglBindAPI(EGL_OPENGL_API);
    return eglGetCurrentContext() == m_context;
}

} // namespace facet
