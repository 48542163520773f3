// glad first, so that no system GL header comes before it.
#include <glad/gl.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <volsg/context/EglContext.h>
#include <volsg/core/Error.h>
#include <volsg/gl/GlLoader.h>

#include <cstdio>
#include <mutex>
#include <string>

namespace volsg {

namespace {

std::string eglErrorText(const char* what) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(eglGetError()));
    return std::string("egl: ") + what + " failed (EGL error " + code + ")";
}

// One EGL display for the process, initialised on first use and never terminated:
// eglTerminate ends it for every user in the process, and it unloads Mesa's driver, whose
// few process-lifetime allocations then show up as leaks nobody can name (LeakSanitizer
// cannot attribute them to an unloaded library).
std::mutex displayMutex;
EGLDisplay sharedDisplay = EGL_NO_DISPLAY;

EGLDisplay processDisplay() {
    std::lock_guard<std::mutex> lock(displayMutex);
    if (sharedDisplay == EGL_NO_DISPLAY) {
        EGLDisplay display =
            eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display == EGL_NO_DISPLAY)
            throw Error(eglErrorText("eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA)"));
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display, &major, &minor)) throw Error(eglErrorText("eglInitialize"));
        sharedDisplay = display;
    }
    return sharedDisplay;
}

} // namespace

EglContext::EglContext() {
    display_ = processDisplay();
    try {
        if (!eglBindAPI(EGL_OPENGL_API)) throw Error(eglErrorText("eglBindAPI(EGL_OPENGL_API)"));
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     3,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_NONE};
        context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
        if (context_ == EGL_NO_CONTEXT)
            throw Error(eglErrorText("eglCreateContext (OpenGL 3.3 core, no config)"));
        makeCurrent();
        requireCoreGl33("egl");
    } catch (...) {
        if (context_ != EGL_NO_CONTEXT) {
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            eglDestroyContext(display_, context_);
        }
        throw;
    }
}

EglContext::~EglContext() {
    if (eglGetCurrentContext() == context_)
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
}

void EglContext::makeCurrent() {
    // The bound client API is per thread: make sure it is desktop OpenGL here.
    eglBindAPI(EGL_OPENGL_API);
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
        throw Error(eglErrorText("eglMakeCurrent (surfaceless)"));
    loadGlFunctions(eglGetProcAddress, "egl");
}

} // namespace volsg
