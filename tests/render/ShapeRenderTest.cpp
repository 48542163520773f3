// What the shape render pipeline draws, against analytic expectations: coverage, colours,
// state scoping, clip planes, switches, instancing, Lambert shading and blending.
#include <doctest/doctest.h>

#include "support/Offscreen.h"

#include <volsg/context/OSMesaContext.h>
#include <volsg/core/Error.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/image/Image.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/Complexity.h>
#include <volsg/nodes/Coordinate3.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/IndexedFaceSet.h>
#include <volsg/nodes/IndexedLineSet.h>
#include <volsg/nodes/Light.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Shape.h>
#include <volsg/nodes/Sphere.h>
#include <volsg/nodes/Switch.h>
#include <volsg/nodes/Transform.h>
#include <volsg/render/Renderer.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

using namespace volsg;

namespace {

using volsg::test::Offscreen;

/// Looks down -Z from z = 5; `height` world units span the image height when it is the
/// narrower side.
ref_ptr<OrthographicCamera> orthoCamera(float height) {
    auto camera = OrthographicCamera::create();
    camera->position = glm::vec3(0.0f, 0.0f, 5.0f);
    camera->height = height;
    camera->nearDistance = 1.0f;
    camera->farDistance = 10.0f;
    return camera;
}

ref_ptr<Material> emissive(glm::vec3 color, float transparency = 0.0f) {
    auto m = Material::create();
    m->diffuseColor = {glm::vec3(0.0f)};
    m->ambientColor = {glm::vec3(0.0f)};
    m->emissiveColor = {color};
    m->transparency = {transparency};
    return m;
}

ref_ptr<Transform> translate(glm::vec3 t) {
    auto tr = Transform::create();
    tr->translation = t;
    return tr;
}

ref_ptr<Cube> cube(float w, float h, float d) {
    auto c = Cube::create();
    c->width = w;
    c->height = h;
    c->depth = d;
    return c;
}

/// The smallest rectangle of pixels that differ from `background` (min x, min y, max x, max y),
/// or {-1,-1,-1,-1} when none do.
glm::ivec4 coveredRect(const Image& image, glm::vec3 background) {
    glm::ivec4 r(-1);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (glm::vec3(image.at(x, y)) == background) continue;
            if (r.x < 0) r = {x, y, x, y};
            r = {std::min(r.x, x), std::min(r.y, y), std::max(r.z, x), std::max(r.w, y)};
        }
    return r;
}

/// The pixel whose centre is nearest to world (x, y) under an orthographic camera at the
/// origin seeing `height` units across `pixels` rows of a square image.
glm::ivec2 pixelAt(double x, double y, double height, int pixels) {
    const double perUnit = pixels / height;
    return {int(std::floor((x + height / 2) * perUnit)),
            int(std::floor((height / 2 - y) * perUnit))};
}

bool isBackground(const Image& image, glm::ivec2 p) {
    return glm::vec3(image.at(p.x, p.y)) == glm::vec3(0.0f);
}

/// A triangle with per-vertex colours and no normals, for what built-in shapes never make.
class ColoredTriangle : public Inherit<Shape, ColoredTriangle> {
public:
    static constexpr const char* typeName = "ColoredTriangle";
    glm::vec4 color{1.0f};

protected:
    ~ColoredTriangle() override = default;
    void buildMesh(const State&, Mesh& out) const override {
        out = Mesh{};
        out.positions = {{-3, -3, 0}, {3, -3, 0}, {0, 3, 0}};
        out.colors = {color, color, color};
        out.indices = {0, 1, 2};
    }
};

} // namespace

TEST_CASE("a cube under a known OrthographicCamera covers the expected pixel rectangle") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(orthoCamera(4.0f)); // 100x80: 4 units high, 5 wide, 20 px per unit
    root->addChild(translate({0.5f, 0.25f, 0.0f}));
    root->addChild(cube(2.0f, 1.0f, 1.0f));
    RenderOptions options;
    options.width = 100;
    options.height = 80;
    const Image image = gl.renderer.render(*root, options);
    // x in [-0.5, 1.5] -> columns (x + 2.5) * 20 = [40, 80); y in [-0.25, 0.75] -> rows
    // (2 - y) * 20 = [25, 45).
    const glm::ivec4 r = coveredRect(image, glm::vec3(0.0f));
    CHECK(std::abs(r.x - 40) <= 1);
    CHECK(std::abs(r.z - 79) <= 1);
    CHECK(std::abs(r.y - 25) <= 1);
    CHECK(std::abs(r.w - 44) <= 1);
}

