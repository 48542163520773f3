#pragma once
// Loads GL entry points (glad) for the context made current, and checks that it is 3.3 core.

#include <glad/gl.h>

namespace volsg {

/// Loads glad's global function pointers through `getProcAddress` unless they were already
/// loaded through that same function. glad's pointers are process-wide, while the pointers a
/// backend hands out are its own (OSMesa's Mesa glapi stubs, glvnd's EGL/GLX dispatch), so
/// switching the current context to another backend must reload them. Call it right after
/// making a context current. Throws Error if nothing could be loaded.
void loadGlFunctions(GLADloadfunc getProcAddress, const char* backendName);

/// Throws Error unless the current context is OpenGL 3.3 or newer with the core profile.
/// The version is checked with >=: Mesa gives the highest version it has (4.5 here).
/// Every backend calls it once for each new context, which then runs the context hook.
void requireCoreGl33(const char* backendName);

/// A function run for every new context of every backend, current and checked, before the
/// context is handed out (nullptr: none). The test support installs one that switches on GL
/// error reporting (GlDebug.h) so any GL error fails the test that made it.
using ContextCreatedHook = void (*)();
void setContextCreatedHook(ContextCreatedHook hook);

} // namespace volsg
