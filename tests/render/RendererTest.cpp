// The Renderer across frames and contexts: backends agree, caches stay small, GPU work only
// when something changed, blits to the caller's framebuffer, default camera, depth readback.
#include <doctest/doctest.h>

#include <volsg/context/EglContext.h>
#include <volsg/context/OSMesaContext.h>
#include <volsg/core/Error.h>
#include <volsg/gl/Framebuffer.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/gl/Renderbuffer.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/Light.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Sphere.h>
#include <volsg/nodes/Transform.h>
#include <volsg/render/Renderer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

using namespace volsg;

namespace {

ref_ptr<OrthographicCamera> orthoCamera(float height) {
    auto camera = OrthographicCamera::create();
    camera->position = glm::vec3(0.0f, 0.0f, 5.0f);
    camera->height = height;
    camera->nearDistance = 1.0f;
    camera->farDistance = 9.0f;
    return camera;
}

ref_ptr<Transform> translate(glm::vec3 t) {
    auto tr = Transform::create();
    tr->translation = t;
    return tr;
}

/// A lit sphere with specular highlights, a rotated cube and a transparent box, under a
/// perspective camera and a point light: most of the shading paths at once.
ref_ptr<Separator> mixedScene() {
    auto root = Separator::create();
    auto camera = PerspectiveCamera::create();
    camera->position = glm::vec3(0.5f, 1.0f, 6.0f);
    camera->nearDistance = 1.0f;
    camera->farDistance = 20.0f;
    root->addChild(camera);
    auto light = PointLight::create();
    light->location = glm::vec3(3.0f, 4.0f, 5.0f);
    root->addChild(light);
    auto shiny = Material::create();
    shiny->diffuseColor = {glm::vec3(0.7f, 0.3f, 0.2f)};
    shiny->specularColor = {glm::vec3(0.8f)};
    shiny->shininess = {0.4f};
    auto left = Separator::create();
    left->addChild(translate({-1.2f, 0.0f, 0.0f}));
    left->addChild(shiny);
    left->addChild(Sphere::create());
    root->addChild(left);
    auto right = Separator::create();
    auto turn = Transform::create();
    turn->translation = glm::vec3(1.3f, 0.0f, 0.0f);
    turn->rotation = Rotation{glm::vec3(1.0f, 1.0f, 0.0f), 0.7f};
    right->addChild(turn);
    right->addChild(Cube::create());
    root->addChild(right);
    auto glass = Material::create();
    glass->diffuseColor = {glm::vec3(0.2f, 0.4f, 0.9f)};
    glass->transparency = {0.6f};
    auto front = Separator::create();
    front->addChild(translate({0.0f, -0.5f, 2.0f}));
    front->addChild(glass);
    auto box = Cube::create();
    box->width = 3.0f;
    box->height = 1.0f;
    box->depth = 0.5f;
    front->addChild(box);
    root->addChild(front);
    return root;
}

RenderOptions smallOptions(int w = 64, int h = 48) {
    RenderOptions o;
    o.width = w;
    o.height = h;
    o.background = {0.1f, 0.1f, 0.15f};
    return o;
}

int differingPixels(const Image& a, const Image& b) {
    int n = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        n += a.pixels[i] != b.pixels[i];
    return n;
}

} // namespace

TEST_CASE("the EGL backend renders exactly the same pixels as OSMesa") {
    auto scene = mixedScene();
    Image fromOsmesa, fromEgl;
    {
        OSMesaContext context;
        REQUIRE(enableGlErrorChecking());
        Renderer renderer;
        fromOsmesa = renderer.render(*scene, smallOptions());
    }
    {
        EglContext context;
        REQUIRE(enableGlErrorChecking());
        Renderer renderer;
        fromEgl = renderer.render(*scene, smallOptions());
    }
    REQUIRE(fromOsmesa.pixels.size() == fromEgl.pixels.size());
    CHECK(differingPixels(fromOsmesa, fromEgl) == 0);
    // And the scene really drew something: not all background.
    int drawn = 0;
    for (const auto& p : fromOsmesa.pixels)
        drawn += glm::vec3(p) != glm::vec3(0.1f, 0.1f, 0.15f);
    CHECK(drawn > 500);
}