TEST_CASE("a cube under a PerspectiveCamera covers the projected rectangle") {
    Offscreen gl;
    auto root = Separator::create();
    auto camera = PerspectiveCamera::create();
    camera->position = glm::vec3(0.0f, 0.0f, 5.0f);
    camera->heightAngle = float(std::numbers::pi / 2); // tan(45 deg) = 1
    camera->nearDistance = 1.0f;
    camera->farDistance = 20.0f;
    root->addChild(camera);
    root->addChild(cube(2.0f, 2.0f, 2.0f));
    RenderOptions options;
    options.width = 120;
    options.height = 120;
    const Image image = gl.renderer.render(*root, options);
    // The front face at z = 1 is 4 units away; the view there is 2 * 4 * tan(45) = 8 units
    // high, so the face's 2 units cover 120 * 2 / 8 = 30 pixels, centred: [45, 75).
    const glm::ivec4 r = coveredRect(image, glm::vec3(0.0f));
    CHECK(std::abs(r.x - 45) <= 1);
    CHECK(std::abs(r.z - 74) <= 1);
    CHECK(std::abs(r.y - 45) <= 1);
    CHECK(std::abs(r.w - 74) <= 1);
}

TEST_CASE("an emissive Material's colour reaches the pixels exactly") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(orthoCamera(4.0f));
    root->addChild(emissive({0.25f, 0.5f, 0.75f}));
    root->addChild(cube(2.0f, 2.0f, 2.0f));
    RenderOptions options;
    options.width = 32;
    options.height = 32;
    const Image image = gl.renderer.render(*root, options);
    const glm::vec4 centre = image.at(16, 16);
    CHECK(std::abs(centre.r - 0.25f) <= 1e-6f);
    CHECK(std::abs(centre.g - 0.5f) <= 1e-6f);
    CHECK(std::abs(centre.b - 0.75f) <= 1e-6f);
    CHECK(centre.a == 1.0f);

    const std::filesystem::path dir =
        std::filesystem::path(VOLSG_BINARY_DIR) / "test-output" / "render";
    std::filesystem::create_directories(dir);
    const std::string png = (dir / "emissive.png").string();
    writePng(png, image);
    const glm::vec4 back = readPng(png).at(16, 16) * 255.0f;
    CHECK(std::lround(back.r) == 64);
    CHECK(std::lround(back.g) == 128);
    CHECK(std::lround(back.b) == 191);
}

TEST_CASE("a Separator scopes its Transform and Material") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(orthoCamera(8.0f));
    auto inner = Separator::create();
    inner->addChild(translate({-2.5f, 0.0f, 0.0f}));
    inner->addChild(emissive({1.0f, 0.0f, 0.0f}));
    inner->addChild(cube(2.0f, 2.0f, 2.0f));
    root->addChild(inner);
    root->addChild(cube(2.0f, 2.0f, 2.0f)); // at the origin, default material, headlight
    RenderOptions options;
    options.width = 80;
    options.height = 80;
    const Image image = gl.renderer.render(*root, options);
    const glm::ivec2 left = pixelAt(-2.5, 0.0, 8.0, 80), centre = pixelAt(0.0, 0.0, 8.0, 80);
    CHECK(glm::vec3(image.at(left.x, left.y)) == glm::vec3(1.0f, 0.0f, 0.0f));
    // Default material under the headlight, front face: 0.2 * 0.2 + 0.8 * 1.
    const glm::vec4 c = image.at(centre.x, centre.y);
    CHECK(std::abs(c.r - 0.84f) <= 1e-5f);
    CHECK(std::abs(c.g - 0.84f) <= 1e-5f);
    CHECK(std::abs(c.b - 0.84f) <= 1e-5f);
    // The translation did not leak either: nothing between the two cubes or right of them.
    CHECK(isBackground(image, pixelAt(-1.25, 0.0, 8.0, 80)));
    CHECK(isBackground(image, pixelAt(2.0, 0.0, 8.0, 80)));
}

