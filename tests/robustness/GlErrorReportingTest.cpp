// The test support (tests/support/TestMain.cpp) switches on KHR_debug error reporting for
// every context a backend creates, so a GL error anywhere in a test fails it. These cases
// check that the switch really happens for each offscreen backend.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include <volsg/context/Context.h>
#include <volsg/core/Error.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/gl/GlLoader.h>

using namespace volsg;

namespace {

/// Makes one GL error in a fresh context and returns what the debug callback recorded.
std::vector<std::string> recordedErrorOfBadCall(Backend backend) {
    const auto context = Context::createOffscreen(backend);
    takeGlDebugErrors();
    glEnable(GL_NONE); // GL_INVALID_ENUM
    std::vector<std::string> recorded = takeGlDebugErrors();
    while (glGetError() != GL_NO_ERROR) {
    }
    return recorded;
}

} // namespace

TEST_CASE("every new OSMesa context reports GL errors through the debug callback") {
    const std::vector<std::string> recorded = recordedErrorOfBadCall(Backend::OSMesa);
    REQUIRE(recorded.size() == 1);
    CHECK(recorded.front().find("GL debug error") != std::string::npos);
}

TEST_CASE("every new EGL context reports GL errors through the debug callback") {
    std::unique_ptr<Context> probe;
    try {
        probe = Context::createOffscreen(Backend::EGL);
    } catch (const Error& e) {
        MESSAGE("EGL unavailable here, nothing to check: " << e.what());
        return;
    }
    probe.reset();
    const std::vector<std::string> recorded = recordedErrorOfBadCall(Backend::EGL);
    REQUIRE(recorded.size() == 1);
    CHECK(recorded.front().find("GL debug error") != std::string::npos);
}

TEST_CASE("a GL call without an error records nothing") {
    const auto context = Context::createOffscreen(Backend::OSMesa);
    takeGlDebugErrors();
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_DEPTH_TEST);
    CHECK(takeGlDebugErrors().empty());
    CHECK(glGetError() == GL_NO_ERROR);
}