TEST_CASE("a frame where nothing changed uploads no mesh and compiles no shader") {
    OSMesaContext context;
    Renderer renderer;
    auto scene = mixedScene();
    const Image first = renderer.render(*scene, smallOptions());
    const RenderStats after1 = renderer.stats();
    CHECK(after1.programBuilds >= 1); // the shape program's variants this scene needs
    // Sphere, cube, box, and the sphere's 2 coarser tessellations (ShapeDetail.h).
    CHECK(after1.meshUploads == 3 + 2);
    const Image second = renderer.render(*scene, smallOptions());
    CHECK(renderer.stats().meshUploads == after1.meshUploads);
    CHECK(renderer.stats().programBuilds == after1.programBuilds);
    CHECK(renderer.stats().frames == 2);
    CHECK(differingPixels(first, second) == 0);
    // A resized target re-renders the same scene without new meshes either.
    renderer.render(*scene, smallOptions(30, 30));
    CHECK(renderer.stats().meshUploads == after1.meshUploads);
}

TEST_CASE("a changed shape is uploaded again and its old mesh is dropped") {
    OSMesaContext context;
    Renderer renderer;
    auto root = Separator::create();
    root->addChild(orthoCamera(4.0f));
    auto cube = Cube::create();
    root->addChild(cube);
    RenderOptions options = smallOptions(40, 40);
    renderer.render(*root, options);
    CHECK(renderer.stats().meshUploads == 1);
    const std::size_t entries = renderer.stats().cachedEntries; // the mesh, the root's cache
    const std::size_t meshBytes = renderer.stats().meshBytes;
    CHECK(meshBytes > 0);
    cube->width = 1.0f;
    const Image image = renderer.render(*root, options);
    CHECK(renderer.stats().meshUploads == 2);
    CHECK(renderer.stats().cachedEntries == entries); // the old width's mesh is gone
    CHECK(renderer.stats().meshBytes == meshBytes);
    // The new size is what is drawn: 1 unit wide at 10 px per unit.
    int covered = 0;
    for (int x = 0; x < 40; ++x)
        covered += glm::vec3(image.at(x, 20)) != options.background;
    CHECK(std::abs(covered - 10) <= 1);
}

TEST_CASE("a node removed from the scene is released by the renderer after one frame") {
    OSMesaContext context;
    Renderer renderer;
    auto root = Separator::create();
    root->addChild(orthoCamera(4.0f));
    ref_ptr<Cube> cube = Cube::create();
    root->addChild(cube);
    renderer.render(*root, smallOptions(16, 16));
    CHECK(cube->refCount() > 2); // the scene, this test and the renderer's cache
    root->removeChild(1);
    renderer.render(*root, smallOptions(16, 16));
    CHECK(renderer.stats().meshBytes == 0); // the root's render cache remains, empty
    CHECK(cube->refCount() == 1);           // only this test holds it now
}

TEST_CASE("renderToBoundFramebuffer blits the frame into the framebuffer bound before") {
    OSMesaContext context;
    Renderer renderer;
    auto root = Separator::create();
    root->addChild(orthoCamera(2.0f));
    auto material = Material::create();
    material->diffuseColor = {glm::vec3(0.0f)};
    material->ambientColor = {glm::vec3(0.0f)};
    material->emissiveColor = {glm::vec3(0.25f, 0.5f, 0.75f)};
    root->addChild(material);
    auto cube = Cube::create();
    cube->width = 1.0f; // half the view: columns [8, 24) of 32
    root->addChild(cube);

    Renderbuffer color(GL_RGBA8, 32, 32);
    Framebuffer window = Framebuffer::create();
    window.attach(GL_COLOR_ATTACHMENT0, color);
    window.requireComplete("window stand-in");
    window.bind();
    RenderOptions options = smallOptions(32, 32);
    renderer.renderToBoundFramebuffer(*root, options);

    GLint bound = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
    CHECK(GLuint(bound) == window.id()); // the caller's binding is back
    std::array<unsigned char, 4> inside{}, outside{};
    glReadPixels(16, 16, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, inside.data());
    glReadPixels(2, 16, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, outside.data());
    CHECK(int(inside[0]) == 64);
    CHECK(int(inside[1]) == 128);
    CHECK(int(inside[2]) == 191);
    CHECK(int(outside[0]) == 26); // background 0.1 * 255 = 25.5 rounds to 26 (GL rounds to nearest)
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

namespace {

/// Renders `root` into an 8-bit framebuffer standing in for a window, as the viewer does, and
/// returns the window's bytes (RGBA, bottom row first).
std::vector<unsigned char> renderToWindow(Renderer& renderer, Node& root, int size) {
    Renderbuffer color(GL_RGBA8, size, size);
    Framebuffer window = Framebuffer::create();
    window.attach(GL_COLOR_ATTACHMENT0, color);
    window.requireComplete("window stand-in");
    window.bind();
    renderer.renderToBoundFramebuffer(root, smallOptions(size, size));
    std::vector<unsigned char> bytes(std::size_t(size) * std::size_t(size) * 4);
    glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return bytes;
}

/// The largest difference, in 1/255 steps, between the window's bytes and the float image
/// rounded as GL rounds.
int largestStep(const std::vector<unsigned char>& window, const Image& image) {
    int largest = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const int expected =
                    int(std::lround(std::clamp(image.at(x, y)[c], 0.0f, 1.0f) * 255.0f));
                const std::size_t at = (std::size_t(image.height - 1 - y) * image.width + x) * 4;
                largest = std::max(largest, std::abs(int(window[at + std::size_t(c)]) - expected));
            }
    return largest;
}

/// Whether every colour of `image` is a whole number of 1/255 steps (an 8-bit target's).
bool onByteSteps(const Image& image) {
    for (const glm::vec4& p : image.pixels)
        for (int c = 0; c < 3; ++c)
            if (std::abs(p[c] * 255.0f - std::round(p[c] * 255.0f)) > 1e-3f) return false;
    return true;
}

} // namespace

