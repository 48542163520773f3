// The ShearWarpVolume and VolumeObject nodes in a scene: file round trip, GL compositing
// against the reference, depth mixing with shapes, picking, time steps through a Switch.
#include <doctest/doctest.h>

#include <volsg/context/OSMesaContext.h>
#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/Switch.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/VolumeObject.h>
#include <volsg/render/Renderer.h>
#include <volsg/volumescene/ReferenceScene.h>

#include <cmath>
#include <string>

using namespace volsg;

namespace {

template <class T> T* findNode(Node& node) {
    if (node.isA<T>()) return static_cast<T*>(&node);
    if (auto* children = node.children())
        for (const auto& child : *children)
            if (child)
                if (T* found = findNode<T>(*child)) return found;
    return nullptr;
}

double rmse(const Image& a, const Image& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const glm::dvec3 d = glm::dvec3(a.pixels[i]) - glm::dvec3(b.pixels[i]);
        sum += glm::dot(d, d) / 3.0;
    }
    return std::sqrt(sum / double(a.pixels.size()));
}

/// A 32^3 volume in [-1, 1]^3 (spacing 1/16), an orthographic camera at z = 5 seeing
/// [-1.25, 1.25]^2, and `body` (state and objects) inside a ShearWarpVolume.
std::string sceneWith(const std::string& generator, const std::string& before,
                      const std::string& body, const std::string& after = "") {
    return "#Inventor V2.1 ascii\nSeparator {\n"
           "  OrthographicCamera { position 0 0 5 height 2.5 nearDistance 1 farDistance 9 }\n"
           "  VolumeData { generator " +
           generator + " dimensions 32 32 32 spacing 0.0625 0.0625 0.0625 }\n" + before +
           "  ShearWarpVolume {\n" + body + "  }\n" + after + "}\n";
}

RenderOptions smallOptions(int size = 64) {
    RenderOptions options;
    options.width = options.height = size;
    return options;
}

} // namespace

TEST_CASE("ShearWarpVolume and VolumeObject fields are written and read back") {
    const ref_ptr<Node> root = readSceneFromString(
        sceneWith("LABELLED", "",
                  "    TransferFunction { tag 1 alpha [ 0 0.5 ] }\n"
                  "    VolumeObject { source TAG tag 1 voxels SURFACE renderMode SHADED "
                  "compositing MIP opacity 0.5 clippedOpacity 0.25 clippedRenderMode CONTOUR }\n"
                  "    VolumeObject { source THRESHOLD threshold 10 200 voxels GRADIENT "
                  "gradientThreshold 0.1 renderMode COLORED_CONTOUR compositing SURFACE "
                  "contourColor 0 1 0 contourSharpness 2 shininess 8 }\n"));
    const std::string text = writeSceneToString(*root);
    const ref_ptr<Node> again = readSceneFromString(text);
    auto* volume = findNode<ShearWarpVolume>(*again);
    REQUIRE(volume);
    REQUIRE(volume->getNumChildren() == 3u);
    auto* first = static_cast<VolumeObject*>(volume->getChild(1));
    auto* second = static_cast<VolumeObject*>(volume->getChild(2));
    CHECK(first->source() == VolumeObject::TAG);
    CHECK(first->voxels() == VolumeObject::SURFACE);
    CHECK(first->renderMode() == VolumeObject::SHADED);
    CHECK(first->compositing() == VolumeObject::MIP);
    CHECK(first->clippedRenderMode() == VolumeObject::CONTOUR);
    CHECK(first->clippedOpacity() == 0.25f);
    CHECK(second->threshold() == glm::vec2(10.0f, 200.0f));
    CHECK(second->compositing() == VolumeObject::SURFACE_HIT);
    CHECK(second->renderMode() == VolumeObject::COLORED_CONTOUR);
    CHECK(second->contourColor() == glm::vec3(0.0f, 1.0f, 0.0f));
    CHECK(text.find("fields [") != std::string::npos); // self-described for other readers
}

