#pragma once
// Offscreen GL through EGL on Mesa's surfaceless platform: no window system, no X server.

#include <volsg/context/Context.h>

namespace volsg {

/// An EGL 3.3+ core-profile context with no config and no surface (EGL_KHR_no_config_context,
/// EGL_KHR_surfaceless_context); renders go to framebuffer objects. Made current on
/// construction. The EGL display is shared by all EglContexts and stays initialised for the
/// life of the process.
class EglContext final : public Context {
public:
    EglContext();
    ~EglContext() override;
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    void makeCurrent() override;
    std::string backendName() const override { return "egl"; }

private:
    void* display_ = nullptr; // EGLDisplay
    void* context_ = nullptr; // EGLContext
};

} // namespace volsg
