// The scene-to-reference bridge: collectVolumes() reads each Volume's state as a render would,
// and renderReference() composites the reference ray caster over GL's opaque geometry.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include <volsg/context/Context.h>
#include <volsg/core/Error.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/volumescene/ReferenceScene.h>

#include "../support/TempDir.h"

using namespace volsg;

namespace {

ref_ptr<Node> scene(const std::string& body) {
    return readSceneFromString("#Inventor V2.1 ascii\nSeparator {\n" + body + "\n}\n");
}

const char* smallVolume = "VolumeData { generator SOFT_SPHERE dimensions 4 4 4 }\n";

void checkMatrix(const glm::dmat4& actual, const glm::dmat4& expected, double tolerance) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            INFO("element [", c, "][", r, "]");
            CHECK(std::abs(actual[c][r] - expected[c][r]) <= tolerance);
        }
}

void checkPlane(const glm::dvec4& actual, const glm::dvec4& expected) {
    for (int i = 0; i < 4; ++i)
        CHECK(std::abs(actual[i] - expected[i]) < 1e-6);
}

// A constant-density volume filling [-1, 1]^3: RAMP16 data with a transfer function that is
// constant in colour (red) and opacity, so tau does not depend on the data. L0 = 0.25.
constexpr double kSlabAlpha = 0.2;
constexpr double kL0 = 0.25;
const std::string constantVolume =
    "VolumeData { generator RAMP16 dimensions 8 8 8 spacing 0.25 0.25 0.25 }\n"
    "TransferFunction { red [ 0 1 ] green [ 0 0 ] blue [ 0 0 ] alpha [ 0 0.2 ] }\n"
    "Volume { }\n";
// An opaque unit cube at the centre, pure emissive green (no light or ambient terms).
const std::string greenCube =
    "Material { ambientColor 0 0 0 diffuseColor 0 0 0 specularColor 0 0 0 "
    "emissiveColor 0 1 0 }\nCube { width 1 height 1 depth 1 }\n";

double tau() {
    return -std::log(1.0 - kSlabAlpha) / kL0;
}

// Red emitted by a constant slab of thickness d, then what lies behind it, attenuated.
glm::dvec3 throughSlab(double d, const glm::dvec3& behind) {
    const double t = std::exp(-tau() * d);
    return glm::dvec3(1.0, 0.0, 0.0) * (1.0 - t) + t * behind;
}

void checkPixel(const Image& image, int x, int y, const glm::dvec3& expected, double tolerance) {
    const glm::vec4 p = image.at(x, y);
    INFO("pixel ", x, ",", y, ": ", p.r, " ", p.g, " ", p.b, " expected ", expected.r, " ",
         expected.g, " ", expected.b);
    for (int c = 0; c < 3; ++c)
        CHECK(std::abs(double(p[c]) - expected[c]) <= tolerance);
}

} // namespace

TEST_CASE("collectVolumes takes the model matrix at the Volume and its data") {
    auto root = scene(std::string(smallVolume) +
                      "Transform { translation 1 2 3 scaleFactor 2 2 2 }\nVolume { }\n");
    const auto volumes = collectVolumes(*root);
    REQUIRE(volumes.size() == 1);
    REQUIRE(volumes[0].data);
    CHECK(volumes[0].data->dimensions() == glm::ivec3(4));
    CHECK(!volumes[0].tags);
    const glm::dmat4 expected =
        glm::scale(glm::translate(glm::dmat4(1.0), {1.0, 2.0, 3.0}), glm::dvec3(2.0));
    checkMatrix(volumes[0].model, expected, 1e-12);
    CHECK(volumes[0].transferFunctions.empty()); // none in scope: the caster's identity default
    CHECK(!volumes[0].boxClip);
    CHECK(volumes[0].clipPlanes.empty());
}

TEST_CASE("collectVolumes keys transfer functions by tag and a later one replaces an earlier") {
    auto root = scene(std::string(smallVolume) + "TransferFunction { alpha [ 0 0.1 ] }\n"
                                                 "TransferFunction { tag 2 alpha [ 0 0.7 ] }\n"
                                                 "TransferFunction { tag -1 alpha [ 0 0.5 ] }\n"
                                                 "Volume { }\n");
    const auto volumes = collectVolumes(*root);
    REQUIRE(volumes.size() == 1);
    const auto& tfs = volumes[0].transferFunctions;
    CHECK(tfs.size() == 2);
    REQUIRE(tfs.count(-1) == 1);
    REQUIRE(tfs.count(2) == 1);
    CHECK(tfs.at(-1).evaluate(TransferFunction1D::Alpha, 0.3) == doctest::Approx(0.5));
    CHECK(tfs.at(2).evaluate(TransferFunction1D::Alpha, 0.3) == doctest::Approx(0.7));
}

