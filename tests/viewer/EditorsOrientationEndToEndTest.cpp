// volsg-view under Xvfb: the 3D view buttons (anterior, left, superior) turn the camera to
// look from that side of the patient, the axes marker and the scale bar show in the 3D view,
// a ctrl+right drag is window/level of the transfer function's range, and a preset applied to
// the opacity alone leaves the colours as they were. Skips itself without xvfb-run.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <volsg/actions/SearchAction.h>
#include <volsg/editors/TransferFunctionPresets.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/volume/VolumeGrid.h>

#include "ViewerTestSupport.h"
#include "view/WindowLayout.h"

using namespace volsg;
namespace fs = std::filesystem;

namespace {

Camera& cameraIn(Node& root) {
    auto* camera = static_cast<Camera*>(findByName(root, "camera"));
    REQUIRE(camera);
    return *camera;
}

/// The camera's view direction and up in the world.
std::pair<glm::dvec3, glm::dvec3> lookOf(const Camera& camera) {
    const glm::dquat q = camera.orientation().quat();
    return {q * glm::dvec3(0, 0, -1), q * glm::dvec3(0, 1, 0)};
}

int pixelsLike(const Image& image, const PixelRect& r, glm::vec3 colour, float tolerance) {
    int count = 0;
    for (int y = r.y; y < r.y + r.height; ++y)
        for (int x = r.x; x < r.x + r.width; ++x) {
            const glm::vec3 d = glm::abs(glm::vec3(image.at(x, y)) - colour);
            count += std::max(d.r, std::max(d.g, d.b)) <= tolerance;
        }
    return count;
}

} // namespace

TEST_CASE("view buttons, axes marker, scale bar, window/level and an opacity preset") {
    if (!haveXvfbRun()) {
        MESSAGE("xvfb-run is not installed: the viewer orientation test is skipped");
        return;
    }
    const fs::path dir =
        fs::temp_directory_path() / ("volsg-view-orient-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string scene = std::string(VOLSG_SOURCE_DIR) + "/tests/viewer/views-scene.iv";
    auto file = [&](const char* name) { return (dir / name).string(); };
    {
        std::ofstream script(file("script.txt"));
        script << "view anterior\n"
               << "wait 1\n"
               << "save " << file("anterior.iv") << "\n"
               << "view left\n"
               << "wait 1\n"
               << "save " << file("left.iv") << "\n"
               << "view superior\n"
               << "wait 1\n"
               << "screenshot " << file("superior.png") << "\n"
               << "save " << file("superior.iv")
               << "\n"
               // Window/level: 20% of the view to the right, 10% up.
               << "drag right view:3d:0.5,0.5 view:3d:0.7,0.6 4 ctrl\n"
               << "wait 1\n"
               << "save " << file("windowed.iv") << "\n"
               << "preset opacity CT soft tissue\n"
               << "wait 1\n"
               << "save " << file("preset.iv") << "\n"
               << "quit\n";
    }
    std::string log;
    const int status =
        runViewerScript(scene, "--size 800x500 --background 1,0,1", file("script.txt"), log);
    INFO("viewer output: " << log);
    REQUIRE(status == 0);

    // RAS: anterior looks along -y, head (+z) up; left looks along +x; superior down -z with
    // anterior (+y) up. (The scene's volume has no transform: its axes are the world's.)
    const auto near = [](glm::dvec3 a, glm::dvec3 b) { return glm::length(a - b) < 1e-4; };
    ref_ptr<Node> anterior = readScene(file("anterior.iv")), left = readScene(file("left.iv"));
    ref_ptr<Node> superior = readScene(file("superior.iv"));
    CHECK(near(lookOf(cameraIn(*anterior)).first, {0, -1, 0}));
    CHECK(near(lookOf(cameraIn(*anterior)).second, {0, 0, 1}));
    CHECK(near(lookOf(cameraIn(*left)).first, {1, 0, 0}));
    CHECK(near(lookOf(cameraIn(*left)).second, {0, 0, 1}));
    CHECK(near(lookOf(cameraIn(*superior)).first, {0, 0, -1}));
    CHECK(near(lookOf(cameraIn(*superior)).second, {0, 1, 0}));
    // View all after the turn: the focal point is the volume's centre.
    const Camera& c = cameraIn(*superior);
    CHECK(glm::length(glm::dvec3(c.position()) + lookOf(c).first * double(c.focalDistance())) <
          1e-3);

    // The marker's red R axis in the 3D view's bottom-left corner, the white scale bar in its
    // bottom-right corner (neither is in the background or the volume's colours).
    const Image shot = readPng(file("superior.png"));
    const PixelRect view = layoutWindow({800, 500}, true, ViewLayout::Single).views[0];
    const PixelRect markerCorner{view.x, view.y + view.height - 90, 90, 90};
    const PixelRect barCorner{view.x + view.width - view.width / 3, view.y + view.height - 50,
                              view.width / 3, 50};
    CHECK(pixelsLike(shot, markerCorner, {235 / 255.0f, 70 / 255.0f, 70 / 255.0f}, 0.08f) > 20);
    CHECK(pixelsLike(shot, barCorner, {235 / 255.0f, 235 / 255.0f, 235 / 255.0f}, 0.05f) > 30);
    CHECK(pixelsLike(shot, {view.x + view.width / 3, view.y, view.width / 3, 60},
                     {235 / 255.0f, 235 / 255.0f, 235 / 255.0f}, 0.05f) == 0);

    // Window/level: from the function's range [0, 255] (default), width + 0.2 span and level
    // + 0.1 span, the span being the data's own max - min.
    ref_ptr<Node> original = readScene(scene), windowed = readScene(file("windowed.iv"));
    auto* data = static_cast<VolumeData*>(findAll(*original, VolumeData::classType()).front());
    const auto [lo, hi] = data->grid()->minMax();
    const double span = hi - lo;
    auto* tf = static_cast<TransferFunction*>(findByName(*windowed, "tf"));
    REQUIRE(tf);
    const double width = 255.0 + 0.2 * span, level = 127.5 + 0.1 * span;
    const double pixel = span / 540.0; // a pixel of the drag, in data units
    CHECK(std::abs(tf->dataRange()[0] - (level - 0.5 * width)) < 2.0 * pixel);
    CHECK(std::abs(tf->dataRange()[1] - (level + 0.5 * width)) < 2.0 * pixel);

    // The preset on the opacity alone: alpha is the preset's (through the windowed range),
    // the colours are the scene's.
    ref_ptr<Node> preset = readScene(file("preset.iv"));
    auto* after = static_cast<TransferFunction*>(findByName(*preset, "tf"));
    auto* before = static_cast<TransferFunction*>(findByName(*original, "tf"));
    REQUIRE(after);
    const TransferFunctionPreset* soft = nullptr;
    for (const auto& p : transferFunctionPresets())
        if (p.name == "CT soft tissue") soft = &p;
    REQUIRE(soft);
    CHECK(after->alpha.getValues() ==
          presetChannelInV(*soft, 3, glm::dvec2(tf->dataRange()), {lo, hi}));
    CHECK(after->red.getValues() == before->red.getValues());
    CHECK(after->green.getValues() == before->green.getValues());
    CHECK(after->blue.getValues() == before->blue.getValues());
    fs::remove_all(dir);
}
