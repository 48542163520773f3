// Level of detail for small curved shapes (lib/volsg/render/ShapeDetail.h), against analytic
// expectations: a sphere, or a cone or cylinder seen along its axis, projects orthographically
// to a disk of the shape's radius; its coarser tessellation lies within kShapeDetailPixels of
// that disk's edge (and a tenth of its radius), so every pixel centre farther inside covers the
// shape and every one outside the disk does not. And the level chosen under a perspective view, and
// its lit image.
#include <doctest/doctest.h>

#include "support/Offscreen.h"

#include <volsg/context/OSMesaContext.h>
#include <volsg/geometry/PrimitiveMeshes.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/image/Image.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/Complexity.h>
#include <volsg/nodes/Cone.h>
#include <volsg/nodes/Cylinder.h>
#include <volsg/nodes/Light.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Sphere.h>
#include <volsg/nodes/Transform.h>
#include <volsg/render/GpuMesh.h>
#include <volsg/render/Renderer.h>
#include <volsg/render/ShapeDetail.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

using namespace volsg;

namespace {

using volsg::test::Offscreen;

constexpr int kSize = 256;
constexpr double kPixelsPerUnit = 4.0; // the camera's 64 units over 256 pixels

enum class Kind { Sphere, Cylinder, Cone };

/// One shape of radius `radiusPixels`, its centre at pixel (cx, cy) (y down), axis towards the
/// camera, in an unlit white.
ref_ptr<Separator> placed(Kind kind, double radiusPixels, double cx, double cy) {
    auto sep = Separator::create();
    auto move = Transform::create();
    move->translation =
        glm::vec3(float(cx / kPixelsPerUnit - 32.0), float(32.0 - cy / kPixelsPerUnit), 0.0f);
    // Round shapes stand along +Y: turned to face the camera along their axis.
    move->rotation = Rotation{glm::vec3(1.0f, 0.0f, 0.0f), 0.5f * std::numbers::pi_v<float>};
    sep->addChild(move);
    auto white = Material::create();
    white->diffuseColor = {glm::vec3(0.0f)};
    white->ambientColor = {glm::vec3(0.0f)};
    white->emissiveColor = {glm::vec3(1.0f)};
    sep->addChild(white);
    const float r = float(radiusPixels / kPixelsPerUnit);
    switch (kind) {
    case Kind::Sphere: {
        auto s = Sphere::create();
        s->radius = r;
        sep->addChild(s);
        break;
    }
    case Kind::Cylinder: {
        auto c = Cylinder::create();
        c->radius = r;
        c->height = r;
        sep->addChild(c);
        break;
    }
    case Kind::Cone: {
        auto c = Cone::create();
        c->bottomRadius = r;
        c->height = r;
        sep->addChild(c);
        break;
    }
    }
    return sep;
}

ref_ptr<OrthographicCamera> camera() {
    auto c = OrthographicCamera::create();
    c->position = glm::vec3(0.0f, 0.0f, 50.0f);
    c->height = float(kSize / kPixelsPerUnit);
    c->nearDistance = 1.0f;
    c->farDistance = 100.0f;
    return c;
}

struct Disk {
    double radius, cx, cy;
};

/// Pixel centres that break the disk rule: inside by more than inset(radius) pixels but not
/// white, or outside the disk but not black (a small margin for the rasteriser's own rounding).
template <class Inset>
int misplaced(const Image& image, const std::vector<Disk>& disks, Inset inset) {
    int bad = 0;
    for (const Disk& d : disks)
        for (int y = int(d.cy - d.radius) - 2; y <= int(d.cy + d.radius) + 2; ++y)
            for (int x = int(d.cx - d.radius) - 2; x <= int(d.cx + d.radius) + 2; ++x) {
                const double dist = std::hypot(x + 0.5 - d.cx, y + 0.5 - d.cy);
                const float v = image.at(x, y).r;
                if (dist < d.radius - inset(d.radius) - 0.01 && v < 0.99f) ++bad;
                if (dist > d.radius + 0.01 && v > 0.01f) ++bad;
            }
    return bad;
}

} // namespace

