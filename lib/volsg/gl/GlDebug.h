#pragma once
// Turning GL errors into volsg::Error: KHR_debug messages and glGetError.

#include <string>
#include <vector>

namespace volsg {

/// Switches on synchronous KHR_debug output for the current context and records every
/// GL_DEBUG_TYPE_ERROR message (the callback runs inside the driver, where throwing is not
/// safe, so it records; checkGlError() throws). Returns false when the context has no
/// KHR_debug (then checkGlError() still sees glGetError()).
bool enableGlErrorChecking();

/// Throws Error naming `where` if the GL reported an error since the last check: recorded
/// debug messages and every pending glGetError() code. Does nothing otherwise.
void checkGlError(const char* where);

/// The error messages recorded by the debug callback since the last call, cleared.
std::vector<std::string> takeGlDebugErrors();

/// "GL_INVALID_ENUM", ... for a glGetError() code.
const char* glErrorName(unsigned int code);

} // namespace volsg
