#include <volsg/core/Error.h>
#include <volsg/gl/GlDebug.h>

#include <mutex>
#include <utility>

#include <glad/gl.h>

namespace volsg {

namespace {

std::mutex recordedMutex;
std::vector<std::string> recordedErrors;

void GLAD_API_PTR recordDebugMessage(GLenum source, GLenum type, GLuint id, GLenum /*severity*/,
                                     GLsizei length, const GLchar* message, const void* /*user*/) {
    if (type != GL_DEBUG_TYPE_ERROR) return;
    // Mesa repeats a failed compile's info log here; Shader reads the compile status and
    // throws with that log, so it is no GL error (glGetError stays clean).
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
    std::string text =
        length >= 0 ? std::string(message, std::size_t(length)) : std::string(message);
    std::lock_guard<std::mutex> lock(recordedMutex);
    // Bounded: a broken draw in a loop must not grow memory without end.
    if (recordedErrors.size() < 64)
        recordedErrors.push_back("GL debug error " + std::to_string(id) + ": " + text);
}

} // namespace

bool enableGlErrorChecking() {
    if (!glDebugMessageCallback || !glDebugMessageControl) return false;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(recordDebugMessage, nullptr);
    glDebugMessageControl(GL_DONT_CARE, GL_DEBUG_TYPE_ERROR, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    return true;
}

std::vector<std::string> takeGlDebugErrors() {
    std::lock_guard<std::mutex> lock(recordedMutex);
    return std::exchange(recordedErrors, {});
}

const char* glErrorName(unsigned int code) {
    switch (code) {
    case GL_NO_ERROR:
        return "GL_NO_ERROR";
    case GL_INVALID_ENUM:
        return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
        return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
        return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
        return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
        return "GL_OUT_OF_MEMORY";
    case GL_STACK_UNDERFLOW:
        return "GL_STACK_UNDERFLOW";
    case GL_STACK_OVERFLOW:
        return "GL_STACK_OVERFLOW";
    default:
        return "unknown GL error";
    }
}

void checkGlError(const char* where) {
    std::string message;
    for (const std::string& e : takeGlDebugErrors())
        message += (message.empty() ? "" : "; ") + e;
    // glGetError keeps one flag per error kind; a bounded loop drains them all.
    for (int i = 0; glGetError && i < 16; ++i) {
        const GLenum code = glGetError();
        if (code == GL_NO_ERROR) break;
        message += (message.empty() ? "" : "; ") + std::string(glErrorName(code));
    }
    if (!message.empty()) throw Error(std::string(where) + ": " + message);
}

} // namespace volsg
