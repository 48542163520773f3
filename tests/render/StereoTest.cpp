// Stereo pairs against their geometry: an object at the focal distance has zero parallax, a
// nearer one crossed parallax of the predicted pixels, a farther one uncrossed; the anaglyph's
// red channel is the left eye and its green and blue the right eye; side-by-side puts each eye
// in its half.
#include <doctest/doctest.h>

#include "support/Offscreen.h"

#include <cmath>
#include <string>

#include <volsg/context/OSMesaContext.h>
#include <volsg/core/Error.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/io/SceneReader.h>
#include <volsg/render/StereoRenderer.h>

using namespace volsg;

namespace {

using volsg::test::Offscreen;

constexpr int kSize = 128;
constexpr double kFocal = 5.0, kSeparationFraction = 0.1; // eyes 0.5 apart
const glm::vec3 kBackground(0.1f, 0.1f, 0.1f);
constexpr float kGrey = 0.6f; // the squares' emissive grey (no diffuse: unlit by the headlight)

/// A camera at the origin looking down -z, 60 degrees high, focal distance 5, and a thin grey
/// square of side `side` facing it, centred at (x, 0, -depth).
ref_ptr<Node> squareScene(double x, double depth, double side, const char* camera) {
    const std::string text =
        std::string("#Inventor V2.1 ascii\nSeparator {\n") + camera +
        " Material { ambientColor 0 0 0 diffuseColor 0 0 0 emissiveColor 0.6 0.6 0.6 }\n"
        " Transform { translation " +
        std::to_string(x) + " 0 " + std::to_string(-depth) + " }\n Cube { width " +
        std::to_string(side) + " height " + std::to_string(side) + " depth 0.0001 }\n}\n";
    return readSceneFromString(text);
}

const char* perspectiveCamera =
    " PerspectiveCamera { position 0 0 0 heightAngle 1.0471975512 focalDistance 5 "
    "nearDistance 0.5 farDistance 50 }\n";

RenderOptions options() {
    RenderOptions o;
    o.width = kSize;
    o.height = kSize;
    o.background = kBackground;
    return o;
}

/// The mean x (pixel centres) of the pixels whose `channel` is brighter than the background.
double centroidX(const Image& image, int channel, int x0 = 0, int x1 = -1) {
    if (x1 < 0) x1 = image.width;
    double sum = 0.0, count = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = x0; x < x1; ++x)
            if (image.at(x, y)[channel] > 0.35f) {
                sum += x + 0.5;
                count += 1.0;
            }
    REQUIRE(count > 0.0);
    return sum / count;
}

Image renderEye(Renderer& renderer, Node& scene, Eye eye) {
    RenderOptions o = options();
    o.camera =
        stereoEyeCamera(*worldSpaceCamera(findOrMakeCamera(scene, 1.0)), kSeparationFraction, eye);
    return renderer.render(scene, o);
}

/// Right-eye x minus left-eye x of a point at `depth` in pixels: s P00 (1/f - 1/d) W/2.
double predictedParallax(double depth) {
    const double p00 = 1.0 / std::tan(0.5 * 1.0471975512); // aspect 1
    return kSeparationFraction * kFocal * p00 * (1.0 / kFocal - 1.0 / depth) * 0.5 * kSize;
}

} // namespace

TEST_CASE("an object at the focal distance has zero parallax") {
    Offscreen gl;
    auto scene = squareScene(0.7, kFocal, 1.0, perspectiveCamera);
    const Image left = renderEye(gl.renderer, *scene, Eye::Left);
    const Image right = renderEye(gl.renderer, *scene, Eye::Right);
    // Where the centre camera sees it: x = 0.7 at depth 5, P00 / 5 * 0.7 of the half width.
    const double expected = (1.0 + 0.7 / kFocal / std::tan(0.5 * 1.0471975512)) * 0.5 * kSize;
    CHECK(centroidX(left, 0) == doctest::Approx(expected).epsilon(0.5 / expected));
    CHECK(std::abs(centroidX(right, 0) - centroidX(left, 0)) < 0.25); // pixels
}

TEST_CASE("a nearer object has crossed parallax and a farther one uncrossed, as predicted") {
    Offscreen gl;
    for (double depth : {2.5, 3.5, 10.0}) {
        CAPTURE(depth);
        auto scene = squareScene(0.0, depth, 0.15 * depth, perspectiveCamera);
        const double parallax = centroidX(renderEye(gl.renderer, *scene, Eye::Right), 0) -
                                centroidX(renderEye(gl.renderer, *scene, Eye::Left), 0);
        const double predicted = predictedParallax(depth); // -11.1, -4.7, +5.5 pixels
        // Within 0.6 pixels: each square's centroid is of whole pixels at a hard edge.
        CHECK(std::abs(parallax - predicted) <= 0.6);
        CHECK((depth < kFocal ? parallax < -4.0 : parallax > 4.0)); // the sign: crossed if nearer
    }
}