TEST_CASE("a ClipPlane removes the expected half of a cube") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(orthoCamera(4.0f));
    root->addChild(emissive({1.0f, 1.0f, 1.0f}));
    auto clip = ClipPlane::create();
    clip->plane = Plane{glm::vec3(1.0f, 0.0f, 0.0f), 0.5f}; // keep x >= 0.5 (local)
    root->addChild(translate({-1.0f, 0.0f, 0.0f}));         // so x >= -0.5 in the world
    root->addChild(clip);
    root->addChild(translate({1.0f, 0.0f, 0.0f}));
    root->addChild(cube(2.0f, 2.0f, 2.0f));
    RenderOptions options;
    options.width = 80;
    options.height = 80;
    const Image image = gl.renderer.render(*root, options);
    // Cube x in [-1, 1] kept for x >= -0.5: columns (x + 2) * 20 = [30, 60).
    const glm::ivec4 r = coveredRect(image, glm::vec3(0.0f));
    CHECK(std::abs(r.x - 30) <= 1);
    CHECK(std::abs(r.z - 59) <= 1);
    CHECK(std::abs(r.y - 20) <= 1);
    CHECK(std::abs(r.w - 59) <= 1);

    clip->on = false; // an inactive plane clips nothing
    const glm::ivec4 all = coveredRect(gl.renderer.render(*root, options), glm::vec3(0.0f));
    CHECK(std::abs(all.x - 20) <= 1);
}

TEST_CASE("six clip planes at once cut a sphere to the analytic region") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(orthoCamera(3.0f));
    root->addChild(emissive({1.0f, 1.0f, 1.0f}));
    auto addPlane = [&](glm::vec3 n, float d) {
        auto clip = ClipPlane::create();
        clip->plane = Plane{n, d};
        root->addChild(clip);
    };
    addPlane({1, 0, 0}, -0.5f);       // x >= -0.5
    addPlane({-1, 0, 0}, -0.5f);      // x <= 0.5
    addPlane({0, 1, 0}, -0.25f);      // y >= -0.25
    addPlane({0, -1, 0}, -0.25f);     // y <= 0.25
    addPlane({0, 0, -1}, -0.9f);      // z <= 0.9: the front cap r < sqrt(0.19) is gone
    addPlane({0, 0, 1}, -0.95f);      // z >= -0.95: the back cap r < sqrt(0.0975) is gone
    auto fine = Complexity::create(); // Coin's finest sphere (30 x 29): close to the true one
    fine->value = 1.0f;
    root->addChild(fine);
    auto sphere = Sphere::create();
    root->addChild(sphere);
    RenderOptions options;
    options.width = 150;
    options.height = 150;
    const Image image = gl.renderer.render(*root, options);
    auto at = [&](double x, double y) { return pixelAt(x, y, 3.0, 150); };
    CHECK(isBackground(image, at(0.0, 0.0)));        // both caps removed: see through
    CHECK(isBackground(image, at(0.2, 0.1)));        // r = 0.22 < 0.31
    CHECK_FALSE(isBackground(image, at(0.38, 0.0))); // back surface seen from inside
    CHECK_FALSE(isBackground(image, at(-0.38, 0.0)));
    CHECK_FALSE(isBackground(image, at(0.47, 0.0))); // front surface
    CHECK_FALSE(isBackground(image, at(0.47, 0.2)));
    CHECK(isBackground(image, at(0.6, 0.0))); // x planes
    CHECK(isBackground(image, at(-0.6, 0.0)));
    CHECK(isBackground(image, at(0.45, 0.3))); // y planes
    CHECK(isBackground(image, at(0.45, -0.3)));
    const glm::ivec4 r = coveredRect(image, glm::vec3(0.0f));
    // x in [-0.5, 0.5] -> columns [50, 100); y in [-0.25, 0.25] -> rows [62.5, 87.5).
    CHECK(std::abs(r.x - 50) <= 1);
    CHECK(std::abs(r.z - 99) <= 1);
    CHECK(std::abs(r.y - 63) <= 1);
    CHECK(std::abs(r.w - 87) <= 1);
}

