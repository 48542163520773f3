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

#include "ViewerTestSupport.h"

using namespace volsg;
namespace fs = std::filesystem;

namespace {

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
    REQUIRE(fs::exists(std::string(VOLSG_BINARY_DIR) + "/viewer/volsg-view"));
    auto file = [&](const char* name) { return (dir / name).string(); };
    {
        std::ofstream script(file("script.txt"));
        // The 800x500 window: the panel column on the right (260 px), the view left of it.
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
               // The alpha channel's end point (1, 0.6) dragged down to (1, 0.1), with the
               // transfer-function section scrolled to the top of the column.
               << "panel tf\n"
               << "wait 1\n"
               << "drag left tf:1,0.6 tf:1,0.1 2\n"
               << "screenshot " << file("s3.png") << " scene\n"
               << "save " << file("saved.iv") << "\n"
               << "quit\n";
    }
    std::string log;
    const int status = runViewerScript(scene, "--size 800x500", file("script.txt"), log);
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

TEST_CASE("a scripted seek flies the camera to the volume's visible content") {
    if (!haveXvfbRun()) {
        MESSAGE("xvfb-run is not installed: the viewer end-to-end test is skipped");
        return;
    }
    const fs::path dir =
        fs::temp_directory_path() / ("volsg-view-seek-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string scene = std::string(VOLSG_SOURCE_DIR) + "/tests/viewer/viewer-scene.iv";
    auto file = [&](const char* name) { return (dir / name).string(); };
    {
        std::ofstream script(file("script.txt"));
        script << "wait 1\n"
               << "screenshot " << file("before.png") << " scene\n"
               << "key s\n"
               << "click left world:0,0,0\n" // the volume's centre, straight ahead
               << "wait 3\n"
               << "screenshot " << file("during.png") << " scene\n"
               << "wait seek\n"
               << "screenshot " << file("after.png") << " scene\n"
               << "save " << file("saved.iv") << "\n"
               << "quit\n";
    }
    std::string log;
    const int status =
        runViewerScript(scene, "--size 400x300 --no-panels", file("script.txt"), log);
    INFO("viewer output: " << log);
    REQUIRE(status == 0);

    ref_ptr<Node> saved = readScene(file("saved.iv"));
    auto* camera = static_cast<Camera*>(findByName(*saved, "camera"));
    REQUIRE(camera);
    // The click's ray runs down the z axis. Its pick is the soft sphere's visible content (the
    // data 1 - r / 0.9 under alpha 0.6 v reaches 0.02 at r = 0.87), not the box face at z = 1:
    // the new focal point is there and the camera half way from z = 4.5 to it.
    const glm::dvec3 p(camera->position());
    CHECK(std::abs(p.x) < 1e-3);
    CHECK(std::abs(p.y) < 1e-3);
    CHECK(camera->orientation().angle == 0.0f); // the seek keeps the orientation
    const double picked = p.z - double(camera->focalDistance());
    CHECK(picked == doctest::Approx(0.87).epsilon(0.07)); // within half a voxel (1/16)
    CHECK(picked < 0.95);
    CHECK(p.z == doctest::Approx(0.5 * (4.5 + picked)).epsilon(1e-4));
    // Three frames after the click the camera is on its way: that picture differs from both
    // the one before and the one after.
    const Image before = readPng(file("before.png")), during = readPng(file("during.png"));
    const Image after = readPng(file("after.png"));
    CHECK(changedPixels(before, during, 2.0f / 255.0f) > 500);
    CHECK(changedPixels(during, after, 2.0f / 255.0f) > 500);
    fs::remove_all(dir);
}
