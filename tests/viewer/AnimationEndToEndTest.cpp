// volsg-view animates a scene under Xvfb: a Shuttle moves a cube between two points on the
// viewer's clock, and every screenshot shows the cube where Inventor's Shuttle formula puts it
// at the scene time the viewer reports for that frame (the window as drawn, not a re-render).
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <unistd.h>

#include <volsg/image/Image.h>

#include "ViewerTestSupport.h"

using namespace volsg;
namespace fs = std::filesystem;

namespace {

struct Blob {
    int pixels = 0;
    double centreX = 0.0, centreY = 0.0;
    int minX = 1 << 30, maxX = -1;
};

/// The magenta pixels of the image (the cube's unlit colour; the viewer's overlays have none).
Blob magenta(const Image& image) {
    Blob b;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec4 c = image.at(x, y);
            if (c.r > 0.8f && c.g < 0.2f && c.b > 0.8f) {
                ++b.pixels;
                b.centreX += x + 0.5;
                b.centreY += y + 0.5;
                b.minX = std::min(b.minX, x);
                b.maxX = std::max(b.maxX, x);
            }
        }
    if (b.pixels > 0) {
        b.centreX /= b.pixels;
        b.centreY /= b.pixels;
    }
    return b;
}

/// The scene time the viewer reported for the screenshot `file`.
double sceneTimeOf(const std::string& log, const std::string& file) {
    const std::size_t at = log.find("screenshot saved to " + file + " (scene time ");
    REQUIRE(at != std::string::npos);
    const std::size_t open = log.find("(scene time ", at) + 12;
    return std::stod(log.substr(open));
}

} // namespace

TEST_CASE("the viewer animates a Shuttle on its clock: the cube is where the formula puts it") {
    if (!haveXvfbRun()) {
        MESSAGE("xvfb-run is not installed: the viewer animation test is skipped");
        return;
    }
    const fs::path dir =
        fs::temp_directory_path() / ("volsg-view-anim-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    auto file = [&](const std::string& name) { return (dir / name).string(); };
    // 10 units across 400 pixels: 40 pixels a unit; the cube is 1 unit wide.
    {
        std::ofstream scene(file("shuttle.iv"));
        scene << "#Inventor V2.1 ascii\n"
                 "Separator {\n"
                 "  OrthographicCamera { position 0 0 10 height 10 }\n"
                 "  LightModel { model BASE_COLOR }\n"
                 "  BaseColor { rgb 1 0 1 }\n"
                 "  Shuttle { translation0 -3 0 0 translation1 3 0 0 speed 0.25 }\n"
                 "  Cube { width 1 height 1 depth 1 }\n"
                 "}\n";
    }
    const int shots = 4;
    {
        std::ofstream script(file("script.txt"));
        for (int i = 0; i < shots; ++i)
            script << "wait 15\nscreenshot " << file("shot" + std::to_string(i) + ".png") << "\n";
        script << "quit\n";
    }
    std::string log;
    const int status =
        runViewerScript(file("shuttle.iv"), "--size 400x400 --no-panels", file("script.txt"), log);
    INFO("viewer output: " << log);
    REQUIRE(status == 0);

    double firstTime = 0.0, lastTime = 0.0, firstX = 0.0;
    double largestMove = 0.0;
    for (int i = 0; i < shots; ++i) {
        const std::string name = file("shot" + std::to_string(i) + ".png");
        const double t = sceneTimeOf(log, name);
        const Blob cube = magenta(readPng(name));
        CAPTURE(i);
        CAPTURE(t);
        REQUIRE(cube.pixels > 0);
        // Inventor's Shuttle: translation0 + (translation1 - translation0) (1 - cos 2 pi s t) / 2.
        const double alpha = (1.0 - std::cos(2.0 * std::numbers::pi * 0.25 * t)) * 0.5;
        const double x = -3.0 + 6.0 * alpha;
        // The whole cube at full resolution: 40 x 40 pixels (edges within one pixel).
        CHECK(std::abs(cube.pixels - 1600) <= 160);
        CHECK(std::abs((cube.maxX - cube.minX + 1) - 40) <= 1);
        // Its centre where the formula puts it at the reported time, within 1.5 pixels.
        CHECK(std::abs(cube.centreX - (200.0 + 40.0 * x)) <= 1.5);
        CHECK(std::abs(cube.centreY - 200.0) <= 1.5);
        if (i == 0) {
            firstTime = t;
            firstX = cube.centreX;
        }
        lastTime = t;
        largestMove = std::max(largestMove, std::abs(cube.centreX - firstX));
    }
    // The clock ran and the cube moved between the shots.
    CHECK(lastTime > firstTime);
    CHECK(largestMove > 2.0);
    fs::remove_all(dir);
}