TEST_CASE("small spheres, cylinders and cones drawn coarser still cover their disks") {
    Offscreen gl;
    // Off the pixel grid by varied fractions, apart from each other.
    const std::vector<Disk> disks{
        {1.3, 10.37, 40.29},   {1.9, 25.74, 40.58},    {2.6, 45.11, 40.0},
        {3.7, 70.48, 40.29},   {5.2, 100.85, 40.58},   {8.1, 140.22, 40.0},
        {13.5, 60.59, 140.29}, {31.0, 150.96, 170.58}, {0.9, 200.43, 40.71}};
    for (Kind kind : {Kind::Sphere, Kind::Cylinder, Kind::Cone}) {
        CAPTURE(int(kind));
        auto root = Separator::create();
        root->addChild(camera());
        for (const Disk& d : disks)
            root->addChild(placed(kind, d.radius, d.cx, d.cy));
        RenderOptions options;
        options.width = options.height = kSize;
        const Image coarse = gl.renderer.render(*root, options);
        const std::size_t coarser = gl.renderer.stats().coarserShapes;
        options.debug.shapeDetail = false;
        const Image full = gl.renderer.render(*root, options);
        CHECK(gl.renderer.stats().coarserShapes == 0);

        // Small ones are drawn coarser (all up to 5 pixels), the largest never.
        CHECK(coarser >= 5);
        CHECK(coarser < disks.size());
        // The full tessellation lies within its own deviation of the disk's edge; a coarser
        // one within a quarter pixel and a tenth of the radius, or the full one's deviation
        // where that is larger (it is drawn then).
        const auto fullInset = [&](double r) {
            return kind == Kind::Sphere
                       ? sphereMeshDeviation(float(r), sphereSlicesFor(0.5f), sphereStacksFor(0.5f))
                       : roundMeshDeviation(float(r), roundSlicesFor(0.5f));
        };
        const auto coarseInset = [&](double r) {
            return std::max(fullInset(r),
                            std::min(kShapeDetailPixels, kCoarsestRelativeDeviation * r));
        };
        CHECK(misplaced(full, disks, fullInset) == 0);
        CHECK(misplaced(coarse, disks, coarseInset) == 0);
        // Against the full tessellation: only pixels near the edges differ.
        int differing = 0, edge = 0;
        for (const Disk& d : disks)
            edge += int(std::ceil(2.0 * std::numbers::pi * d.radius));
        for (std::size_t i = 0; i < coarse.pixels.size(); ++i)
            differing += std::abs(coarse.pixels[i].r - full.pixels[i].r) > 0.01f;
        CHECK(differing <= edge / 4);
    }
}

TEST_CASE("the level chosen under a perspective projects its deviation below a quarter pixel") {
    Offscreen gl;
    GpuMesh full, fine, mid, coarsest;
    ShapeDetail detail;
    detail.levels = {{std::shared_ptr<GpuMesh>(&fine, [](GpuMesh*) {}), 0.01},
                     {std::shared_ptr<GpuMesh>(&mid, [](GpuMesh*) {}), 0.03},
                     {std::shared_ptr<GpuMesh>(&coarsest, [](GpuMesh*) {}), 0.1}};
    detail.radius = 1.0;
    RenderView view;
    view.width = view.height = 400;
    const double fovY = 0.8; // radians
    const double f = 1.0 / std::tan(0.5 * fovY);
    view.projection = glm::dmat4(0.0);
    view.projection[0][0] = f;
    view.projection[1][1] = f;
    view.projection[2][2] = -1.0;
    view.projection[2][3] = -1.0;
    view.projection[3][2] = -0.2;
    const auto at = [&](double distance, double scale) -> const GpuMesh* {
        glm::dmat4 model(scale);
        model[3] = glm::dvec4(0.0, 0.0, -distance, 1.0);
        return &detail.choose(view, model, full);
    };
    // Pixels per unit at the sphere's nearest point: 200 f / (distance - scale).
    const auto expected = [&](double distance, double scale) -> const GpuMesh* {
        if (!(distance - scale > 0.0)) return &full; // the eye inside, or behind
        const double ppu = 200.0 * f / (distance - scale) * scale;
        if (0.1 * ppu <= kShapeDetailPixels) return &coarsest;
        if (0.03 * ppu <= kShapeDetailPixels) return &mid;
        if (0.01 * ppu <= kShapeDetailPixels) return &fine;
        return &full;
    };
    for (double distance : {2.0, 5.0, 12.0, 30.0, 80.0, 200.0, 1000.0})
        for (double scale : {0.5, 1.0, 3.0}) {
            CAPTURE(distance);
            CAPTURE(scale);
            CHECK(at(distance, scale) == expected(distance, scale));
        }
    CHECK(at(1000.0, 1.0) == &coarsest);
    CHECK(at(0.5, 1.0) == &full);   // the eye inside the shape's sphere
    CHECK(at(-10.0, 1.0) == &full); // behind the eye
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK(at(nan, 1.0) == &full);
    CHECK(at(10.0, std::numeric_limits<double>::infinity()) == &full);
}

