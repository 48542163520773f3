// Separators' render caches and the batched opaque draws change no pixel: every example scene
// and every inventor-data model draw the same with caching on and off (within 1/255),
// and an edit under a cached Separator, above it, in a USEd node and in a Switch's whichChild
// shows in the very next frame. Picking and bounding boxes do not see the caches.
#include <doctest/doctest.h>

#include "support/ImageDifference.h"

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/actions/PickAction.h>
#include <volsg/context/OSMesaContext.h>
#include <volsg/core/Error.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Switch.h>
#include <volsg/nodes/Transform.h>
#include <volsg/render/Renderer.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

using namespace volsg;
using volsg::test::maxDifference;

namespace {

struct Offscreen {
    OSMesaContext context;
    bool errorChecking = enableGlErrorChecking();
    Renderer cached;   ///< caching and batching on (the defaults)
    Renderer uncached; ///< render caches off
};

RenderOptions options(int size, bool caching) {
    RenderOptions o;
    o.width = o.height = size;
    o.debug.renderCaching = caching;
    return o;
}

constexpr float kOneStep = 1.0f / 255.0f + 1e-6f;

/// Renders `root` three times with caching (records, then replays) and once without; the
/// replayed frame must match the uncached one. Returns the shapes replayed from caches.
std::size_t checkCachedMatchesUncached(Offscreen& gl, Node& root, const std::string& what) {
    gl.cached.render(root, options(96, true));
    gl.cached.render(root, options(96, true));
    const Image cached = gl.cached.render(root, options(96, true));
    const Image uncached = gl.uncached.render(root, options(96, false));
    INFO(what);
    CHECK(maxDifference(cached, uncached) <= kOneStep);
    return gl.cached.stats().replayedShapes;
}

ref_ptr<OrthographicCamera> camera() {
    auto c = OrthographicCamera::create();
    c->position = glm::vec3(0.0f, 0.0f, 5.0f);
    c->height = 4.0f;
    c->nearDistance = 1.0f;
    c->farDistance = 10.0f;
    return c;
}

ref_ptr<Material> emissive(glm::vec3 color) {
    auto m = Material::create();
    m->diffuseColor = {glm::vec3(0.0f)};
    m->ambientColor = {glm::vec3(0.0f)};
    m->emissiveColor = {color};
    return m;
}

/// Separator { Transform (x) Cube } with its transform.
ref_ptr<Separator> cubeAt(float x, ref_ptr<Transform>* transform = nullptr,
                          ref_ptr<Node> material = nullptr) {
    auto s = Separator::create();
    auto t = Transform::create();
    t->translation = glm::vec3(x, 0.0f, 0.0f);
    s->addChild(t);
    if (material) s->addChild(material);
    s->addChild(Cube::create());
    if (transform) *transform = t;
    return s;
}

glm::vec3 centre(const Image& image, int x) {
    return glm::vec3(image.at(x, image.height / 2));
}

/// Renders with caching and checks the pixel at column x has `expected` (and that the uncached
/// render agrees everywhere).
void expectNextFrame(Offscreen& gl, Node& root, int x, glm::vec3 expected) {
    const Image cached = gl.cached.render(root, options(96, true));
    const Image uncached = gl.uncached.render(root, options(96, false));
    const glm::vec3 got = centre(cached, x);
    INFO("pixel " << got.r << " " << got.g << " " << got.b);
    CHECK(glm::all(glm::lessThanEqual(glm::abs(got - expected), glm::vec3(kOneStep))));
    CHECK(maxDifference(cached, uncached) <= kOneStep);
}

} // namespace

TEST_CASE("every example scene draws the same with render caches on and off") {
    Offscreen gl;
    int scenes = 0;
    std::size_t replayed = 0;
    for (const auto& e :
         std::filesystem::directory_iterator(std::string(VOLSG_SOURCE_DIR) + "/examples")) {
        if (e.path().extension() != ".iv") continue;
        ref_ptr<Node> root = readScene(e.path().string());
        replayed += checkCachedMatchesUncached(gl, *root, e.path().filename().string());
        ++scenes;
    }
    CHECK(scenes >= 5);
    CHECK(replayed > 0); // the caches were used, not only made
}

