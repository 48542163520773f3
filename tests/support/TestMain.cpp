// The doctest main of every test executable. It also makes GL errors test failures: each
// context any backend creates gets synchronous KHR_debug output (enableGlErrorChecking), and a
// GL error message that no test consumed (checkGlError, takeGlDebugErrors) fails the test case
// in which it happened, naming it. Where a context has no KHR_debug, glGetError is checked
// each frame by Renderer::render instead (it throws).
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <volsg/gl/GlDebug.h>
#include <volsg/gl/GlLoader.h>

#include <cstdio>
#include <string>
#include <vector>

namespace {

bool glErrorsSeen = false;
int testCasesStarted = 0;

void reportGlErrors(const char* testCase) {
    const std::vector<std::string> errors = volsg::takeGlDebugErrors();
    if (errors.empty()) return;
    glErrorsSeen = true;
    std::fprintf(stderr, "GL errors in test case \"%s\" (the test fails):\n", testCase);
    for (const std::string& e : errors)
        std::fprintf(stderr, "  %s\n", e.c_str());
}

/// Collects the GL errors recorded while each test case ran.
struct GlErrorListener : doctest::IReporter {
    explicit GlErrorListener(const doctest::ContextOptions&) {}
    void report_query(const doctest::QueryData&) override {}
    void test_run_start() override {}
    void test_run_end(const doctest::TestRunStats&) override {}
    void test_case_start(const doctest::TestCaseData& data) override {
        current_ = data.m_name;
        ++testCasesStarted;
        volsg::takeGlDebugErrors(); // from before: not this test's
    }
    void test_case_reenter(const doctest::TestCaseData&) override {}
    void test_case_end(const doctest::CurrentTestCaseStats&) override {
        reportGlErrors(current_.c_str());
    }
    void test_case_exception(const doctest::TestCaseException&) override {}
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    void log_assert(const doctest::AssertData&) override {}
    void log_message(const doctest::MessageData&) override {}
    void test_case_skipped(const doctest::TestCaseData&) override {}

private:
    std::string current_;
};

REGISTER_LISTENER("gl-errors", 1, GlErrorListener);

void enableGlErrorsForNewContext() {
    volsg::enableGlErrorChecking();
}

} // namespace

int main(int argc, char** argv) {
    volsg::setContextCreatedHook(&enableGlErrorsForNewContext);
    doctest::Context context(argc, argv);
    const int result = context.run();
    if (context.shouldExit()) return result;
    // ctest names one source file per run, and the Coin and MPI tests one test case; a filter
    // that matches nothing (a moved file, a name CMake split at ';') would otherwise pass
    // without running anything.
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool filter = arg.rfind("--test-case=", 0) == 0 || arg.rfind("-tc=", 0) == 0 ||
                            arg.rfind("--source-file=", 0) == 0 || arg.rfind("-sf=", 0) == 0;
        if (filter && testCasesStarted == 0) {
            std::fprintf(stderr, "[filter] no test case matches %s: failing\n", arg.c_str());
            return result != 0 ? result : 1;
        }
    }
    if (glErrorsSeen) {
        std::fprintf(stderr, "[gl-errors] GL errors were reported (see above): failing\n");
        return result != 0 ? result : 1;
    }
    return result;
}