TEST_CASE("plain TF DVR and MIP of the node match renderReference") {
    OSMesaContext context;
    Renderer renderer;
    for (const char* compositing : {"DVR", "MIP"}) {
        const ref_ptr<Node> root = readSceneFromString(
            sceneWith("MARSCHNER_LOBB", "",
                      "    Transform { }\n" // ignored: only state nodes and objects count
                      "    TransferFunction { red [ 0 0.1, 0.5 0.9, 1 1 ] green [ 0 0.3, 1 0.9 ] "
                      "blue [ 0 1, 1 0.1 ] alpha [ 0 0, 1 0.2 ] }\n"
                      "    VolumeObject { compositing " +
                          std::string(compositing) + " }\n",
                      ""));
        RenderOptions options = smallOptions();
        options.background = glm::vec3(0.1f, 0.1f, 0.2f);
        const Image image = renderer.render(*root, options);
        RayCastOptions rays;
        rays.tolerance = 1e-3;
        const Image reference = renderReference(*root, options, nullptr, rays);
        const double error = rmse(image, reference);
        MESSAGE(std::string(compositing) << " RMSE versus renderReference: " << error);
        CHECK(error < 0.01); // measured 0.0045 (DVR) and 0.0004 (MIP)
        REQUIRE(collectVolumes(*root).size() == 1u);
    }
}

TEST_CASE("an opaque cube inside the volume hides what is behind and is dimmed in front") {
    OSMesaContext context;
    Renderer renderer;
    // Soft sphere data under a constant transfer function: a homogeneous box [-1, 1]^3 with
    // A = 0.1 per L0 = 1/16. A cube of width 0.5 at the centre: its front face at z = 0.25,
    // 12 voxels behind the box's front face.
    const std::string cube = "  Separator { Material { diffuseColor 0.9 0.6 0.1 } "
                             "Cube { width 0.5 height 0.5 depth 0.5 } }\n";
    const ref_ptr<Node> root = readSceneFromString(
        sceneWith("SOFT_SPHERE", cube,
                  "    TransferFunction { red [ 0 0.2 ] green [ 0 0.4 ] blue [ 0 1 ] "
                  "alpha [ 0 0.1 ] }\n    VolumeObject { }\n"));
    RenderOptions options = smallOptions();
    const Image image = renderer.render(*root, options);
    options.opaqueOnly = true;
    const Image cubeOnly = renderer.render(*root, options);
    const double t = std::pow(0.9, 12.0);
    const glm::vec4 c = image.at(32, 32);
    const glm::vec4 behind = cubeOnly.at(32, 32);
    const double a = 1.0 - t;
    CHECK(c.r == doctest::Approx(0.2 * a + t * behind.r).epsilon(0.01));
    CHECK(c.g == doctest::Approx(0.4 * a + t * behind.g).epsilon(0.01));
    CHECK(c.b == doctest::Approx(1.0 * a + t * behind.b).epsilon(0.01));
    // Beside the cube the whole 32-voxel depth counts.
    const glm::vec4 side = image.at(32, 8);
    CHECK(side.b == doctest::Approx(1.0 - std::pow(0.9, 32.0)).epsilon(0.01));
    options.opaqueOnly = false;
    RayCastOptions rays;
    rays.tolerance = 1e-3;
    const double error = rmse(image, renderReference(*root, smallOptions(), nullptr, rays));
    MESSAGE("RMSE versus renderReference with the cube: " << error);
    CHECK(error < 0.015); // measured 0.0075
}

TEST_CASE("a SURFACE object writes depth and hides a cube behind it") {
    OSMesaContext context;
    Renderer renderer;
    // The ball v >= 0.5 of the soft sphere: radius 0.45 * 32 * 0.5 = 7.2 voxels = 0.45 local.
    const std::string cube = "  Separator { Transform { translation 0 0 -0.8 } "
                             "Material { diffuseColor 1 0 0 } Cube { width 0.3 height 0.3 "
                             "depth 0.3 } }\n";
    const ref_ptr<Node> root = readSceneFromString(sceneWith(
        "SOFT_SPHERE", cube,
        "    TransferFunction { red [ 0 0.2, 1 1 ] green [ 0 0.2, 1 1 ] blue [ 0 0.2, 1 1 ] "
        "alpha [ 0 1 ] }\n"
        "    VolumeObject { source THRESHOLD threshold 128 255 voxels SURFACE renderMode SHADED "
        "compositing SURFACE }\n"));
    const Image image = renderer.render(*root, smallOptions());
    const glm::vec4 c = image.at(32, 32);
    CHECK(c.r == doctest::Approx(c.g).epsilon(0.02)); // the grey ball, not the red cube
    CHECK(c.r > 0.8f);
    // Depth: the ball's front at local z ~ 0.45 (eye z -4.55): window (4.55 - 1) / 8.
    const std::vector<float> depth = renderer.readWindowDepth();
    CHECK(depth[32 * 64 + 32] == doctest::Approx((4.55 - 1.0) / 8.0).epsilon(0.03));
    CHECK(depth[2 * 64 + 2] == 1.0f);
}

