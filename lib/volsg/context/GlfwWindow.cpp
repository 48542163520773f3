// glad first; GLFW must not include a GL header of its own.
#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <volsg/context/GlfwWindow.h>
#include <volsg/core/Error.h>
#include <volsg/gl/GlLoader.h>

#include <cstdlib>
#include <mutex>

namespace volsg {

namespace {

std::string glfwErrorText(const char* what) {
    const char* description = nullptr;
    const int code = glfwGetError(&description);
    std::string text = std::string("glfw: ") + what + " failed";
    if (code != GLFW_NO_ERROR && description) text += ": " + std::string(description);
    return text;
}

// glfwTerminate destroys every window, so GLFW lives as long as the last GlfwWindow.
std::mutex glfwMutex;
int glfwUsers = 0;

void acquireGlfw() {
    std::lock_guard<std::mutex> lock(glfwMutex);
    if (glfwUsers == 0 && glfwInit() != GLFW_TRUE) throw Error(glfwErrorText("glfwInit"));
    ++glfwUsers;
}

void releaseGlfw() {
    std::lock_guard<std::mutex> lock(glfwMutex);
    if (--glfwUsers == 0) glfwTerminate();
}

} // namespace

GlfwWindow::GlfwWindow(const GlfwWindowOptions& options) {
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display)
        throw Error("glfw: no X display (DISPLAY is not set); this GLFW build needs X11. Use "
                    "an offscreen context (osmesa or egl) or run under xvfb-run -a");
    acquireGlfw();
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
    window_ =
        glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string message = glfwErrorText("creating a 3.3 core window");
        releaseGlfw();
        throw Error(message);
    }
    try {
        makeCurrent();
        requireCoreGl33("glfw");
    } catch (...) {
        glfwDestroyWindow(window_);
        releaseGlfw();
        throw;
    }
}

GlfwWindow::~GlfwWindow() {
    if (glfwGetCurrentContext() == window_) glfwMakeContextCurrent(nullptr);
    glfwDestroyWindow(window_);
    releaseGlfw();
}

void GlfwWindow::makeCurrent() {
    glfwMakeContextCurrent(window_);
    loadGlFunctions(glfwGetProcAddress, "glfw");
}

void GlfwWindow::swapBuffers() {
    glfwSwapBuffers(window_);
}

bool GlfwWindow::shouldClose() const {
    return glfwWindowShouldClose(window_) == GLFW_TRUE;
}

glm::ivec2 GlfwWindow::size() const {
    glm::ivec2 s(0);
    glfwGetFramebufferSize(window_, &s.x, &s.y);
    return s;
}

void GlfwWindow::pollEvents() {
    glfwPollEvents();
}

} // namespace volsg
