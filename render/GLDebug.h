#pragma once
// OpenGL debug output (KHR_debug / GL 4.3) routed to a logging function.

#include <functional>
#include <string>
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

// The name of a glGetError() value ("GL_OUT_OF_MEMORY"), or "GL error <number>" for another value:
// the one spelling every message of render/ uses. (A GLenum, taken as unsigned: no GL header here.)
std::string glErrorName(unsigned error);

} // namespace facet