TEST_CASE("more ClipPlanes in scope than GL clip distances throw a clear Error") {
    Offscreen gl;
    auto root = Separator::create();
    for (int i = 0; i < 9; ++i) {
        auto clip = ClipPlane::create();
        clip->plane = Plane{glm::vec3(1.0f, 0.0f, 0.0f), -10.0f - float(i)};
        root->addChild(clip);
    }
    root->addChild(cube(1.0f, 1.0f, 1.0f));
    RenderOptions options;
    options.width = 8;
    options.height = 8;
    CHECK_THROWS_WITH_AS(gl.renderer.render(*root, options),
                         doctest::Contains("GL_MAX_CLIP_DISTANCES"), Error);
    // The renderer is still usable afterwards.
    root->removeAllChildren();
    root->addChild(cube(1.0f, 1.0f, 1.0f));
    CHECK_NOTHROW(gl.renderer.render(*root, options));
}

TEST_CASE("a Switch selects which shape shows") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(orthoCamera(8.0f));
    auto sw = Switch::create();
    auto left = Separator::create();
    left->addChild(translate({-2.0f, 0.0f, 0.0f}));
    left->addChild(emissive({1.0f, 0.0f, 0.0f}));
    left->addChild(cube(2.0f, 2.0f, 2.0f));
    auto right = Separator::create();
    right->addChild(translate({2.0f, 0.0f, 0.0f}));
    right->addChild(emissive({0.0f, 1.0f, 0.0f}));
    right->addChild(cube(2.0f, 2.0f, 2.0f));
    sw->addChild(left);
    sw->addChild(right);
    root->addChild(sw);
    RenderOptions options;
    options.width = 80;
    options.height = 80;
    const glm::ivec2 l = pixelAt(-2.0, 0.0, 8.0, 80), r = pixelAt(2.0, 0.0, 8.0, 80);

    sw->whichChild = 1;
    Image image = gl.renderer.render(*root, options);
    CHECK(isBackground(image, l));
    CHECK(glm::vec3(image.at(r.x, r.y)) == glm::vec3(0.0f, 1.0f, 0.0f));

    sw->whichChild = 0;
    image = gl.renderer.render(*root, options);
    CHECK(glm::vec3(image.at(l.x, l.y)) == glm::vec3(1.0f, 0.0f, 0.0f));
    CHECK(isBackground(image, r));

    sw->whichChild = Switch::SWITCH_NONE;
    image = gl.renderer.render(*root, options);
    CHECK(coveredRect(image, glm::vec3(0.0f)) == glm::ivec4(-1));

    sw->whichChild = Switch::SWITCH_ALL;
    image = gl.renderer.render(*root, options);
    CHECK_FALSE(isBackground(image, l));
    CHECK_FALSE(isBackground(image, r));
}

TEST_CASE("the same node added twice under two Transforms draws twice") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(orthoCamera(8.0f));
    root->addChild(emissive({0.0f, 0.0f, 1.0f}));
    auto shared = cube(2.0f, 2.0f, 2.0f);
    for (float x : {-2.0f, 2.0f}) {
        auto s = Separator::create();
        s->addChild(translate({x, 0.0f, 0.0f}));
        s->addChild(shared);
        root->addChild(s);
    }
    RenderOptions options;
    options.width = 80;
    options.height = 80;
    const Image image = gl.renderer.render(*root, options);
    for (double x : {-2.0, 2.0}) {
        const glm::ivec2 p = pixelAt(x, 0.0, 8.0, 80);
        CHECK(glm::vec3(image.at(p.x, p.y)) == glm::vec3(0.0f, 0.0f, 1.0f));
    }
    CHECK(isBackground(image, pixelAt(0.0, 0.0, 8.0, 80)));
    // One mesh, drawn twice: one instanced draw of two shapes.
    CHECK(gl.renderer.stats().shapeDraws == 1);
    CHECK(gl.renderer.stats().batchedShapes == 2);
    CHECK(gl.renderer.stats().meshUploads == 1);
    // The scene's vertex data counts the mesh for each shape; the GPU holds it once.
    CHECK(gl.renderer.stats().meshBytes > 0);
    CHECK(gl.renderer.stats().drawnMeshBytes == 2 * gl.renderer.stats().meshBytes);
}

