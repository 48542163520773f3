// volsg-view's views and modes under Xvfb, driven by a script: stereo anaglyph and side by side
// against mono, the four-view layout, a click in the coronal view moving the cursor (and the
// scene's axial OrthoSlice), fly and walk moving the camera; the saved scene and the
// screenshots are checked against what each must do. Skips itself where xvfb-run is missing.
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
#include <volsg/nodes/OrthoSlice.h>

#include "ViewerTestSupport.h"

using namespace volsg;
namespace fs = std::filesystem;

namespace {

const glm::vec3 kBackground = glm::vec3(26.0f, 26.0f, 31.0f) / 255.0f; // 0.1 0.1 0.12

int nonBackground(const Image& image, int x0, int y0, int x1, int y1) {
    int count = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const glm::vec3 d = glm::abs(glm::vec3(image.at(x, y)) - kBackground);
            if (std::max(d.r, std::max(d.g, d.b)) > 3.0f / 255.0f) ++count;
        }
    return count;
}

} // namespace

TEST_CASE("scripted viewer session switches views, stereo and navigation and moves the cursor") {
    if (!haveXvfbRun()) {
        MESSAGE("xvfb-run is not installed: the viewer views test is skipped");
        return;
    }
    const fs::path dir =
        fs::temp_directory_path() / ("volsg-view-views-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string scene = std::string(VOLSG_SOURCE_DIR) + "/tests/viewer/views-scene.iv";
    REQUIRE(fs::exists(std::string(VOLSG_BINARY_DIR) + "/viewer/volsg-view"));
    auto file = [&](const char* name) { return (dir / name).string(); };
    {
        // A 640x400 window without panels: in four views each view is 320x200.
        std::ofstream script(file("script.txt"));
        script << "wait 1\n"
               << "screenshot " << file("mono.png") << "\n"
               << "stereo anaglyph 0.1\n" // the slice 0.8 in front of the focus: ~10 px
               << "wait 1\n"
               << "screenshot " << file("anaglyph.png") << "\n"
               << "stereo side-by-side 0.05\n"
               << "wait 1\n"
               << "screenshot " << file("sbs.png") << "\n"
               << "stereo off\n"
               << "layout four\n"
               << "wait 1\n"
               << "screenshot " << file("four.png")
               << "\n"
               // Coronal: x right, z up. V = 0.8 is z = 0.3 * 1.06 * 2 above the centre.
               << "click left view:coronal:0.5,0.8\n"
               << "wait 1\n"
               << "screenshot " << file("four-clicked.png") << "\n"
               << "layout single\n"
               << "navigation fly\n"
               << "click left view:3d:0.5,0.5\n" // faster: from rest to the base speed
               << "wait 12\n"
               << "navigation walk\n"
               << "drag left view:3d:0.5,0.5 view:3d:0.5,0.0 6\n" // hold at the top: forward
               << "navigation examiner\n"
               << "wait 1\n"
               << "save " << file("saved.iv") << "\n"
               << "quit\n";
    }
    std::string log;
    const int status =
        runViewerScript(scene, "--size 640x400 --no-panels", file("script.txt"), log);
    INFO("viewer output: " << log);
    REQUIRE(status == 0);

    const Image mono = readPng(file("mono.png")), anaglyph = readPng(file("anaglyph.png"));
    const Image sbs = readPng(file("sbs.png"));
    const Image four = readPng(file("four.png")), clicked = readPng(file("four-clicked.png"));
    REQUIRE(mono.width == 640);
    REQUIRE(mono.height == 400);
    // Stereo: the anaglyph's colour separation and the halved side-by-side views change the
    // picture where the volume is, and not the background far from it.
    CHECK(changedPixels(mono, anaglyph, 2.0f / 255.0f, 0, 0, 640, 380) > 100); // the fringes
    CHECK(changedPixels(mono, anaglyph, 2.0f / 255.0f, 0, 0, 100, 380) == 0);
    CHECK(changedPixels(mono, sbs, 2.0f / 255.0f, 0, 0, 640, 380) > 1000);
    int redOnly = 0; // the anaglyph's left-eye edge: red differs from the mono picture alone
    for (int y = 0; y < 380; ++y)
        for (int x = 0; x < 640; ++x) {
            const glm::vec4 a = anaglyph.at(x, y), m = mono.at(x, y);
            if (std::abs(a.r - m.r) > 2.0f / 255.0f && std::abs(a.g - m.g) <= 1.0f / 255.0f)
                ++redOnly;
        }
    CHECK(redOnly > 20);
    // Four views: each quadrant shows something (3D volume, axial, coronal, sagittal slices).
    for (const auto& corner : {std::pair{0, 0}, {320, 0}, {0, 200}, {320, 200}}) {
        const int x0 = corner.first, y0 = corner.second; // CAPTURE cannot take a binding
        CAPTURE(x0);
        CAPTURE(y0);
        CHECK(nonBackground(four, x0, y0, x0 + 320, y0 + 200) > 4000);
    }
    // The click moved the cursor: the crosshairs move in the section views.
    CHECK(changedPixels(four, clicked, 2.0f / 255.0f, 320, 0, 640, 200) > 100);
    CHECK(changedPixels(four, clicked, 2.0f / 255.0f, 0, 200, 320, 400) > 100);

    ref_ptr<Node> saved = readScene(file("saved.iv"));
    auto* slice = static_cast<OrthoSlice*>(findByName(*saved, "sliceZ"));
    auto* camera = static_cast<Camera*>(findByName(*saved, "camera"));
    REQUIRE(slice);
    REQUIRE(camera);
    // V = 0.8 of the 200-pixel view: 60 pixels above the centre at 2.12 / 200 units per
    // pixel = 0.636; the voxel floor((0.636 + 1) / 0.0625) = 26 (the view's height is the
    // box's 2 units with a 6% margin).
    CHECK(slice->sliceNumber() == 26);
    // Fly then walk forward along -z at the eye height: z shrank, x and y stayed.
    CHECK(camera->position().z < 4.4f);
    CHECK(std::abs(camera->position().x) < 1e-4f);
    CHECK(std::abs(camera->position().y) < 1e-4f);
    fs::remove_all(dir);
}