TEST_CASE("a TransferFunction inside a Separator does not leak out of it") {
    auto root = scene(std::string(smallVolume) +
                      "TransferFunction { tag 1 alpha [ 0 0.25 ] }\n"
                      "Separator {\n  TransferFunction { tag 1 alpha [ 0 0.75 ] }\n"
                      "  TransferFunction { tag 4 }\n  Volume { renderMode MIP }\n}\n"
                      "Volume { }\n");
    const auto volumes = collectVolumes(*root);
    REQUIRE(volumes.size() == 2);
    // Inside: its own tag 1 replaces the outer one, and tag 4 is there.
    CHECK(volumes[0].mode == VolumeRenderMode::MIP);
    CHECK(volumes[0].transferFunctions.size() == 2);
    CHECK(volumes[0].transferFunctions.at(1).evaluate(TransferFunction1D::Alpha, 0.0) ==
          doctest::Approx(0.75));
    // After the Separator: only the outer tag 1.
    CHECK(volumes[1].mode == VolumeRenderMode::DVR);
    CHECK(volumes[1].transferFunctions.size() == 1);
    CHECK(volumes[1].transferFunctions.at(1).evaluate(TransferFunction1D::Alpha, 0.0) ==
          doctest::Approx(0.25));
}

TEST_CASE("collectVolumes gives clip planes in world coordinates and skips planes that are off") {
    auto root = scene(std::string(smallVolume) +
                      "Separator {\n  Transform { translation 0 0 2 }\n"
                      "  ClipPlane { plane 0 0 1 1 }\n}\n" // scoped away: not for the Volume
                      "Transform { translation 0 0 2 }\n"
                      "ClipPlane { plane 0 0 1 1 }\n" // z >= 1 locally: z >= 3 in world
                      "ClipPlane { plane 1 0 0 0 on FALSE }\n"
                      "Transform { rotation 0 1 0 1.5707963267948966 }\n"
                      "ClipPlane { plane 1 0 0 0.5 }\n" // local +x is world -z here
                      "Volume { }\n");
    const auto volumes = collectVolumes(*root);
    REQUIRE(volumes.size() == 1);
    const auto& planes = volumes[0].clipPlanes;
    REQUIRE(planes.size() == 2);
    checkPlane(planes[0], {0.0, 0.0, 1.0, 3.0});
    // Kept: local x >= 0.5; local x = -(world z - 2): world -z >= 0.5 - 2 = -1.5.
    checkPlane(planes[1], {0.0, 0.0, -1.0, -1.5});
}

TEST_CASE("BoxClip keeps the model matrix at its own place, not the Volume's") {
    auto root = scene(std::string(smallVolume) +
                      "Transform { translation 5 0 0 }\n"
                      "BoxClip { origin 0 0 0 extent 1 2 3 insideOpacity 0.5 outsideOpacity 0.25 "
                      "insideColor 1 0 0 insideColorWeight 0.5 outsideColorWeight 1 }\n"
                      "Transform { scaleFactor 2 2 2 }\nVolume { }\n");
    const auto volumes = collectVolumes(*root);
    REQUIRE(volumes.size() == 1);
    REQUIRE(volumes[0].boxClip);
    const RayCastBoxClip& box = *volumes[0].boxClip;
    CHECK(box.origin == glm::dvec3(0.0));
    CHECK(box.extent == glm::dvec3(1.0, 2.0, 3.0));
    REQUIRE(box.model);
    checkMatrix(*box.model, glm::translate(glm::dmat4(1.0), {5.0, 0.0, 0.0}), 1e-12);
    checkMatrix(volumes[0].model,
                glm::scale(glm::translate(glm::dmat4(1.0), {5.0, 0.0, 0.0}), glm::dvec3(2.0)),
                1e-12);
    CHECK(box.insideOpacity == 0.5);
    CHECK(box.outsideOpacity == 0.25);
    CHECK(box.insideColor == glm::dvec3(1.0, 0.0, 0.0));
    CHECK(box.insideColorWeight == 0.5);
    CHECK(box.outsideColorWeight == 1.0);
}

TEST_CASE("collectVolumes takes renderMode, planeOpacity and labels from the scene") {
    auto root = scene("VolumeData { generator LABELLED dimensions 8 8 8 }\n"
                      "Volume { renderMode AVERAGE planeOpacity [ 0 1, 0.5 0.25, 1 0 ] }\n");
    const auto volumes = collectVolumes(*root);
    REQUIRE(volumes.size() == 1);
    CHECK(volumes[0].mode == VolumeRenderMode::AVERAGE);
    REQUIRE(volumes[0].planeOpacity.size() == 3);
    CHECK(volumes[0].planeOpacity[1].x == 0.5);
    CHECK(volumes[0].planeOpacity[1].y == 0.25);
    REQUIRE(volumes[0].tags);
    CHECK(volumes[0].tags->dimensions() == glm::ivec3(8));
}