TEST_CASE("a sphere under a DirectionalLight follows Lambert's law") {
    Offscreen gl;
    auto root = Separator::create();
    const double height = 2.5;
    const int size = 100;
    root->addChild(orthoCamera(float(height)));
    auto light = DirectionalLight::create(); // direction 0 0 -1: L = +Z
    root->addChild(light);
    auto material = Material::create();
    material->diffuseColor = {glm::vec3(1.0f)};
    material->ambientColor = {glm::vec3(0.0f)};
    root->addChild(material);
    auto fine = Complexity::create(); // Coin's finest sphere (30 x 29)
    fine->value = 1.0f;
    root->addChild(fine);
    root->addChild(Sphere::create());
    RenderOptions options;
    options.width = size;
    options.height = size;
    // The per-fragment model; where lights are summed per vertex is VertexLightingTest's.
    options.debug.shapeLighting = RenderDebug::Lighting::PerFragment;

    // For each light, every pixel whose centre sees the sphere within radius 0.9: the pixel
    // value is max(N.L, 0), N the sphere normal at that pixel = (x, y, sqrt(1 - x^2 - y^2)).
    const glm::dvec3 directions[] = {{0, 0, -1}, {-1, 0, -1}, {0.3, -0.5, -0.8}};
    for (const glm::dvec3& direction : directions) {
        light->direction = glm::vec3(direction);
        const glm::dvec3 L = -glm::normalize(direction);
        const Image image = gl.renderer.render(*root, options);
        double worst = 0.0;
        int checked = 0;
        for (int py = 0; py < size; ++py)
            for (int px = 0; px < size; ++px) {
                const double x = (px + 0.5) * height / size - height / 2;
                const double y = height / 2 - (py + 0.5) * height / size;
                if (x * x + y * y > 0.81) continue;
                const glm::dvec3 n(x, y, std::sqrt(1.0 - x * x - y * y));
                const double expected = std::max(glm::dot(n, L), 0.0);
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, std::abs(double(image.at(px, py)[c]) - expected));
                ++checked;
            }
        CHECK(checked > 4000);
        // Coin's finest sphere (30 x 29) lies up to 0.55% inside the true one and its
        // interpolated normals lean by up to a few degrees near the silhouette: measured
        // 0.0115 (2.9/255) at worst.
        CHECK(worst <= 4.0 / 255.0);
    }
}

TEST_CASE("a transparent shape blends with what is behind it") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(orthoCamera(8.0f));
    auto back = Separator::create();
    back->addChild(translate({-1.5f, 0.0f, -1.0f}));
    back->addChild(emissive({1.0f, 0.0f, 0.0f}));
    back->addChild(cube(3.0f, 3.0f, 0.5f));
    // A single quad (one layer; a closed solid would blend its front and back faces both).
    auto front = Separator::create();
    front->addChild(emissive({0.0f, 0.0f, 1.0f}, 0.25f)); // alpha 0.75
    auto corners = Coordinate3::create();
    corners->point = {glm::vec3(-1.0f, -1.0f, 1.0f), glm::vec3(3.0f, -1.0f, 1.0f),
                      glm::vec3(3.0f, 1.0f, 1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)};
    front->addChild(corners);
    auto quad = IndexedFaceSet::create();
    quad->coordIndex = {0, 1, 2, 3, -1};
    front->addChild(quad);
    root->addChild(front); // listed first: the opaque one still ends up behind
    root->addChild(back);
    RenderOptions options;
    options.width = 80;
    options.height = 80;
    options.background = {0.0f, 0.5f, 0.0f};
    const Image image = gl.renderer.render(*root, options);
    auto near = [](glm::vec4 a, glm::vec3 b) {
        return glm::all(glm::lessThanEqual(glm::abs(glm::vec3(a) - b), glm::vec3(1.0f / 255.0f)));
    };
    const glm::ivec2 overOpaque = pixelAt(-0.5, 0.0, 8.0, 80);
    const glm::ivec2 overBackground = pixelAt(2.5, 0.0, 8.0, 80);
    const glm::ivec2 opaqueOnly = pixelAt(-2.5, 1.2, 8.0, 80);
    CHECK(near(image.at(overOpaque.x, overOpaque.y),
               0.75f * glm::vec3(0, 0, 1) + 0.25f * glm::vec3(1, 0, 0)));
    CHECK(near(image.at(overBackground.x, overBackground.y),
               0.75f * glm::vec3(0, 0, 1) + 0.25f * glm::vec3(0, 0.5f, 0)));
    CHECK(near(image.at(opaqueOnly.x, opaqueOnly.y), glm::vec3(1, 0, 0)));
}

