// volsg-view under Xvfb, driven by an input script: it rotates the view, drags a clip plane
// with its manipulator, moves a transfer-function point in the editor panel, and saves the scene
// and screenshots. The saved fields and the screenshots are checked against what those edits
// must do. Skips itself (with a message) where xvfb-run is not installed.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <volsg/actions/SearchAction.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/TransferFunction.h>

using namespace volsg;
namespace fs = std::filesystem;

namespace {

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
std::string sanitizerEnvironment() {
    const char* driver = "/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so";
    if (!addressSanitizer || !fs::exists(driver)) return {};
    return std::string("ASAN_OPTIONS=verify_asan_link_order=0 LD_PRELOAD=") + driver + " ";
}

bool haveXvfbRun() {
    return std::system("command -v xvfb-run > /dev/null 2>&1") == 0;
}

double distanceFromBackground(const Image& image, int rowsFrom, int rowsTo) {
    const glm::vec3 background = glm::vec3(26.0f, 26.0f, 31.0f) / 255.0f; // 0.1 0.1 0.12 in 8 bits
    double sum = 0.0;
    for (int y = rowsFrom; y < rowsTo; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3 d = glm::vec3(image.at(x, y)) - background;
            sum += std::abs(d.r) + std::abs(d.g) + std::abs(d.b);
        }
    return sum;
}

int changedPixels(const Image& a, const Image& b, float threshold) {
    int count = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const glm::vec4 d = glm::abs(a.pixels[i] - b.pixels[i]);
        if (std::max(d.r, std::max(d.g, d.b)) > threshold) ++count;
    }
    return count;
}

} // namespace

TEST_CASE("scripted viewer session rotates, clips, edits the transfer function and saves") {
    if (!haveXvfbRun()) {
        MESSAGE("xvfb-run is not installed: the viewer end-to-end test is skipped");
        return;
    }
    const fs::path dir = fs::temp_directory_path() / ("volsg-view-e2e-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string scene = std::string(VOLSG_SOURCE_DIR) + "/tests/viewer/viewer-scene.iv";
    const std::string viewer = std::string(VOLSG_BINARY_DIR) + "/viewer/volsg-view";
    REQUIRE(fs::exists(viewer));
    auto file = [&](const char* name) { return (dir / name).string(); };
    {
        std::ofstream script(file("script.txt"));
        // The 800x500 window: panels on the left (224 px) and right (272 px); the view between.
        script << "wait 1\n"
               << "screenshot " << file("s0.png") << " scene\n"
               << "drag left 330 100 400 100 2\n" // trackball: the camera orbits the origin
               << "screenshot " << file("s1.png") << " scene\n"
               << "select clip\n"
               << "key m\n" // the clip-plane manipulator
               << "wait 1\n"
               // Along the plane's normal line through its handle centre (0, -0.2, 0 is the
               // scene box's centre): the plane moves from x = -0.3 to x = 0.2.
               << "drag left world:-0.3,-0.2,0 world:0.2,-0.2,0 2\n"
               << "key m\n"
               << "screenshot " << file("s2.png")
               << " scene\n"
               // The alpha channel's end point (1, 0.6) dragged down to (1, 0.1).
               << "drag left tf:1,0.6 tf:1,0.1 2\n"
               << "screenshot " << file("s3.png") << " scene\n"
               << "save " << file("saved.iv") << "\n"
               << "quit\n";
    }
    const std::string command = sanitizerEnvironment() + "xvfb-run -a -s '-screen 0 1280x800x24' " +
                                viewer + " " + scene + " --size 800x500 --script " +
                                file("script.txt") + " > " + file("log.txt") + " 2>&1";
    const int status = std::system(command.c_str());
    std::string log;
    {
        std::ifstream in(file("log.txt"));
        log.assign(std::istreambuf_iterator<char>(in), {});
    }
    INFO("viewer output: " << log);
    REQUIRE(status == 0);

    // The saved scene: the view, the plane and the transfer function as the script left them.
    ref_ptr<Node> saved = readScene(file("saved.iv"));
    auto* camera = static_cast<Camera*>(findByName(*saved, "camera"));
    auto* clip = static_cast<ClipPlane*>(findByName(*saved, "clip"));
    auto* tf = static_cast<TransferFunction*>(findByName(*saved, "tf"));
    REQUIRE(camera);
    REQUIRE(clip);
    REQUIRE(tf);
    // Orbiting about the focal point (the origin, 4.5 ahead) keeps the distance.
    CHECK(glm::length(glm::dvec3(camera->position())) == doctest::Approx(4.5).epsilon(1e-3));
    CHECK(camera->orientation().angle > 0.05f);
    CHECK(camera->position().x < -0.2f); // a drag to the right turns the camera to the left
    CHECK(clip->plane().distance == doctest::Approx(0.2).epsilon(0.01));
    CHECK(glm::length(glm::dvec3(clip->plane().normal) - glm::dvec3(1, 0, 0)) < 1e-3);
    REQUIRE(tf->alpha.size() == 2);
    CHECK(tf->alpha[1].x == doctest::Approx(1.0).epsilon(1e-4));
    CHECK(tf->alpha[1].y == doctest::Approx(0.1).epsilon(0.01));
    CHECK(tf->red.getValues() == std::vector<glm::vec2>{{0, 0.2f}, {1, 1}}); // untouched

    const Image s0 = readPng(file("s0.png")), s1 = readPng(file("s1.png"));
    const Image s2 = readPng(file("s2.png")), s3 = readPng(file("s3.png"));
    REQUIRE(s0.width == 800);
    REQUIRE(s0.height == 500);
    // Rotating the view changes much of the picture.
    CHECK(changedPixels(s0, s1, 2.0f / 255.0f) > 2000);
    // Moving the plane from x = -0.3 to 0.2 cuts more of the volume away: in the rows above the
    // slab (the top 55%), what differs from the background shrinks.
    const int top = int(0.55 * s1.height);
    CHECK(distanceFromBackground(s2, 0, top) < 0.9 * distanceFromBackground(s1, 0, top));
    CHECK(changedPixels(s1, s2, 2.0f / 255.0f) > 500);
    // Lowering alpha from 0.6 to 0.1 fades the volume towards the background; the slab and the
    // background stay exactly as they were, so only volume pixels change.
    CHECK(distanceFromBackground(s3, 0, top) < 0.7 * distanceFromBackground(s2, 0, top));
    int brighter = 0, changedBelowVolume = 0;
    for (int y = 0; y < s2.height; ++y)
        for (int x = 0; x < s2.width; ++x) {
            const glm::vec4 a = s2.at(x, y), b = s3.at(x, y);
            if (glm::length(glm::vec3(b - a)) > 3.0f / 255.0f &&
                glm::length(glm::vec3(b) - glm::vec3(26, 26, 31) / 255.0f) >
                    glm::length(glm::vec3(a) - glm::vec3(26, 26, 31) / 255.0f))
                ++brighter; // moved away from the background: not what fading does
            if (y >= int(0.9 * s2.height) && a != b) ++changedBelowVolume;
        }
    CHECK(brighter == 0);
    CHECK(changedBelowVolume == 0); // the bottom rows hold the slab only
    fs::remove_all(dir);
}