TEST_CASE("collectVolumes follows Switch and uses the nearest VolumeData") {
    auto root =
        scene("VolumeData { generator SOFT_SPHERE dimensions 4 4 4 }\n"
              "Switch { whichChild 1\n  Volume { }\n"
              "  Group { VolumeData { generator SOFT_SPHERE dimensions 6 6 6 } Volume { } }\n"
              "}\n");
    const auto volumes = collectVolumes(*root);
    REQUIRE(volumes.size() == 1);
    CHECK(volumes[0].data->dimensions() == glm::ivec3(6));
}

TEST_CASE("a Volume without VolumeData in scope is an error") {
    auto root = scene("Separator { VolumeData { generator SOFT_SPHERE } }\nVolume { }\n");
    try {
        collectVolumes(*root);
        FAIL("no error for a Volume without data");
    } catch (const Error& e) {
        CHECK(std::string(e.what()).find("Volume without VolumeData in scope") !=
              std::string::npos);
    }
}

TEST_CASE("the reference shows a cube inside a constant volume through the volume in front") {
    auto context = Context::createOffscreen();
    // Orthographic, straight down -z: 64 px across 4 units, 16 px per unit.
    auto root = scene("OrthographicCamera { position 0 0 10 height 4 nearDistance 1 "
                      "farDistance 20 }\n" +
                      constantVolume + greenCube);
    RenderOptions options;
    options.width = 64;
    options.height = 64;
    options.background = glm::vec3(0.0f, 0.0f, 1.0f);
    RayCastResult details;
    const Image image = renderReference(*root, options, &details);
    REQUIRE(image.width == 64);
    CHECK(details.converged);
    const glm::dvec3 blue(0.0, 0.0, 1.0), green(0.0, 1.0, 0.0);
    // Over the cube: the volume from its face at z = 1 to the cube's at z = 0.5, then green.
    checkPixel(image, 32, 32, throughSlab(0.5, green), 1e-3);
    checkPixel(image, 27, 37, throughSlab(0.5, green), 1e-3);
    // Beside the cube, inside the volume's square: 2 units of volume over the background.
    checkPixel(image, 20, 32, throughSlab(2.0, blue), 1e-3);
    checkPixel(image, 45, 20, throughSlab(2.0, blue), 1e-3);
    // Outside the volume (|x| > 1): the background alone.
    checkPixel(image, 2, 32, blue, 1e-6);
    checkPixel(image, 32, 61, blue, 1e-6);
}

TEST_CASE("the reference converts a perspective depth buffer to the right ray distance") {
    auto context = Context::createOffscreen();
    auto root = scene("PerspectiveCamera { position 0 0 5 heightAngle 0.5 nearDistance 2 "
                      "farDistance 9 }\n" +
                      constantVolume + greenCube);
    RenderOptions options;
    options.width = 33; // odd: the centre pixel's ray runs straight down the z axis
    options.height = 33;
    const Image image = renderReference(*root, options);
    checkPixel(image, 16, 16, throughSlab(0.5, glm::dvec3(0.0, 1.0, 0.0)), 1e-3);
}

TEST_CASE("volsg-render --reference writes a PFM of the reference image") {
    namespace fs = std::filesystem;
    const test::TempDir scratch("volsg-reference-scene-test");
    const fs::path& dir = scratch.path();
    const fs::path sceneFile = dir / "cube-in-volume.iv", out = dir / "reference.pfm",
                   log = dir / "reference.out";
    std::ofstream(sceneFile) << "#Inventor V2.1 ascii\nSeparator {\n"
                                "OrthographicCamera { position 0 0 10 height 4 nearDistance 1 "
                                "farDistance 20 }\n"
                             << constantVolume << greenCube << "}\n";
    fs::remove(out);
    const std::string command = std::string(VOLSG_BINARY_DIR) + "/viewer/volsg-render " +
                                sceneFile.string() + " --reference -o " + out.string() +
                                " --size 32x32 >" + log.string() + " 2>&1";
    const int status = std::system(command.c_str());
    std::stringstream printed;
    printed << std::ifstream(log).rdbuf();
    INFO(printed.str());
    REQUIRE(status == 0);
    CHECK(printed.str().find("error bound") != std::string::npos);
    const Image image = readPfm(out.string());
    REQUIRE(image.width == 32);
    REQUIRE(image.height == 32);
    // 8 px per unit: pixel 16 is over the cube, pixel 4 (x = -1.44) outside the volume.
    checkPixel(image, 16, 16, throughSlab(0.5, glm::dvec3(0.0, 1.0, 0.0)), 1e-3);
    checkPixel(image, 4, 16, glm::dvec3(0.0), 1e-6);
}
