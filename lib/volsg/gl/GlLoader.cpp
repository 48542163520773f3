#include <volsg/core/Error.h>
#include <volsg/gl/GlLoader.h>

#include <atomic>
#include <mutex>
#include <string>

namespace volsg {

namespace {
// Which GetProcAddress filled glad's pointers. A mutex keeps two threads that make contexts
// current at once from loading over each other.
std::mutex loaderMutex;
GLADloadfunc loadedFor = nullptr;
std::atomic<ContextCreatedHook> contextCreatedHook{nullptr};
} // namespace

void setContextCreatedHook(ContextCreatedHook hook) {
    contextCreatedHook = hook;
}

void loadGlFunctions(GLADloadfunc getProcAddress, const char* backendName) {
    std::lock_guard<std::mutex> lock(loaderMutex);
    if (loadedFor == getProcAddress) return;
    if (gladLoadGL(getProcAddress) == 0) {
        loadedFor = nullptr;
        throw Error(std::string(backendName) +
                    ": could not load OpenGL functions (glad found no GL version)");
    }
    loadedFor = getProcAddress;
}

void requireCoreGl33(const char* backendName) {
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    const bool atLeast33 = major > 3 || (major == 3 && minor >= 3);
    if (!atLeast33 || (profile & GL_CONTEXT_CORE_PROFILE_BIT) == 0) {
        throw Error(std::string(backendName) + ": OpenGL 3.3 core profile required, got " +
                    (version ? version : "no version string"));
    }
    if (const ContextCreatedHook hook = contextCreatedHook) hook();
}

} // namespace volsg