TEST_CASE("every inventor-data model draws the same with render caches on and off") {
    const std::filesystem::path models = "/usr/share/inventor/data/models";
    if (!std::filesystem::exists(models)) return; // inventor-data is not installed
    Offscreen gl;
    std::size_t replayed = 0;
    int drawn = 0;
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(models))
        if (e.path().extension() == ".iv") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    int unreadable = 0; // chesschairs.iv's File nodes name paths that are not installed
    for (const std::filesystem::path& file : files) {
        try {
            ref_ptr<Node> root = readScene(file.string());
            replayed += checkCachedMatchesUncached(gl, *root, file.string());
            ++drawn;
        } catch (const Error& e) {
            MESSAGE(std::string(e.what()));
            ++unreadable;
        }
    }
    CHECK(drawn >= 90);
    CHECK(unreadable <= 1);
    CHECK(replayed > 0);
}

TEST_CASE("an edit under a cached Separator shows in the next frame") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(camera());
    auto material = emissive({1.0f, 0.0f, 0.0f});
    ref_ptr<Transform> transform;
    root->addChild(cubeAt(0.0f, &transform, material));
    for (int i = 0; i < 3; ++i)
        gl.cached.render(*root, options(96, true));
    CHECK(gl.cached.stats().replayedShapes == 1);
    material->emissiveColor = {glm::vec3(0.0f, 1.0f, 0.0f)};
    expectNextFrame(gl, *root, 48, {0.0f, 1.0f, 0.0f});
    transform->translation = glm::vec3(1.5f, 0.0f, 0.0f); // the cube leaves the centre
    expectNextFrame(gl, *root, 48, {0.0f, 0.0f, 0.0f});
}

TEST_CASE("an edit above a cached Separator shows in the next frame") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(camera());
    auto material = emissive({1.0f, 0.0f, 0.0f});
    auto move = Transform::create();
    root->addChild(material);
    root->addChild(move);
    root->addChild(cubeAt(0.0f));
    for (int i = 0; i < 3; ++i)
        gl.cached.render(*root, options(96, true));
    CHECK(gl.cached.stats().replayedShapes == 1);
    material->emissiveColor = {glm::vec3(0.0f, 0.0f, 1.0f)};
    expectNextFrame(gl, *root, 48, {0.0f, 0.0f, 1.0f});
    move->translation = glm::vec3(-1.5f, 0.0f, 0.0f);
    expectNextFrame(gl, *root, 48, {0.0f, 0.0f, 0.0f});
    expectNextFrame(gl, *root, 12, {0.0f, 0.0f, 1.0f}); // x = -1.5 is column 12
}

TEST_CASE("an edit of a USEd node shows everywhere it is used in the next frame") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(camera());
    auto shared = emissive({1.0f, 0.0f, 0.0f});
    root->addChild(cubeAt(-1.0f, nullptr, shared));
    root->addChild(cubeAt(1.0f, nullptr, shared));
    for (int i = 0; i < 3; ++i)
        gl.cached.render(*root, options(96, true));
    CHECK(gl.cached.stats().replayedShapes == 2);
    shared->emissiveColor = {glm::vec3(1.0f, 1.0f, 0.0f)};
    expectNextFrame(gl, *root, 24, {1.0f, 1.0f, 0.0f}); // x = -1
    expectNextFrame(gl, *root, 72, {1.0f, 1.0f, 0.0f}); // x = +1
}