TEST_CASE("picking a pixel returns the VolumeObject and the point hit") {
    OSMesaContext context;
    Renderer renderer;
    // Labelled volume: tag 1 is the ball r < 8 voxels, tag 3 the slab k < 8 outside r >= 12.8.
    const ref_ptr<Node> root =
        readSceneFromString(sceneWith("LABELLED", "",
                                      "    TransferFunction { alpha [ 0 0.3 ] }\n"
                                      "    DEF BALL VolumeObject { source TAG tag 1 }\n"
                                      "    DEF SLAB VolumeObject { source TAG tag 3 }\n"));
    renderer.render(*root, smallOptions());
    auto* volume = findNode<ShearWarpVolume>(*root);
    REQUIRE(volume);
    const auto centre = volume->pickAt(32, 32);
    REQUIRE(centre);
    REQUIRE(centre->object);
    CHECK(centre->object->getName() == "BALL");
    CHECK(centre->worldPosition.z > 0.3); // the front of the ball (radius 0.5)
    CHECK(centre->worldPosition.z < 0.55);
    const auto corner = volume->pickAt(8, 56); // (-0.92, -0.96): outside the ball, over the slab
    REQUIRE(corner);
    CHECK(corner->object->getName() == "SLAB");
    CHECK(corner->worldPosition.z < -0.5);
    const auto empty = volume->pickAt(0, 0); // the box's corner: the slab or nothing
    CHECK((!empty || empty->object->getName() == "SLAB"));
}

TEST_CASE("a perspective camera is refused with a clear message") {
    OSMesaContext context;
    Renderer renderer;
    const ref_ptr<Node> root = readSceneFromString(
        "#Inventor V2.1 ascii\nSeparator { PerspectiveCamera { position 0 0 5 }\n"
        "  VolumeData { generator SOFT_SPHERE dimensions 8 8 8 }\n"
        "  ShearWarpVolume { VolumeObject { } } }\n");
    CHECK_THROWS_WITH_AS(renderer.render(*root, smallOptions(16)),
                         doctest::Contains("OrthographicCamera"), Error);
}

TEST_CASE("a Switch browses time steps whose voxel lists stay cached") {
    OSMesaContext context;
    Renderer renderer;
    const ref_ptr<Node> root = readSceneFromString(
        "#Inventor V2.1 ascii\nSeparator {\n"
        "  OrthographicCamera { position 0 0 5 height 2.5 nearDistance 1 farDistance 9 }\n"
        "  DEF STEPS Switch { whichChild 0\n"
        "    VolumeData { generator SOFT_SPHERE dimensions 16 16 16 spacing 0.125 0.125 0.125 }\n"
        "    VolumeData { generator THIN_SHELL dimensions 16 16 16 spacing 0.125 0.125 0.125 }\n"
        "  }\n"
        "  ShearWarpVolume { TransferFunction { alpha [ 0 0, 1 0.5 ] } DEF OBJ VolumeObject { } }\n"
        "}\n");
    auto* steps = findNode<Switch>(*root);
    REQUIRE(steps);
    const Image first = renderer.render(*root, smallOptions(32));
    steps->whichChild = 1;
    const Image second = renderer.render(*root, smallOptions(32));
    CHECK(first.pixels != second.pixels);
    // Back to step 0: the voxel list cached for that grid, the same image.
    steps->whichChild = 0;
    const Image again = renderer.render(*root, smallOptions(32));
    CHECK(again.pixels == first.pixels);
}

