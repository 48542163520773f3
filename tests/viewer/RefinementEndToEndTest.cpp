// volsg-view's first image and interactive frames under Xvfb: the first frame of a scene is a
// coarse image (a quarter of the resolution) that looks like the full still frame that follows
// (the same transfer function and brightness: block averages agree), and a frame drawn during
// a drag (a pan there and back, so the view is the same) looks like the still frame too. The
// viewer says when each image came. Frames with nothing new show the kept still image without
// drawing it. No timing is asserted here (volsg-bench's business).
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <volsg/image/Image.h>

#include "ViewerTestSupport.h"

using namespace volsg;
namespace fs = std::filesystem;

namespace {

/// The mean colour of each 16 x 16 block of the image's [0, w) x [0, h - 24) (the mode line
/// at the bottom left out).
std::vector<glm::vec3> blockMeans(const Image& image, int w, int h) {
    std::vector<glm::vec3> out;
    for (int by = 0; by + 16 <= h - 24; by += 16)
        for (int bx = 0; bx + 16 <= w; bx += 16) {
            glm::vec3 sum(0.0f);
            for (int y = by; y < by + 16; ++y)
                for (int x = bx; x < bx + 16; ++x)
                    sum += glm::vec3(image.at(x, y));
            out.push_back(sum / 256.0f);
        }
    return out;
}

struct Likeness {
    double meanDifference = 0.0; ///< of the block means, per channel
    double brightnessRatio = 1.0;
};

Likeness compare(const Image& a, const Image& b, int w, int h) {
    const auto ma = blockMeans(a, w, h), mb = blockMeans(b, w, h);
    double diff = 0.0, sa = 0.0, sb = 0.0;
    for (std::size_t i = 0; i < ma.size(); ++i) {
        const glm::vec3 d = glm::abs(ma[i] - mb[i]);
        diff += (d.r + d.g + d.b) / 3.0;
        sa += ma[i].r + ma[i].g + ma[i].b;
        sb += mb[i].r + mb[i].g + mb[i].b;
    }
    return {diff / double(ma.size()), sa / sb};
}

} // namespace

TEST_CASE("the first image is a coarse version of the still frame, and so are drag frames") {
    if (!haveXvfbRun()) {
        MESSAGE("xvfb-run is not installed: the viewer refinement test is skipped");
        return;
    }
    const fs::path dir =
        fs::temp_directory_path() / ("volsg-view-refine-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string scene = std::string(VOLSG_SOURCE_DIR) + "/examples/volumes/marschner-lobb.iv";
    auto file = [&](const char* name) { return (dir / name).string(); };
    {
        std::ofstream script(file("script.txt"));
        script << "screenshot " << file("first.png") << "\n" // the first frame: coarse
               << "wait 1\n"
               << "screenshot " << file("still.png") << "\n"
               << "press left view:3d:0.5,0.5 shift\n" // a pan out and back: the same view
               << "move view:3d:0.7,0.5\n"
               << "move view:3d:0.5,0.5\n"
               << "move view:3d:0.7,0.5\n"
               << "move view:3d:0.5,0.5\n"
               << "screenshot " << file("drag.png") << "\n"
               << "release left view:3d:0.5,0.5 shift\n"
               << "wait 2\n"
               << "screenshot " << file("after.png") << "\n"
               << "wait 10\n" // nothing changes: the kept still image is shown again
               << "screenshot " << file("idle.png") << "\n"
               << "quit\n";
    }
    std::string log;
    const int status =
        runViewerScript(scene, "--size 640x400 --no-panels", file("script.txt"), log);
    INFO("viewer output: " << log);
    REQUIRE(status == 0);
    const std::size_t first = log.find("first (coarse) image after");
    const std::size_t full = log.find("full image after");
    CHECK(first != std::string::npos);
    CHECK(full != std::string::npos);
    CHECK(first < full);

    const Image coarse = readPng(file("first.png")), still = readPng(file("still.png"));
    const Image drag = readPng(file("drag.png"));
    // The coarse image differs from the still one (it is coarser) ...
    CHECK(changedPixels(coarse, still, 4.0f / 255.0f, 0, 0, 640, 376) > 500);
    // ... but looks the same at the scale of 16-pixel blocks: colours within 3% of the range
    // on average and the same overall brightness within 5%.
    const Likeness a = compare(coarse, still, 640, 400);
    CHECK(a.meanDifference < 0.03);
    CHECK(std::abs(a.brightnessRatio - 1.0) < 0.05);
    CHECK(changedPixels(drag, still, 4.0f / 255.0f, 0, 0, 640, 376) > 500); // a drag frame
    const Likeness b = compare(drag, still, 640, 400);
    CHECK(b.meanDifference < 0.03);
    CHECK(std::abs(b.brightnessRatio - 1.0) < 0.05);
    // Idle frames show the still image again, pixel for pixel, without drawing it: the viewer
    // reports at least those 10 frames as not drawn.
    const Image after = readPng(file("after.png")), idle = readPng(file("idle.png"));
    CHECK(changedPixels(after, idle, 0.0f) == 0);
    const std::size_t framesAt = log.find(" frames, ");
    REQUIRE(framesAt != std::string::npos);
    const std::size_t lineStart = log.rfind(' ', framesAt - 1) + 1;
    const long long frames = std::stoll(log.substr(lineStart, framesAt - lineStart));
    const long long drawn = std::stoll(log.substr(framesAt + 9));
    CHECK(drawn <= frames - 10);
    fs::remove_all(dir);
}
