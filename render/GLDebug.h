#pragma once
// OpenGL debug output (KHR_debug / GL 4.3) routed to a logging function.

#include <functional>
#include <string_view>

namespace facet {

enum class GLDebugSeverity { Notification, Low, Medium, High };

// Receives one driver message, e.g. "GL error (high): GL_INVALID_OPERATION in glDrawArrays(...)".
using GLDebugLogFunction = std::function<void(GLDebugSeverity severity, std::string_view message)>;

// Installs `log` as the debug-message callback of the context current on this thread and enables
// GL_DEBUG_OUTPUT_SYNCHRONOUS, so a message arrives inside the call that caused it. `log` is held
// by address: it must stay alive, where it is, until disableGLDebugOutput() runs on that context.
// Returns false, doing nothing, when the context has no KHR_debug (GL < 4.3 without the
// extension). Contexts created with a debug flag report the most.
bool enableGLDebugOutput(const GLDebugLogFunction* log);

// Removes the callback from the context current on this thread. Harmless when none was installed.
void disableGLDebugOutput();

} // namespace facet