TEST_CASE("a window frame without volumes is drawn in 8 bits, one with a volume in float") {
    OSMesaContext context;
    enableGlErrorChecking();
    Renderer renderer;
    constexpr int size = 48;
    // Lit, specular and transparent shapes: the 8-bit frame agrees with the float one rounded
    // (a transparent blend rounds its result once more: one step at most). The colours stay
    // within [0, 1]: beyond it the float target would carry what a window's clamps (as Coin's).
    ref_ptr<Node> shapes = readSceneFromString(
        "#Inventor V2.1 ascii\nSeparator { PerspectiveCamera { position 0 0 6 }\n"
        "  Material { diffuseColor 0.5 0.3 0.2 specularColor 0.4 0.4 0.4 shininess 0.3 }\n"
        "  Sphere { }\n"
        "  Material { diffuseColor 0.2 0.5 0.9 transparency 0.4 }\n"
        "  Translation { translation 0.5 0.3 1.2 } Cube { width 1.2 height 1 depth 0.3 } }\n");
    const std::vector<unsigned char> window = renderToWindow(renderer, *shapes, size);
    CHECK(onByteSteps(renderer.readImage())); // the 8-bit target
    const Image exact = renderer.render(*shapes, smallOptions(size, size));
    CHECK(!onByteSteps(exact)); // render() reads float pixels: the float target
    CHECK(largestStep(window, exact) <= 1);

    // A volume needs float accumulation: its window frame starts again on the float target.
    ref_ptr<Node> volume = readSceneFromString(
        "#Inventor V2.1 ascii\nSeparator { OrthographicCamera { position 0 0 5 height 2.4 }\n"
        "  VolumeData { generator SOFT_SPHERE dimensions 32 32 32 "
        "spacing 0.0625 0.0625 0.0625 }\n"
        "  TransferFunction { alpha [ 0 0, 1 0.05 ] }\n"
        "  Volume { numPlanes 256 }\n"
        "  Material { diffuseColor 0 0 0 ambientColor 0 0 0 emissiveColor 1 0.5 0 }\n"
        "  Translation { translation 0 0 -2 } Cube { width 0.5 height 0.5 depth 0.5 } }\n");
    const std::vector<unsigned char> volumeWindow = renderToWindow(renderer, *volume, size);
    CHECK(!onByteSteps(renderer.readImage()));
    const Image volumeExact = renderer.render(*volume, smallOptions(size, size));
    CHECK(largestStep(volumeWindow, volumeExact) <= 1);
    // And it is back on 8 bits when the volume is gone.
    renderToWindow(renderer, *shapes, size);
    renderToWindow(renderer, *shapes, size);
    CHECK(onByteSteps(renderer.readImage()));
}

TEST_CASE("without a camera the scene is seen whole from +Z") {
    OSMesaContext context;
    Renderer renderer;
    auto root = Separator::create();
    root->addChild(translate({10.0f, -3.0f, 0.0f})); // far from the origin
    root->addChild(Sphere::create());
    RenderOptions options = smallOptions(48, 48);
    const Image image = renderer.render(*root, options);
    CHECK(glm::vec3(image.at(24, 24)) != options.background); // centred
    CHECK(glm::vec3(image.at(0, 0)) == options.background);   // and inside the view
    CHECK(glm::vec3(image.at(47, 47)) == options.background);
    const SceneCamera scene = findOrMakeCamera(*root, 1.0);
    REQUIRE(scene.camera);
    CHECK(scene.camera->isA<PerspectiveCamera>());
    CHECK(scene.camera->position().x == doctest::Approx(10.0));
    CHECK(scene.camera->position().y == doctest::Approx(-3.0));
    CHECK(scene.camera->position().z > 1.0f);
}

