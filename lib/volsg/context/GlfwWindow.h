#pragma once
// An on-screen window with a GL 3.3+ core context (GLFW on X11), for the interactive viewer.

#include <string>

#include <glm/glm.hpp>

#include <volsg/context/Context.h>

struct GLFWwindow;

namespace volsg {

struct GlfwWindowOptions {
    int width = 800;
    int height = 600;
    std::string title = "volsg";
    bool visible = true; ///< false: a hidden window (renders and reads back all the same)
};

/// A GLFW window with a 3.3 core forward-compatible context, made current on construction.
/// GLFW here is an X11-only build: without DISPLAY it throws Error saying so (use an offscreen
/// Context, or run under `xvfb-run -a`). GLFW is initialised with the first window and
/// terminated with the last.
class GlfwWindow final : public Context {
public:
    explicit GlfwWindow(const GlfwWindowOptions& options = {});
    ~GlfwWindow() override;
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;

    void makeCurrent() override;
    std::string backendName() const override { return "glfw"; }

    void swapBuffers();
    bool shouldClose() const;
    glm::ivec2 size() const;                       ///< framebuffer size in pixels
    GLFWwindow* handle() const { return window_; } ///< for input callbacks
    static void pollEvents();

private:
    GLFWwindow* window_ = nullptr;
};

} // namespace volsg
