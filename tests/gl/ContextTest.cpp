// Offscreen contexts: creation, several in one process, switching backends, clear errors.
#include <doctest/doctest.h>

#include <volsg/context/Context.h>
#include <volsg/context/EglContext.h>
#include <volsg/context/GlfwWindow.h>
#include <volsg/context/OSMesaContext.h>
#include <volsg/core/Error.h>
#include <volsg/gl/Framebuffer.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/gl/Renderbuffer.h>

#include <cstdlib>
#include <optional>
#include <string>

#include <glad/gl.h>

using namespace volsg;

namespace {

/// Clears a small RGBA32F framebuffer of the current context to `color` and reads pixel (1,1).
glm::vec4 clearAndRead(const glm::vec4& color) {
    Renderbuffer target(GL_RGBA32F, 4, 4);
    Framebuffer fb = Framebuffer::create();
    fb.attach(GL_COLOR_ATTACHMENT0, target);
    fb.requireComplete("test target");
    glViewport(0, 0, 4, 4);
    glClearColor(color.r, color.g, color.b, color.a);
    glClear(GL_COLOR_BUFFER_BIT);
    glm::vec4 pixel(-1.0f);
    glReadPixels(1, 1, 1, 1, GL_RGBA, GL_FLOAT, &pixel[0]);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    checkGlError("clearAndRead");
    return pixel;
}

std::string glVersion() {
    return reinterpret_cast<const char*>(glGetString(GL_VERSION));
}

/// Unsets DISPLAY for one scope.
class NoDisplay {
public:
    NoDisplay() {
        if (const char* d = std::getenv("DISPLAY")) saved_ = d;
        unsetenv("DISPLAY");
    }
    ~NoDisplay() {
        if (saved_) setenv("DISPLAY", saved_->c_str(), 1);
    }

private:
    std::optional<std::string> saved_;
};

} // namespace

TEST_CASE("an OSMesa context is 3.3 core or newer and draws into a float framebuffer") {
    auto context = Context::createOffscreen(Backend::OSMesa);
    CHECK(context->backendName() == "osmesa");
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    CHECK(major * 10 + minor >= 33);
    CHECK((profile & GL_CONTEXT_CORE_PROFILE_BIT) != 0);
    CHECK(clearAndRead({0.25f, -1.5f, 2.0f, 0.125f}) == glm::vec4(0.25f, -1.5f, 2.0f, 0.125f));
}

TEST_CASE("OSMesa contexts can be created, used and destroyed one after another") {
    for (int i = 0; i < 3; ++i) {
        OSMesaContext context;
        const float v = 0.125f * float(i + 1);
        CHECK(clearAndRead(glm::vec4(v)) == glm::vec4(v));
    }
}

TEST_CASE("two OSMesa contexts alive at once each keep their own objects") {
    OSMesaContext a;
    Renderbuffer onlyInA(GL_RGBA8, 2, 2);
    OSMesaContext b;
    CHECK(glIsRenderbuffer(onlyInA.id()) == GL_FALSE); // not shared with b
    CHECK(clearAndRead(glm::vec4(0.5f)) == glm::vec4(0.5f));
    a.makeCurrent();
    CHECK(glIsRenderbuffer(onlyInA.id()) == GL_TRUE);
    CHECK(clearAndRead(glm::vec4(0.75f)) == glm::vec4(0.75f));
}

TEST_CASE("an EGL surfaceless context is 3.3 core or newer and draws into a float framebuffer") {
    EglContext context;
    CHECK(context.backendName() == "egl");
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    CHECK(major * 10 + minor >= 33);
    CHECK(glVersion().find("Core Profile") != std::string::npos);
    CHECK(clearAndRead({0.5f, 0.25f, 4.0f, 1.0f}) == glm::vec4(0.5f, 0.25f, 4.0f, 1.0f));
    EglContext second; // shares the EGL display; both must work
    CHECK(clearAndRead(glm::vec4(0.375f)) == glm::vec4(0.375f));
    context.makeCurrent();
    CHECK(clearAndRead(glm::vec4(0.625f)) == glm::vec4(0.625f));
}

TEST_CASE("switching between OSMesa and EGL contexts reloads the GL functions") {
    OSMesaContext osmesa;
    CHECK(clearAndRead(glm::vec4(0.25f)) == glm::vec4(0.25f));
    {
        EglContext egl;
        CHECK(clearAndRead(glm::vec4(0.5f)) == glm::vec4(0.5f));
        osmesa.makeCurrent();
        CHECK(clearAndRead(glm::vec4(0.75f)) == glm::vec4(0.75f));
        egl.makeCurrent();
        CHECK(clearAndRead(glm::vec4(0.875f)) == glm::vec4(0.875f));
    }
    osmesa.makeCurrent();
    CHECK(clearAndRead(glm::vec4(0.0625f)) == glm::vec4(0.0625f));
    // And a new EGL context after the last one (and the EGL display) went away.
    EglContext again;
    CHECK(clearAndRead(glm::vec4(0.3125f)) == glm::vec4(0.3125f));
}

TEST_CASE("parseBackend knows osmesa and egl and names anything else") {
    CHECK(parseBackend("osmesa") == Backend::OSMesa);
    CHECK(parseBackend("egl") == Backend::EGL);
    CHECK_THROWS_WITH_AS(parseBackend("vulkan"), doctest::Contains("'vulkan'"), Error);
}

TEST_CASE("a GLFW window without DISPLAY throws an Error that says so") {
    NoDisplay noDisplay;
    CHECK_THROWS_WITH_AS(GlfwWindow(GlfwWindowOptions{}), doctest::Contains("DISPLAY"), Error);
}
