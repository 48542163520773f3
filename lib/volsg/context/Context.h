#pragma once
// A place to draw: an OpenGL 3.3+ core context made current on this thread, with GL functions
// loaded. Nodes never know which kind they draw into.

#include <memory>
#include <string>

namespace volsg {

enum class Backend { OSMesa, EGL };

class Context {
public:
    virtual ~Context() = default;
    virtual void makeCurrent() = 0;
    virtual std::string backendName() const = 0; ///< "osmesa", "egl", "glfw"

    /// An offscreen context (no window, no X server). Renders go to framebuffer objects.
    /// Throws Error when the backend is unavailable, saying why.
    static std::unique_ptr<Context> createOffscreen(Backend backend = Backend::OSMesa);
};

/// "osmesa" or "egl"; throws Error for anything else.
Backend parseBackend(const std::string& name);

} // namespace volsg