TEST_CASE("transparent shapes are drawn back to front whatever their scene order") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(orthoCamera(4.0f));
    auto nearer = Separator::create();
    nearer->addChild(translate({0.0f, 0.0f, 1.0f}));
    nearer->addChild(emissive({1.0f, 0.0f, 0.0f}, 0.5f));
    nearer->addChild(cube(2.0f, 2.0f, 0.1f));
    auto farther = Separator::create();
    farther->addChild(emissive({0.0f, 0.0f, 1.0f}, 0.5f));
    farther->addChild(cube(2.0f, 2.0f, 0.1f));
    root->addChild(nearer);
    root->addChild(farther);
    RenderOptions options;
    options.width = 40;
    options.height = 40;
    const Image image = gl.renderer.render(*root, options);
    // Each cube is two faces deep along the view, both blended: a slab of one material with
    // alpha a over colour C leaves C * (1 - (1-a)^2) + behind * (1-a)^2 = 0.75 C + 0.25 behind.
    // Farther over black, then nearer over that.
    const glm::vec3 afterFar = 0.75f * glm::vec3(0, 0, 1);
    const glm::vec3 expected = 0.75f * glm::vec3(1, 0, 0) + 0.25f * afterFar;
    const glm::vec4 p = image.at(20, 20);
    CHECK(std::abs(p.r - expected.r) <= 1.0f / 255.0f);
    CHECK(std::abs(p.g - expected.g) <= 1.0f / 255.0f);
    CHECK(std::abs(p.b - expected.b) <= 1.0f / 255.0f);
}

TEST_CASE("vertex colours replace the diffuse colour") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(orthoCamera(2.0f));
    auto material = Material::create();
    material->ambientColor = {glm::vec3(0.0f)};
    material->diffuseColor = {glm::vec3(1.0f, 0.0f, 1.0f)}; // must not show
    root->addChild(material);
    auto triangle = ColoredTriangle::create();
    triangle->color = {0.1f, 0.6f, 0.3f, 1.0f};
    root->addChild(triangle);
    RenderOptions options;
    options.width = 16;
    options.height = 16;
    const Image image = gl.renderer.render(*root, options);
    // Headlight straight on, flat normal from the triangle's plane: colour * 1.
    const glm::vec4 p = image.at(8, 8);
    CHECK(std::abs(p.r - 0.1f) <= 1e-5f);
    CHECK(std::abs(p.g - 0.6f) <= 1e-5f);
    CHECK(std::abs(p.b - 0.3f) <= 1e-5f);
}

TEST_CASE("an IndexedLineSet without normals is drawn unlit in its diffuse colour, as Coin") {
    // Coin draws a line set without normals in its BASE_COLOR light model (lighting off): the
    // diffuse colour alone, the emissive colour ignored (seen in Coin's images of draggers).
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(orthoCamera(4.0f));
    auto material = Material::create();
    material->diffuseColor = {glm::vec3(0.2f, 0.3f, 0.1f)};
    material->emissiveColor = {glm::vec3(0.1f, 0.1f, 0.5f)};
    root->addChild(material);
    auto coords = Coordinate3::create();
    // A horizontal line through the centres of row 10 (y = 2 - 10.5 * 0.2 = -0.1).
    coords->point = {glm::vec3(-1.5f, -0.1f, 0.0f), glm::vec3(1.5f, -0.1f, 0.0f)};
    root->addChild(coords);
    auto lines = IndexedLineSet::create();
    lines->coordIndex = {0, 1, -1};
    root->addChild(lines);
    RenderOptions options;
    options.width = 20;
    options.height = 20;
    const Image image = gl.renderer.render(*root, options);
    const glm::vec4 p = image.at(10, 10);
    CHECK(std::abs(p.r - 0.2f) <= 1e-5f);
    CHECK(std::abs(p.g - 0.3f) <= 1e-5f);
    CHECK(std::abs(p.b - 0.1f) <= 1e-5f);
    CHECK(isBackground(image, {10, 5}));
}