TEST_CASE("an orthographic camera turns its eyes about the focal point") {
    Offscreen gl;
    const char* ortho = " OrthographicCamera { position 0 0 0 height 4 focalDistance 5 "
                        "nearDistance 0.5 farDistance 50 }\n";
    auto atFocus = squareScene(0.0, kFocal, 0.6, ortho);
    CHECK(std::abs(centroidX(renderEye(gl.renderer, *atFocus, Eye::Right), 0) -
                   centroidX(renderEye(gl.renderer, *atFocus, Eye::Left), 0)) < 0.25);
    // Turned by +-atan(0.25 / 5): a point 2.5 nearer shifts by 2.5 sin(angle) each way.
    auto nearer = squareScene(0.0, 2.5, 0.6, ortho);
    const double parallax = centroidX(renderEye(gl.renderer, *nearer, Eye::Right), 0) -
                            centroidX(renderEye(gl.renderer, *nearer, Eye::Left), 0);
    const double angle = std::atan2(0.25, kFocal);
    const double predicted = -2.0 * 2.5 * std::sin(angle) / 4.0 * kSize; // 4 units high
    CHECK(std::abs(parallax - predicted) <= 0.6);                        // pixels
}

TEST_CASE("the anaglyph's red channel is the left eye and green and blue the right eye") {
    Offscreen gl;
    auto scene = squareScene(0.0, 2.5, 0.4, perspectiveCamera); // 11 pixels of parallax
    StereoOptions stereo;
    stereo.mode = StereoMode::Anaglyph;
    stereo.separationFraction = kSeparationFraction;
    const Image anaglyph = renderStereo(gl.renderer, *scene, options(), stereo);
    REQUIRE(anaglyph.width == kSize);
    // Where each eye's square is, from the geometry: half side 0.2 at depth 2.5, centre shifted
    // by half the parallax to each side.
    const double p00 = 1.0 / std::tan(0.5 * 1.0471975512);
    const double halfSide = 0.2 / 2.5 * p00 * 0.5 * kSize, shift = 0.5 * predictedParallax(2.5);
    auto inside = [&](int x, int y, double centre) {
        const double px = x + 0.5 - centre, py = y + 0.5 - 0.5 * kSize;
        return std::abs(px) < halfSide - 1.0 && std::abs(py) < halfSide - 1.0;
    };
    auto outside = [&](int x, int y, double centre) {
        const double px = x + 0.5 - centre, py = y + 0.5 - 0.5 * kSize;
        return std::abs(px) > halfSide + 1.0 || std::abs(py) > halfSide + 1.0;
    };
    const double mid = 0.5 * kSize;
    int leftOnly = 0, rightOnly = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const glm::vec4 c = anaglyph.at(x, y);
            const bool inLeft = inside(x, y, mid - shift), inRight = inside(x, y, mid + shift);
            const bool outLeft = outside(x, y, mid - shift), outRight = outside(x, y, mid + shift);
            if (inLeft) CHECK(std::abs(c.r - kGrey) <= 1.0f / 255.0f);
            if (outLeft) CHECK(std::abs(c.r - kBackground.r) <= 1.0f / 255.0f);
            if (inRight) {
                CHECK(std::abs(c.g - kGrey) <= 1.0f / 255.0f);
                CHECK(std::abs(c.b - kGrey) <= 1.0f / 255.0f);
            }
            if (outRight) {
                CHECK(std::abs(c.g - kBackground.g) <= 1.0f / 255.0f);
                CHECK(std::abs(c.b - kBackground.b) <= 1.0f / 255.0f);
            }
            leftOnly += inLeft && outRight;
            rightOnly += inRight && outLeft;
        }
    CHECK(leftOnly > 50); // the parallax really separates the two squares' pixels
    CHECK(rightOnly > 50);
}

TEST_CASE("side-by-side puts the left eye in the left half and the right eye in the right") {
    Offscreen gl;
    auto scene = squareScene(0.0, 2.5, 0.5, perspectiveCamera);
    StereoOptions stereo;
    stereo.mode = StereoMode::SideBySide;
    stereo.separationFraction = kSeparationFraction;
    RenderOptions o = options();
    o.width = 2 * kSize;
    const Image pair = renderStereo(gl.renderer, *scene, o, stereo);
    REQUIRE(pair.width == 2 * kSize);
    REQUIRE(pair.height == kSize);
    // Each half is a 128x128 eye view: the same parallax as above within each half.
    const double leftX = centroidX(pair, 1, 0, kSize);
    const double rightX = centroidX(pair, 1, kSize, 2 * kSize) - kSize;
    CHECK(std::abs(rightX - leftX - predictedParallax(2.5)) <= 0.6); // pixels
    CHECK(leftX > 0.5 * kSize); // the left eye sees a centred near object to its right
}

TEST_CASE("stereo modes parse by name and unknown ones are errors") {
    CHECK(parseStereoMode("anaglyph") == StereoMode::Anaglyph);
    CHECK(parseStereoMode("side-by-side") == StereoMode::SideBySide);
    CHECK(parseStereoMode("off") == StereoMode::Off);
    CHECK_THROWS_AS(parseStereoMode("interlaced"), Error);
    CHECK(std::string(stereoModeName(StereoMode::SideBySide)) == "side-by-side");
}
