#pragma once
// What the viewer's end-to-end tests share: whether xvfb-run exists, and the environment the
// viewer's command line needs under AddressSanitizer.

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <volsg/image/Image.h>

namespace volsg {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool addressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool addressSanitizer = true;
#else
constexpr bool addressSanitizer = false;
#endif
#else
constexpr bool addressSanitizer = false;
#endif

/// What the viewer's command line needs in front under AddressSanitizer. GLX loads Mesa's
/// driver with dlopen and unloads it at exit, before LeakSanitizer looks: the driver's own
/// allocations then have no module name, so tests/support/lsan.supp cannot name them. Preloaded,
/// the driver stays loaded and its suppression applies (the viewer's own leaks still count).
inline std::string sanitizerEnvironment() {
    const char* driver = "/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so";
    if (!addressSanitizer || !std::filesystem::exists(driver)) return {};
    return std::string("ASAN_OPTIONS=verify_asan_link_order=0 LD_PRELOAD=") + driver + " ";
}

inline bool haveXvfbRun() {
    return std::system("command -v xvfb-run > /dev/null 2>&1") == 0;
}

/// Pixels of the rectangle [x0, x1) x [y0, y1) (default: the whole image) whose red, green or
/// blue differs between the two images by more than `threshold`.
inline int changedPixels(const Image& a, const Image& b, float threshold, int x0 = 0, int y0 = 0,
                         int x1 = -1, int y1 = -1) {
    if (x1 < 0) x1 = a.width;
    if (y1 < 0) y1 = a.height;
    int count = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const glm::vec4 d = glm::abs(a.at(x, y) - b.at(x, y));
            if (std::max(d.r, std::max(d.g, d.b)) > threshold) ++count;
        }
    return count;
}

/// The viewer's settings folder for tests (XDG_CONFIG_HOME): the recent files of test runs
/// never reach the user's own.
inline std::string testConfigHome() {
    return std::string(VOLSG_BINARY_DIR) + "/tests/viewer-config";
}

/// Runs volsg-view (of this build) on `scene` with `arguments` and the script `script` under
/// xvfb-run; returns the exit status, and the viewer's output in `log`. `configHome` is its
/// XDG_CONFIG_HOME (default: testConfigHome()).
inline int runViewerScript(const std::string& scene, const std::string& arguments,
                           const std::string& script, std::string& log,
                           const std::string& configHome = testConfigHome()) {
    const std::string viewer = std::string(VOLSG_BINARY_DIR) + "/viewer/volsg-view";
    const std::string logFile = script + ".log";
    const std::string command = sanitizerEnvironment() + "XDG_CONFIG_HOME='" + configHome +
                                "' xvfb-run -a -s '-screen 0 1280x800x24' " + viewer + " " + scene +
                                " " + arguments + " --script " + script + " > " + logFile + " 2>&1";
    const int status = std::system(command.c_str());
    std::ifstream in(logFile);
    log.assign(std::istreambuf_iterator<char>(in), {});
    return status;
}

} // namespace volsg