TEST_CASE(
    "small lit spheres drawn coarser shade as the full ones: at most 6/255, 1/255 on average") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(camera());
    auto light = DirectionalLight::create();
    light->direction = glm::vec3(-0.4f, -0.5f, -1.0f);
    root->addChild(light);
    std::vector<Disk> disks;
    for (int i = 0; i < 6; ++i) {
        const double r = 2.0 + 0.7 * i, cx = 20.0 + 40.0 * i + 0.3 * i, cy = 100.5;
        auto sep = Separator::create();
        auto move = Transform::create();
        move->translation =
            glm::vec3(float(cx / kPixelsPerUnit - 32.0), float(32.0 - cy / kPixelsPerUnit), 0.0f);
        sep->addChild(move);
        auto s = Sphere::create();
        s->radius = float(r / kPixelsPerUnit);
        sep->addChild(s);
        root->addChild(sep);
        disks.push_back({r, cx, cy});
    }
    RenderOptions options;
    options.width = options.height = kSize;
    options.debug.shapeLighting = RenderDebug::Lighting::PerFragment;
    const Image coarse = gl.renderer.render(*root, options);
    CHECK(gl.renderer.stats().coarserShapes == 6);
    options.debug.shapeDetail = false;
    const Image full = gl.renderer.render(*root, options);
    // Inside by more than a pixel (away from the edge's coverage changes), per channel: the
    // normals interpolated over wider facets (measured: at most 3.8/255).
    float worst = 0.0f;
    double sum = 0.0;
    int count = 0;
    for (const Disk& d : disks)
        for (int y = int(d.cy - d.radius); y <= int(d.cy + d.radius); ++y)
            for (int x = int(d.cx - d.radius); x <= int(d.cx + d.radius); ++x)
                if (std::hypot(x + 0.5 - d.cx, y + 0.5 - d.cy) < d.radius - 1.0)
                    for (int c = 0; c < 3; ++c) {
                        const float e = std::abs(coarse.at(x, y)[c] - full.at(x, y)[c]);
                        worst = std::max(worst, e);
                        sum += e;
                        ++count;
                    }
    MESSAGE("inside the disks: largest difference " << worst * 255.0f << "/255, mean "
                                                    << sum / count * 255.0 << "/255");
    REQUIRE(count > 100);
    CHECK(worst <= 6.0f / 255.0f);
    CHECK(sum / count <= 1.0 / 255.0);
}

TEST_CASE("shapes under a SCREEN_SPACE Complexity keep the tessellation it fits to the view") {
    Offscreen gl;
    auto root = Separator::create();
    root->addChild(camera());
    auto complexity = Complexity::create();
    complexity->type = Complexity::SCREEN_SPACE;
    root->addChild(complexity);
    root->addChild(placed(Kind::Sphere, 2.5, 40.3, 40.6));
    RenderOptions options;
    options.width = options.height = kSize;
    gl.renderer.render(*root, options);
    CHECK(gl.renderer.stats().coarserShapes == 0);
    complexity->type = Complexity::OBJECT_SPACE;
    gl.renderer.render(*root, options);
    CHECK(gl.renderer.stats().coarserShapes == 1);
}