TEST_CASE("a Switch's whichChild under a cached Separator shows in the next frame") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(camera());
    auto inner = Separator::create();
    auto choice = Switch::create();
    choice->addChild(emissive({1.0f, 0.0f, 0.0f}));
    choice->addChild(emissive({0.0f, 1.0f, 0.0f}));
    choice->whichChild = 0;
    inner->addChild(choice);
    inner->addChild(Cube::create());
    root->addChild(inner);
    for (int i = 0; i < 3; ++i)
        gl.cached.render(*root, options(96, true));
    CHECK(gl.cached.stats().replayedShapes == 1);
    choice->whichChild = 1;
    expectNextFrame(gl, *root, 48, {0.0f, 1.0f, 0.0f});
    choice->whichChild = 0;
    expectNextFrame(gl, *root, 48, {1.0f, 0.0f, 0.0f});
}

TEST_CASE("picking and bounding boxes see edits the render caches have not drawn yet") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(camera());
    ref_ptr<Transform> transform;
    root->addChild(cubeAt(0.0f, &transform, emissive({1.0f, 1.0f, 1.0f})));
    for (int i = 0; i < 3; ++i)
        gl.cached.render(*root, options(96, true));
    transform->translation = glm::vec3(1.5f, 0.0f, 0.0f);
    const Box3 box = computeBoundingBox(*root);
    CHECK(box.min.x == doctest::Approx(0.5));
    CHECK(box.max.x == doctest::Approx(2.5));
    PickAction pick;
    pick.setPixel(48.0, 48.0, 96, 96); // the centre: the cube has left it
    pick.apply(*root);
    CHECK_FALSE(pick.picked().has_value());
    pick.setPixel(84.0, 48.0, 96, 96); // x = 1.5
    pick.apply(*root);
    REQUIRE(pick.picked().has_value());
    CHECK(pick.picked()->point.x == doctest::Approx(1.5).epsilon(0.05));
}

TEST_CASE("a cached Separator outside the view is not drawn and the image is unchanged") {
    // The camera sees x and y in [-2, 2]: a cube at x = 10 is outside, one at x = 2.5 (1.5 to
    // 3.5) crosses the right edge and is drawn.
    Offscreen gl;
    auto root = Separator::create();
    // The root replays as a whole when it caches (and is culled only as a whole): the three
    // Separators below keep their own caches here.
    root->renderCaching.setValue(Separator::OFF);
    root->addChild(camera());
    root->addChild(cubeAt(0.0f, nullptr, emissive({1.0f, 0.0f, 0.0f})));
    auto far = cubeAt(10.0f, nullptr, emissive({0.0f, 1.0f, 0.0f}));
    root->addChild(far);
    root->addChild(cubeAt(2.5f, nullptr, emissive({0.0f, 0.0f, 1.0f})));
    Image culled;
    for (int i = 0; i < 3; ++i)
        culled = gl.cached.render(*root, options(96, true));
    CHECK(gl.cached.stats().culledSeparators == 1);
    CHECK(gl.cached.stats().replayedShapes == 2);
    CHECK(gl.cached.stats().batchedShapes == 2); // the far cube was not drawn
    const Image uncached = gl.uncached.render(*root, options(96, false));
    CHECK(gl.uncached.stats().culledSeparators == 0);
    CHECK(maxDifference(culled, uncached) <= kOneStep);
    CHECK(glm::all(glm::lessThanEqual(glm::abs(centre(culled, 48) - glm::vec3(1.0f, 0.0f, 0.0f)),
                                      glm::vec3(kOneStep))));
    CHECK(glm::all(glm::lessThanEqual(glm::abs(centre(culled, 90) - glm::vec3(0.0f, 0.0f, 1.0f)),
                                      glm::vec3(kOneStep)))); // x = 1.77

    far->renderCulling.setValue(Separator::OFF); // an edit: records, then replays unculled
    for (int i = 0; i < 3; ++i)
        gl.cached.render(*root, options(96, true));
    CHECK(gl.cached.stats().culledSeparators == 0);
    CHECK(gl.cached.stats().batchedShapes == 3);
}