TEST_CASE("a scene with a light gets no headlight") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(orthoCamera(4.0f));
    auto light = DirectionalLight::create();
    light->direction = glm::vec3(-1.0f, 0.0f, 0.0f); // lights the +X face only
    root->addChild(light);
    root->addChild(cube(2.0f, 2.0f, 2.0f));
    RenderOptions options;
    options.width = 20;
    options.height = 20;
    Image image = gl.renderer.render(*root, options);
    // The front face gets ambient only: 0.2 * 0.2.
    CHECK(std::abs(image.at(10, 10).r - 0.04f) <= 1e-6f);

    light->on = false; // no light on at all: the headlight lights the front face
    image = gl.renderer.render(*root, options);
    CHECK(std::abs(image.at(10, 10).r - 0.84f) <= 1e-5f);
}

TEST_CASE("a tilted face shows the Phong diffuse and specular terms") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(orthoCamera(4.0f));
    root->addChild(DirectionalLight::create()); // L = +Z, the view direction: H = +Z too
    auto material = Material::create();
    material->ambientColor = {glm::vec3(0.0f)};
    material->diffuseColor = {glm::vec3(0.5f)};
    material->specularColor = {glm::vec3(0.5f)};
    material->shininess = {0.25f}; // exponent 32
    root->addChild(material);
    auto turn = Transform::create();
    const float angle = 0.3f;
    turn->rotation = Rotation{glm::vec3(0.0f, 1.0f, 0.0f), angle};
    root->addChild(turn);
    root->addChild(cube(2.0f, 2.0f, 2.0f));
    RenderOptions options;
    options.width = 20;
    options.height = 20;
    const Image image = gl.renderer.render(*root, options);
    // The front face's normal is (sin a, 0, cos a): N.L = N.H = cos a.
    const double c = std::cos(double(angle));
    const double expected = 0.5 * c + 0.5 * std::pow(c, 32.0);
    CHECK(std::abs(image.at(10, 10).r - expected) <= 1e-5);
}

TEST_CASE("a PointLight under a Transform lights a plane by the inverse cosine law") {
    Offscreen gl;
    auto root = Separator::create();
    const double height = 4.0;
    root->addChild(orthoCamera(float(height)));
    root->addChild(translate({0.0f, 0.0f, 0.25f}));
    auto light = PointLight::create();
    light->location = glm::vec3(0.0f, 0.0f, 0.25f); // world (0, 0, 0.5)
    light->intensity = 0.9f;
    root->addChild(light);
    root->addChild(translate({0.0f, 0.0f, -0.25f})); // the plane at z = 0
    auto material = Material::create();
    material->ambientColor = {glm::vec3(0.0f)};
    material->diffuseColor = {glm::vec3(1.0f)};
    root->addChild(material);
    auto corners = Coordinate3::create();
    corners->point = {glm::vec3(-2, -2, 0), glm::vec3(2, -2, 0), glm::vec3(2, 2, 0),
                      glm::vec3(-2, 2, 0)};
    root->addChild(corners);
    auto plane = IndexedFaceSet::create();
    plane->coordIndex = {0, 1, 2, 3, -1};
    root->addChild(plane);
    RenderOptions options;
    options.width = 40;
    options.height = 40;
    const Image image = gl.renderer.render(*root, options);
    // At (x, y, 0) the light at height h gives 0.9 * h / sqrt(x^2 + y^2 + h^2).
    for (int px : {2, 10, 20, 33}) {
        const int py = 17;
        const double x = (px + 0.5) * height / 40 - height / 2;
        const double y = height / 2 - (py + 0.5) * height / 40;
        const double h = 0.5;
        const double expected = 0.9 * h / std::sqrt(x * x + y * y + h * h);
        CHECK(std::abs(image.at(px, py).g - expected) <= 1e-5);
    }
}