TEST_CASE("a transfer function edit keeps the lists and the optimizer keeps the image") {
    OSMesaContext context;
    Renderer renderer;
    const ref_ptr<Node> root = readSceneFromString(
        sceneWith("SOFT_SPHERE", "",
                  "    DEF TF TransferFunction { red [ 0 1 ] green [ 0 0.5 ] blue [ 0 0.2 ] "
                  "alpha [ 0 0.05 ] }\n"
                  // Every voxel of the region (gradient >= 0): a selection the transfer function
                  // does not decide, so editing the function keeps the lists.
                  "    VolumeObject { source THRESHOLD threshold 1 255 voxels GRADIENT "
                  "gradientThreshold 0 }\n"));
    auto* volume = findNode<ShearWarpVolume>(*root);
    auto* tf = findNode<TransferFunction>(*root);
    REQUIRE(volume);
    REQUIRE(tf);
    renderer.render(*root, smallOptions());
    const std::uint64_t touchedAll = volume->lastFrame()->stats.voxelsTouched;
    // Only v >= 0.5 visible now: the same lists, most voxels cannot count any more.
    tf->alpha.setValues({glm::vec2(0.5f, 0.0f), glm::vec2(0.51f, 0.05f)});
    const Image before = renderer.render(*root, smallOptions());
    CHECK(volume->lastFrame()->stats.voxelsTouched == touchedAll); // not optimized yet
    volume->waitForOptimizer();
    const Image after = renderer.render(*root, smallOptions());
    CHECK(after.pixels == before.pixels);
    MESSAGE("voxels read: " << touchedAll << " before optimizing, "
                            << volume->lastFrame()->stats.voxelsTouched << " after");
    CHECK(volume->lastFrame()->stats.voxelsTouched < touchedAll / 2);
}

TEST_CASE("while interacting the node skips slices, lowered further by the viewer's scale") {
    ref_ptr<ShearWarpVolume> node = ShearWarpVolume::create();
    CHECK(node->sliceStepFor(false, 1.0) == 1);
    CHECK(node->sliceStepFor(false, 0.1) == 1); // still frames are full quality
    CHECK(node->sliceStepFor(true, 1.0) == 2);  // the default interactiveSliceStep
    CHECK(node->sliceStepFor(true, 0.5) == 4);
    CHECK(node->sliceStepFor(true, 0.3) == 7); // 2 / 0.3 = 6.67, rounded
    CHECK(node->sliceStepFor(true, 1.0 / 32.0) == 16);
    node->interactiveSliceStep = 1;
    CHECK(node->sliceStepFor(true, 1.0) == 1);
    node->interactiveSliceStep = -5; // nonsense counts as 1
    CHECK(node->sliceStepFor(true, 0.25) == 4);

    OSMesaContext context;
    Renderer renderer;
    const ref_ptr<Node> root = readSceneFromString(
        sceneWith("MARSCHNER_LOBB", "",
                  "    TransferFunction { red [ 0 0.1, 0.5 0.9, 1 1 ] green [ 0 0.3, 1 0.9 ] "
                  "blue [ 0 1, 1 0.1 ] alpha [ 0 0, 1 0.2 ] }\n"
                  "    VolumeObject { }\n"));
    ShearWarpVolume* volume = findNode<ShearWarpVolume>(*root);
    REQUIRE(volume != nullptr);
    volume->optimize = false;
    // Set, so the fixed step applies (left unset, interactiveErrorTarget chooses it).
    volume->interactiveSliceStep = 2;
    RenderOptions options = smallOptions();
    const Image still = renderer.render(*root, options);
    const ShearWarpStats stillStats = volume->lastFrame()->stats;
    options.interactive = true;
    const Image moving = renderer.render(*root, options);
    const ShearWarpStats movingStats = volume->lastFrame()->stats;
    options.interactivePlaneScale = 0.5;
    renderer.render(*root, options);
    const ShearWarpStats slowerStats = volume->lastFrame()->stats;
    options.interactive = false;
    const Image stillAgain = renderer.render(*root, options);

    CHECK(stillStats.sliceStep == 1);
    CHECK(movingStats.sliceStep == 2);
    CHECK(slowerStats.sliceStep == 4);
    CHECK(movingStats.voxelsTouched < stillStats.voxelsTouched * 6 / 10);
    CHECK(slowerStats.voxelsTouched < stillStats.voxelsTouched * 3 / 10);
    const double error = rmse(moving, still);
    MESSAGE("interactive (every second slice) versus still RMSE " << error);
    CHECK(error > 0.0);                       // it did render differently
    CHECK(error < 0.01);                      // and stays close to full quality
    CHECK(stillAgain.pixels == still.pixels); // full quality as soon as the interaction stops
}