TEST_CASE("findOrMakeCamera returns the first camera with the transform above it") {
    auto root = Separator::create();
    auto inner = Separator::create();
    inner->addChild(translate({0.0f, 2.0f, 0.0f}));
    auto first = PerspectiveCamera::create();
    inner->addChild(first);
    root->addChild(inner);
    root->addChild(orthoCamera(2.0f)); // second: ignored
    const SceneCamera scene = findOrMakeCamera(*root, 1.0);
    CHECK(scene.camera.get() == first.get());
    CHECK(scene.model[3][1] == doctest::Approx(2.0));
}

TEST_CASE("readWindowDepth gives the depth of the nearest opaque surface") {
    OSMesaContext context;
    Renderer renderer;
    auto root = Separator::create();
    root->addChild(orthoCamera(4.0f)); // near 1, far 9 from z = 5: depth = (5 - z - 1) / 8
    auto cube = Cube::create();
    cube->width = 2.0f;
    root->addChild(translate({1.0f, 0.0f, 0.0f}));
    root->addChild(cube);                         // front face at z = 1
    RenderOptions options = smallOptions(40, 20); // 4 high, 8 wide: 5 px per unit
    renderer.render(*root, options);
    const std::vector<float> depth = renderer.readWindowDepth();
    REQUIRE(depth.size() == 800u);
    CHECK(depth[10 * 40 + 25] == doctest::Approx(3.0 / 8.0).epsilon(1e-6)); // on the cube
    CHECK(depth[10 * 40 + 5] == 1.0f);                                      // background
}

TEST_CASE("opaqueOnly leaves transparent shapes out") {
    OSMesaContext context;
    Renderer renderer;
    auto root = Separator::create();
    root->addChild(orthoCamera(4.0f));
    auto glass = Material::create();
    glass->transparency = {0.5f};
    root->addChild(glass);
    root->addChild(Cube::create());
    RenderOptions options = smallOptions(16, 16);
    CHECK(glm::vec3(renderer.render(*root, options).at(8, 8)) != options.background);
    options.opaqueOnly = true;
    CHECK(glm::vec3(renderer.render(*root, options).at(8, 8)) == options.background);
}

TEST_CASE("two contexts with a renderer each render the same image alternately") {
    auto scene = mixedScene();
    OSMesaContext a;
    Renderer inA;
    OSMesaContext b;
    Renderer inB;
    const Image fromB = inB.render(*scene, smallOptions());
    a.makeCurrent();
    const Image fromA = inA.render(*scene, smallOptions());
    b.makeCurrent();
    const Image fromBAgain = inB.render(*scene, smallOptions());
    CHECK(differingPixels(fromA, fromB) == 0);
    CHECK(differingPixels(fromB, fromBAgain) == 0);
}

TEST_CASE("an empty render size throws an Error") {
    OSMesaContext context;
    Renderer renderer;
    auto root = Separator::create();
    CHECK_THROWS_WITH_AS(renderer.render(*root, smallOptions(0, 10)), doctest::Contains("empty"),
                         Error);
}

TEST_CASE("render into a caller's image reads the frame top row first, reusing or resizing it") {
    OSMesaContext context;
    Renderer renderer;
    auto root = Separator::create();
    root->addChild(orthoCamera(2.0f));
    auto material = Material::create();
    material->diffuseColor = {glm::vec3(0.0f)};
    material->ambientColor = {glm::vec3(0.0f)};
    material->emissiveColor = {glm::vec3(0.25f, 0.5f, 0.75f)};
    root->addChild(material);
    auto translation = Transform::create();
    translation->translation = glm::vec3(0.0f, 0.5f, 0.0f); // the cube in the top half
    root->addChild(translation);
    auto cube = Cube::create();
    cube->width = 1.0f;
    cube->height = 1.0f;
    root->addChild(cube);
    const RenderOptions options = smallOptions(32, 24);
    const Image fresh = renderer.render(*root, options);
    // The cube covers the top half: rows [0, 12) of 24 (y in [0, 1] of a view from -1 to 1).
    CHECK(fresh.at(16, 4).r == doctest::Approx(0.25f));
    CHECK(fresh.at(16, 20).r != doctest::Approx(0.25f));
    for (const Image& start :
         {Image(32, 24, glm::vec4(7.0f)), Image(5, 3, glm::vec4(7.0f)), Image()}) {
        Image into = start;
        renderer.render(*root, options, into);
        CHECK(into.width == 32);
        CHECK(into.height == 24);
        CHECK(into.pixels == fresh.pixels); // every pixel overwritten, same orientation
    }
}
