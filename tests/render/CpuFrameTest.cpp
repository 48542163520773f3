// Frames whose only drawing is images rendered on the CPU (ShearWarpVolume) are composited on
// the CPU (RenderDebug::cpuFrames): the same pixels as the GL frame, and GL wherever anything
// else draws.
#include <doctest/doctest.h>

#include "support/ImageDifference.h"

#include <volsg/context/OSMesaContext.h>
#include <volsg/io/SceneReader.h>
#include <volsg/render/Renderer.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace volsg;
using volsg::test::maxDifference;

namespace {

/// A 32^3 volume in [-1, 1]^3 under an orthographic camera, `body` after it.
std::string sceneWith(const std::string& body) {
    return "#Inventor V2.1 ascii\nSeparator {\n"
           "  OrthographicCamera { position 0.3 0.2 5 height 2.5 nearDistance 1 farDistance 9 }\n"
           "  VolumeData { generator SOFT_SPHERE dimensions 32 32 32 spacing 0.0625 0.0625 "
           "0.0625 }\n" +
           body + "}\n";
}

const std::string kTransfer =
    "    TransferFunction { red [ 0 0.2, 1 1 ] green [ 0 0.5, 1 0.8 ] blue [ 0 1, 1 0.3 ] "
    "alpha [ 0 0, 0.3 0, 1 0.4 ] }\n";

std::string shearWarp(const std::string& object = "    VolumeObject { }\n") {
    return "  ShearWarpVolume {\n" + kTransfer + object + "  }\n";
}

RenderOptions options(bool cpuFrames) {
    RenderOptions o;
    o.width = 72;
    o.height = 56;
    o.background = glm::vec3(0.2f, 0.3f, 0.4f);
    o.debug.cpuFrames = cpuFrames;
    return o;
}

/// Pixels that are not the background: the volume was drawn.
std::size_t drawnPixels(const Image& image, const RenderOptions& o) {
    std::size_t n = 0;
    for (const glm::vec4& p : image.pixels)
        if (glm::any(glm::greaterThan(glm::abs(glm::vec3(p) - o.background), glm::vec3(1e-3f))))
            ++n;
    return n;
}

struct Frames {
    Image cpu, gl;
    bool cpuFrame = false, glFrame = true;
};

/// The scene rendered with CPU frames allowed and with them off, each by a Renderer of its own.
Frames renderBoth(const std::string& text) {
    const ref_ptr<Node> root = readSceneFromString(text);
    Frames f;
    Renderer a, b;
    f.cpu = a.render(*root, options(true));
    f.cpuFrame = a.stats().cpuFrame;
    f.gl = b.render(*root, options(false));
    f.glFrame = b.stats().cpuFrame;
    return f;
}

} // namespace

TEST_CASE("ShearWarpVolumes alone are composited on the CPU, to the GL frame's pixels") {
    OSMesaContext context;
    // GL blends in float with the same operations: the tolerance is one float rounding.
    constexpr float kTolerance = 1e-6f;
    const std::vector<std::pair<const char*, std::string>> scenes = {
        {"unshaded", sceneWith(shearWarp())},
        {"shaded", sceneWith(shearWarp("    VolumeObject { renderMode SHADED }\n"))},
        {"two volumes, the second moved",
         sceneWith(shearWarp() + "  Translation { translation 0.4 -0.2 -0.5 }\n" + shearWarp())},
        {"empty: the background", "#Inventor V2.1 ascii\nSeparator { OrthographicCamera { } }\n"},
    };
    for (const auto& scene : scenes) {
        const std::string name = scene.first;
        CAPTURE(name);
        const Frames f = renderBoth(scene.second);
        CHECK(f.cpuFrame);
        CHECK(!f.glFrame);
        const float d = maxDifference(f.cpu, f.gl);
        MESSAGE(name << ": " << drawnPixels(f.gl, options(false)) << " pixels drawn, CPU and GL "
                     << d << " apart");
        CHECK(d <= kTolerance);
        if (name.starts_with("empty"))
            CHECK(drawnPixels(f.gl, options(false)) == 0);
        else
            CHECK(drawnPixels(f.gl, options(false)) > 500);
    }
}

TEST_CASE("a frame with anything GL draws is drawn by GL") {
    OSMesaContext context;
    const std::vector<std::pair<const char*, std::string>> scenes = {
        {"a Cube", sceneWith(shearWarp() + "  Cube { width 0.3 height 0.3 depth 0.3 }\n")},
        {"a Cube first", sceneWith("  Cube { width 0.3 height 0.3 depth 0.3 }\n" + shearWarp())},
        {"a Volume", sceneWith(shearWarp() + "  Volume { }\n")},
        {"a Text2", sceneWith(shearWarp() + "  Text2 { string \"volsg\" }\n")},
        {"an Annotation", sceneWith(shearWarp() + "  Annotation { Sphere { radius 0.2 } }\n")},
        {"a Surface object's depth",
         sceneWith(shearWarp("    VolumeObject { source THRESHOLD threshold 128 255 voxels "
                             "SURFACE compositing SURFACE }\n"))},
    };
    for (const auto& scene : scenes) {
        const std::string name = scene.first;
        CAPTURE(name);
        const Frames f = renderBoth(scene.second);
        CHECK(!f.cpuFrame);
        CHECK(maxDifference(f.cpu, f.gl) == 0.0f); // both GL frames
    }
    // Options a CPU frame does not cover: multisampling, the opaque pass alone.
    const ref_ptr<Node> root = readSceneFromString(sceneWith(shearWarp()));
    Renderer renderer;
    RenderOptions o = options(true);
    o.samples = 4;
    renderer.render(*root, o);
    CHECK(!renderer.stats().cpuFrame);
    o = options(true);
    o.opaqueOnly = true;
    renderer.render(*root, o);
    CHECK(!renderer.stats().cpuFrame);
}

TEST_CASE("after a CPU frame the renderer reads back its image and a depth of 1") {
    OSMesaContext context;
    const ref_ptr<Node> root = readSceneFromString(sceneWith(shearWarp()));
    Renderer renderer;
    const Image image = renderer.render(*root, options(true));
    REQUIRE(renderer.stats().cpuFrame);
    CHECK(maxDifference(renderer.readImage(), image) == 0.0f);
    const std::vector<float> depth = renderer.readWindowDepth();
    CHECK(depth.size() == image.pixels.size());
    CHECK(std::all_of(depth.begin(), depth.end(), [](float d) { return d == 1.0f; }));
    // renderFrame draws on GL: its image is the GL frame's.
    renderer.renderFrame(*root, options(true));
    CHECK(!renderer.stats().cpuFrame);
    CHECK(maxDifference(renderer.readImage(), image) <= 1e-6f);
}