TEST_CASE("valueSortedMip chooses the value-sorted or the general MIP path") {
    OSMesaContext context;
    for (const bool sorted : {true, false}) {
        const ref_ptr<Node> root = readSceneFromString(
            sceneWith("MARSCHNER_LOBB", "",
                      std::string("    valueSortedMip ") + (sorted ? "TRUE" : "FALSE") +
                          "\n    TransferFunction { alpha [ 0 0, 1 0.4 ] }\n"
                          "    VolumeObject { compositing MIP }\n"));
        Renderer renderer;
        const RenderOptions options = smallOptions();
        const Image image = renderer.render(*root, options);
        const ShearWarpVolume* volume = findNode<ShearWarpVolume>(*root);
        REQUIRE(volume);
        REQUIRE(volume->lastFrame());
        CHECK(volume->lastFrame()->stats.valueSortedMip == sorted);
        RayCastOptions rays;
        rays.tolerance = 1e-3;
        const double error = rmse(image, renderReference(*root, options, nullptr, rays));
        MESSAGE(std::string(sorted ? "value-sorted" : "general")
                << " MIP RMSE versus renderReference: " << error);
        CHECK(error < 0.01);
    }
}

TEST_CASE("a ShearWarpVolume without VolumeObjects draws the whole volume, as one WHOLE object "
          "does") {
    OSMesaContext context;
    Renderer renderer;
    const std::string tf = "    TransferFunction { alpha [ 0 0, 1 0.5 ] }\n";
    const ref_ptr<Node> bare = readSceneFromString(sceneWith("SOFT_SPHERE", "", tf));
    const ref_ptr<Node> whole =
        readSceneFromString(sceneWith("SOFT_SPHERE", "", tf + "    VolumeObject { }\n"));
    const Image a = renderer.render(*bare, smallOptions());
    const Image b = renderer.render(*whole, smallOptions());
    CHECK(rmse(a, b) == 0.0); // the same object, the same pixels
    // Not blank: the sphere's middle stands out from the corner (the background).
    const glm::vec4 middle = a.at(32, 32), corner = a.at(1, 1);
    CHECK(glm::length(glm::vec3(middle) - glm::vec3(corner)) > 0.2f);
    // And the reference sees it too.
    CHECK(rmse(a, renderReference(*bare, smallOptions())) < 0.03);
}

TEST_CASE("a scene whose ShearWarpVolume has no camera gets an orthographic one") {
    const ref_ptr<Node> root =
        readSceneFromString("#Inventor V2.1 ascii\nSeparator {\n"
                            "  VolumeData { generator SOFT_SPHERE dimensions 16 16 16 }\n"
                            "  ShearWarpVolume { VolumeObject { } }\n}\n");
    const SceneCamera made = findOrMakeCamera(*root, 1.0);
    REQUIRE(made.camera);
    CHECK(made.camera->isA<OrthographicCamera>());
    // It renders (a perspective camera would be an Error), and shows the sphere.
    OSMesaContext context;
    Renderer renderer;
    const Image image = renderer.render(*root, smallOptions(48));
    CHECK(glm::length(glm::vec3(image.at(24, 24)) - glm::vec3(image.at(1, 1))) > 0.2f);
    // Without a ShearWarpVolume a scene keeps the perspective default.
    const ref_ptr<Node> plain = readSceneFromString(
        "#Inventor V2.1 ascii\nSeparator { VolumeData { generator SOFT_SPHERE } Volume { } }\n");
    CHECK(findOrMakeCamera(*plain, 1.0).camera->isA<PerspectiveCamera>());
}
