// Ray picking against scenes with known geometry: hit point, normal, distance and path are
// checked against values worked out analytically.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include <volsg/actions/PickAction.h>
#include <volsg/geometry/PrimitiveMeshes.h>
#include <volsg/geometry/RayIntersect.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/Complexity.h>
#include <volsg/nodes/Coordinate3.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/IndexedLineSet.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Sphere.h>
#include <volsg/nodes/Transform.h>

#include <glm/gtc/matrix_transform.hpp>

using namespace volsg;

namespace {

ref_ptr<Transform> translation(double x, double y, double z) {
    auto t = Transform::create();
    t->translation = glm::vec3(x, y, z);
    return t;
}

/// Orthographic camera at (0, 0, 10) looking down -Z, `height` world units tall.
ref_ptr<OrthographicCamera> orthoCamera(float height = 4.0f, float nearDistance = 1.0f,
                                        float farDistance = 20.0f) {
    auto camera = OrthographicCamera::create();
    camera->position = glm::vec3(0, 0, 10);
    camera->height = height;
    camera->nearDistance = nearDistance;
    camera->farDistance = farDistance;
    return camera;
}

/// Picks pixel (x, y) of a width x height viewport seen by `camera`.
std::optional<PickedPoint> pickPixel(Node& root, ref_ptr<Camera> camera, double x, double y,
                                     int width, int height,
                                     const glm::dmat4& cameraModel = glm::dmat4(1.0)) {
    PickAction pick;
    pick.setCamera(std::move(camera), cameraModel);
    pick.setPixel(x, y, width, height);
    pick.apply(root);
    return pick.picked();
}

bool near(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
    return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::dvec3(tolerance)));
}

/// The world position a pixel centre maps to under an orthographic view of `halfWidth` x
/// `halfHeight` centred on the axis (y = 0 is the top row).
glm::dvec2 orthoPixel(double x, double y, int width, int height, double halfWidth,
                      double halfHeight) {
    return {(2.0 * (x + 0.5) / width - 1.0) * halfWidth,
            (1.0 - 2.0 * (y + 0.5) / height) * halfHeight};
}

ref_ptr<Node> read(const std::string& body) {
    return readSceneFromString("#Inventor V2.1 ascii\n" + body, "<string>");
}

std::optional<PickedPoint> pickRay(Node& root, glm::dvec3 origin, glm::dvec3 direction) {
    PickAction pick;
    pick.setRay({origin, direction});
    pick.apply(root);
    return pick.picked();
}

} // namespace

TEST_CASE("ray hits a triangle at its barycentric point") {
    const glm::dvec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
    const Ray ray{{0.5, 0.25, 3.0}, {0, 0, -2}};
    const auto hit = intersectTriangle(ray, a, b, c);
    REQUIRE(hit);
    CHECK(hit->t == doctest::Approx(1.5).epsilon(1e-12));
    CHECK(hit->u == doctest::Approx(0.25).epsilon(1e-12));
    CHECK(hit->v == doctest::Approx(0.125).epsilon(1e-12));
    // The back face counts too (no culling).
    CHECK(intersectTriangle(ray, a, c, b));
}

TEST_CASE("ray misses triangles beside it behind it and parallel to it") {
    const glm::dvec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    CHECK_FALSE(
        intersectTriangle(Ray{{0.8, 0.8, 1}, {0, 0, -1}}, a, b, c));        // beyond the hypotenuse
    CHECK_FALSE(intersectTriangle(Ray{{0.2, 0.2, 1}, {0, 0, 1}}, a, b, c)); // behind the origin
    CHECK_FALSE(intersectTriangle(Ray{{-1, 0.2, 0}, {1, 0, 0}}, a, b, c));  // in its plane
    CHECK_FALSE(intersectTriangle(Ray{{0.2, 0.2, 1}, {0, 0, -1}}, a, a, c)); // degenerate
    // On the shared edge of two triangles: counted (edges are inclusive).
    CHECK(intersectTriangle(Ray{{0.5, 0.5, 1}, {0, 0, -1}}, a, b, c));
}

TEST_CASE("orthographic pick of a cube gives the front face point normal distance and path") {
    auto root = Separator::create();
    root->addChild(translation(0.5, 0.25, 0));
    auto cube = Cube::create();
    root->addChild(cube);
    const auto camera = orthoCamera();

    const auto hit = pickPixel(*root, camera, 60, 40, 100, 100);
    REQUIRE(hit);
    const glm::dvec2 xy = orthoPixel(60, 40, 100, 100, 2.0, 2.0); // (0.42, 0.38)
    CHECK(near(hit->point, {xy.x, xy.y, 1.0}, 1e-6));
    CHECK(near(hit->normal, {0, 0, 1}, 1e-6));
    CHECK(hit->distance == doctest::Approx(9.0).epsilon(1e-7)); // camera plane z=10 to z=1
    CHECK(hit->path == std::vector<Node*>{root.get(), cube.get()});
    // The primitive is a triangle of the +Z face.
    State state;
    const Mesh& mesh = cube->mesh(state);
    REQUIRE(hit->primitiveIndex < mesh.primitiveCount());
    for (int k = 0; k < 3; ++k)
        CHECK(mesh.positions[mesh.indices[3 * hit->primitiveIndex + k]].z == 1.0f);
}

TEST_CASE("orthographic pick widens the view for wide and tall viewports") {
    auto root = Separator::create();
    root->addChild(translation(0.5, 0.25, 0));
    root->addChild(Cube::create());
    const auto camera = orthoCamera();
    // 200 x 100: the 4 units of height stay, the width becomes 8.
    auto wide = pickPixel(*root, camera, 120, 50, 200, 100);
    REQUIRE(wide);
    glm::dvec2 xy = orthoPixel(120, 50, 200, 100, 4.0, 2.0);
    CHECK(near(wide->point, {xy.x, xy.y, 1.0}, 1e-6));
    CHECK_FALSE(pickPixel(*root, camera, 150, 50, 200, 100)); // x = 2.02, beyond the cube
    // 100 x 200: the 4 units of width stay (ADJUST_CAMERA), the height becomes 8.
    auto tall = pickPixel(*root, camera, 50, 90, 100, 200);
    REQUIRE(tall);
    xy = orthoPixel(50, 90, 100, 200, 2.0, 4.0);
    CHECK(near(tall->point, {xy.x, xy.y, 1.0}, 1e-6));
    CHECK_FALSE(pickPixel(*root, camera, 50, 60, 100, 200)); // y = 1.58, above the cube
}

TEST_CASE("perspective pick follows the ray from the eye through the pixel") {
    auto root = Separator::create();
    auto slab = Cube::create();
    slab->width = 10.0f;
    slab->height = 10.0f;
    slab->depth = 2.0f;
    root->addChild(slab);
    auto camera = PerspectiveCamera::create();
    camera->position = glm::vec3(0, 0, 5);
    camera->heightAngle = float(std::numbers::pi / 2);
    camera->nearDistance = 1.0f;
    camera->farDistance = 100.0f;

    const auto hit = pickPixel(*root, camera, 150, 25, 200, 100);
    REQUIRE(hit);
    // Eye-space direction through the pixel centre, at unit depth.
    const double halfH = std::tan(0.5 * double(camera->heightAngle()));
    const double halfW = 2.0 * halfH; // aspect 2
    const glm::dvec3 dir((2.0 * 150.5 / 200 - 1.0) * halfW, (1.0 - 2.0 * 25.5 / 100) * halfH, -1.0);
    const double s = 4.0; // from z=5 to the front face at z=1
    CHECK(near(hit->point, glm::dvec3(0, 0, 5) + s * dir, 1e-6));
    CHECK(near(hit->normal, {0, 0, 1}, 1e-6));
    CHECK(hit->distance == doctest::Approx(s * glm::length(dir)).epsilon(1e-7));
    CHECK(hit->path == std::vector<Node*>{root.get(), slab.get()});
}

TEST_CASE("perspective pick uses the camera orientation and the model above it") {
    auto root = Separator::create();
    root->addChild(Cube::create());
    auto camera = PerspectiveCamera::create();
    camera->position = glm::vec3(8, 0, 0);
    camera->orientation = Rotation{glm::vec3(0, 1, 0), float(std::numbers::pi / 2)}; // looks -X
    camera->nearDistance = 1.0f;
    camera->farDistance = 50.0f;
    const glm::dmat4 model = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0.5, 0));
    // x = y = 49.5 is the exact centre of a 100 x 100 viewport.
    const auto hit = pickPixel(*root, camera, 49.5, 49.5, 100, 100, model);
    REQUIRE(hit);
    CHECK(near(hit->point, {1, 0.5, 0}, 1e-6));
    CHECK(near(hit->normal, {1, 0, 0}, 1e-6));
    CHECK(hit->distance == doctest::Approx(7.0).epsilon(1e-7));
}

TEST_CASE("pick normal follows the inverse transpose under non-uniform scale") {
    // model = S * R: scale X by 2 after a 45 degree turn about Y. The cube's +X face normal
    // (1, 0, 0) becomes S^-1 R (1, 0, 0) = (cos a / 2, 0, -sin a), normalized.
    auto root = Separator::create();
    auto scale = Transform::create();
    scale->scaleFactor = glm::vec3(2, 1, 1);
    auto turn = Transform::create();
    const float angle = float(std::numbers::pi / 4);
    turn->rotation = Rotation{glm::vec3(0, 1, 0), angle};
    root->addChild(scale);
    root->addChild(turn);
    root->addChild(Cube::create());

    PickAction pick;
    pick.setRay(Ray{{10, 0.1, -0.3}, {-3, 0, 0}}); // direction is normalized by the action
    pick.apply(*root);
    REQUIRE(pick.picked());
    const double c = std::cos(double(angle)), s = std::sin(double(angle));
    // Before the scale the face is dot(q, (c, 0, -s)) = 1; on the ray q = (x', 0.1, -0.3).
    const double xPrime = (1.0 - 0.3 * s) / c;
    CHECK(near(pick.picked()->point, {2 * xPrime, 0.1, -0.3}, 1e-6));
    CHECK(near(pick.picked()->normal, glm::normalize(glm::dvec3(c / 2, 0, -s)), 1e-6));
    CHECK(pick.picked()->distance == doctest::Approx(10.0 - 2 * xPrime).epsilon(1e-7));
    CHECK(glm::length(pick.worldRay().direction) == doctest::Approx(1.0).epsilon(1e-12));
}

TEST_CASE("the nearer of two overlapping shapes is picked whatever their order") {
    auto root = Separator::create();
    auto back = Separator::create();
    back->addChild(translation(0, 0, -5));
    back->addChild(Sphere::create());
    auto front = Separator::create();
    front->addChild(translation(0, 0, 2));
    auto frontCube = Cube::create();
    front->addChild(frontCube);
    root->addChild(back); // the far one comes first in traversal
    root->addChild(front);
    const auto hit = pickPixel(*root, orthoCamera(), 49.5, 49.5, 100, 100);
    REQUIRE(hit);
    CHECK(near(hit->point, {0, 0, 3}, 1e-6));
    CHECK(hit->distance == doctest::Approx(7.0).epsilon(1e-7));
    CHECK(hit->path == std::vector<Node*>{root.get(), front.get(), frontCube.get()});
}

TEST_CASE("of two coincident shapes the first in traversal order is picked") {
    auto root = Separator::create();
    auto first = Cube::create(), second = Cube::create();
    root->addChild(first);
    root->addChild(second);
    const auto hit = pickPixel(*root, orthoCamera(), 30, 70, 100, 100);
    REQUIRE(hit);
    CHECK(hit->path.back() == first.get());
}

TEST_CASE("a clip plane removing the near face lets the far face be picked") {
    auto root = Separator::create();
    auto clip = ClipPlane::create();
    clip->plane = Plane{glm::vec3(0, 0, -1), 0.0f}; // keeps -z >= 0: the back half
    root->addChild(clip);
    auto cube = Cube::create();
    root->addChild(cube);
    const auto camera = orthoCamera();
    const glm::dvec2 xy = orthoPixel(40, 55, 100, 100, 2.0, 2.0);

    auto hit = pickPixel(*root, camera, 40, 55, 100, 100);
    REQUIRE(hit);
    CHECK(near(hit->point, {xy.x, xy.y, -1.0}, 1e-6));
    CHECK(near(hit->normal, {0, 0, -1}, 1e-6)); // the mesh's outward normal, not flipped
    CHECK(hit->distance == doctest::Approx(11.0).epsilon(1e-7));
    CHECK(hit->path == std::vector<Node*>{root.get(), cube.get()});

    clip->on = false;
    hit = pickPixel(*root, camera, 40, 55, 100, 100);
    REQUIRE(hit);
    CHECK(hit->point.z == doctest::Approx(1.0).epsilon(1e-7));

    clip->on = true;
    clip->plane = Plane{glm::vec3(0, 0, -1), 5.0f}; // keeps z <= -5: removes the whole cube
    CHECK_FALSE(pickPixel(*root, camera, 40, 55, 100, 100));
}

TEST_CASE("a clip plane is placed by the model matrix at its node and scoped by separators") {
    auto root = Separator::create();
    root->addChild(translation(0, 0, 3));
    auto clip = ClipPlane::create();
    clip->plane = Plane{glm::vec3(0, 0, -1), 2.5f}; // local z <= -2.5, world z <= 0.5
    root->addChild(clip);
    root->addChild(translation(0, 0, -3)); // the cube sits at the world origin
    root->addChild(Cube::create());
    const auto camera = orthoCamera();
    auto hit = pickPixel(*root, camera, 49.5, 49.5, 100, 100);
    REQUIRE(hit);
    CHECK(near(hit->point, {0, 0, -1}, 1e-6));

    // The same plane inside a sibling Separator clips nothing after it.
    auto scoped = Separator::create();
    auto inner = Separator::create();
    auto clip2 = ClipPlane::create();
    clip2->plane = Plane{glm::vec3(0, 0, -1), 0.0f};
    inner->addChild(clip2);
    scoped->addChild(inner);
    scoped->addChild(Cube::create());
    hit = pickPixel(*scoped, camera, 49.5, 49.5, 100, 100);
    REQUIRE(hit);
    CHECK(near(hit->point, {0, 0, 1}, 1e-6));
}

TEST_CASE("shapes nearer than the near plane or beyond the far plane are not picked") {
    auto root = Separator::create();
    auto close = Separator::create();
    close->addChild(translation(0, 0, 8)); // faces at z = 7 and 9, camera at 10, near 5
    close->addChild(Cube::create());
    root->addChild(close);
    auto farCube = Cube::create();
    root->addChild(farCube);
    auto hit = pickPixel(*root, orthoCamera(4.0f, 5.0f, 20.0f), 49.5, 49.5, 100, 100);
    REQUIRE(hit);
    CHECK(hit->path.back() == farCube.get());
    CHECK(hit->distance == doctest::Approx(9.0).epsilon(1e-7));
    // With the far plane at 8.5 the cube at the origin (distance 9) is out of view too.
    CHECK_FALSE(pickPixel(*root, orthoCamera(4.0f, 5.0f, 8.5f), 49.5, 49.5, 100, 100));
}

TEST_CASE("a ray that misses everything gives no result") {
    auto root = Separator::create();
    root->addChild(Cube::create());
    const auto camera = orthoCamera();
    CHECK_FALSE(pickPixel(*root, camera, 2, 3, 100, 100)); // (-1.9, 1.86): beside the cube
    auto empty = Separator::create();
    CHECK_FALSE(pickPixel(*empty, camera, 50, 50, 100, 100));
    // A hit on a previous apply does not survive into the next one.
    PickAction pick;
    pick.setCamera(camera);
    pick.setPixel(50, 50, 100, 100);
    pick.apply(*root);
    CHECK(pick.picked());
    pick.setPixel(2, 3, 100, 100);
    pick.apply(*root);
    CHECK_FALSE(pick.picked());
}

TEST_CASE("line sets are not pickable") {
    auto root = Separator::create();
    auto coords = Coordinate3::create();
    coords->point.setValues({{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}});
    root->addChild(coords);
    auto lines = IndexedLineSet::create();
    lines->coordIndex.setValues({0, 1, -1, 2, 3});
    root->addChild(lines);
    PickAction pick;
    pick.setRay(Ray{{0, 0, 5}, {0, 0, -1}}); // straight through the crossing point
    pick.apply(*root);
    CHECK_FALSE(pick.picked());
}

TEST_CASE("a sphere is picked on the true sphere, as Coin picks it, not on its tessellation") {
    // Orthographic view down -Z, 6 units tall, sphere of radius 2 at the origin. A pixel's ray
    // x, y is exact; the hit is on the sphere (z = sqrt(r^2 - x^2 - y^2)) with the radial normal,
    // at every Complexity (the drawn tessellation changes with it; the pick does not).
    for (const float complexity : {0.0f, 0.5f, 1.0f}) {
        CAPTURE(complexity);
        auto root = Separator::create();
        auto detail = Complexity::create();
        detail->value = complexity;
        root->addChild(detail);
        auto sphere = Sphere::create();
        sphere->radius = 2.0f;
        root->addChild(sphere);
        const auto camera = orthoCamera(6.0f);
        const double r = 2.0;
        for (const auto& [x, y] :
             {std::pair{49.5, 49.5}, std::pair{60.0, 45.0}, std::pair{35.0, 62.0},
              std::pair{70.0, 70.0}, std::pair{50.0, 17.0}}) {
            // Copies: structured bindings cannot be captured by CAPTURE's lambda under clang 14.
            const double px = x, py = y;
            CAPTURE(px);
            CAPTURE(py);
            const auto hit = pickPixel(*root, camera, px, py, 100, 100);
            REQUIRE(hit);
            const glm::dvec2 xy = orthoPixel(px, py, 100, 100, 3.0, 3.0);
            CHECK(hit->point.x == doctest::Approx(xy.x).epsilon(1e-6));
            CHECK(hit->point.y == doctest::Approx(xy.y).epsilon(1e-6));
            CHECK(hit->point.z == doctest::Approx(std::sqrt(r * r - glm::dot(xy, xy))));
            CHECK(hit->distance == doctest::Approx(10.0 - hit->point.z).epsilon(1e-9));
            CHECK(glm::length(hit->normal - hit->point / r) < 1e-9);
        }
        CHECK_FALSE(pickPixel(*root, camera, 50, 5, 100, 100)); // y = 2.67 > r
    }
}

TEST_CASE("a cone and a cylinder are picked on their exact sides and caps, part by part") {
    // Cone: bottom radius 1, height 2 (apex y = 1). A ray along -z at y = 0.5 meets the side
    // where its radius is 0.25; with only the BOTTOM part it meets nothing there.
    auto cone = read("Cone { }");
    auto hit = pickRay(*cone, {0.1, 0.5, 5}, {0, 0, -1});
    REQUIRE(hit);
    CHECK(hit->point.z == doctest::Approx(std::sqrt(0.25 * 0.25 - 0.01)));
    CHECK(hit->primitiveIndex == 0);
    auto bottomOnly = read("Cone { parts BOTTOM }");
    CHECK_FALSE(pickRay(*bottomOnly, {0.1, 0.5, 5}, {0, 0, -1}));
    hit = pickRay(*bottomOnly, {0.3, -5, 0.2}, {0, 1, 0});
    REQUIRE(hit);
    CHECK(hit->point.y == doctest::Approx(-1.0));
    CHECK(hit->normal.y == doctest::Approx(-1.0));
    CHECK(hit->primitiveIndex == 1);
    // Cylinder radius 1, height 2: the top from above, the side from the front.
    auto cylinder = read("Cylinder { }");
    hit = pickRay(*cylinder, {0.5, 5, 0.5}, {0, -1, 0});
    REQUIRE(hit);
    CHECK(hit->point.y == doctest::Approx(1.0));
    CHECK(hit->primitiveIndex == 1);
    hit = pickRay(*cylinder, {0.6, 0.3, 5}, {0, 0, -1});
    REQUIRE(hit);
    CHECK(hit->point.z == doctest::Approx(0.8));
    CHECK(hit->normal.x == doctest::Approx(0.6));
    CHECK(hit->primitiveIndex == 0);
    // From inside (the camera inside a cylinder): the far wall.
    hit = pickRay(*cylinder, {0, 0, 0}, {0, 0, -1});
    REQUIRE(hit);
    CHECK(hit->point.z == doctest::Approx(-1.0));
}

TEST_CASE("without an explicit camera the scene's camera and its model are used") {
    auto root = Separator::create();
    auto cameraPlace = Separator::create();
    cameraPlace->addChild(translation(1.5, 0, 0)); // moves only the camera
    cameraPlace->addChild(orthoCamera());
    root->addChild(cameraPlace);
    root->addChild(Cube::create());
    PickAction pick;
    pick.setPixel(10, 49.5, 100, 100); // x = 1.5 - 1.58 = -0.08 in the world
    pick.apply(*root);
    REQUIRE(pick.picked());
    CHECK(near(pick.picked()->point, {1.5 + orthoPixel(10, 49.5, 100, 100, 2, 2).x, 0, 1}, 1e-6));
    CHECK(pick.picked()->distance == doctest::Approx(9.0).epsilon(1e-7));
}

TEST_CASE("without any camera the made camera looks at the scene from plus Z") {
    auto root = Separator::create();
    root->addChild(Cube::create());
    PickAction pick;
    pick.setPixel(49.5, 49.5, 100, 100);
    pick.apply(*root);
    REQUIRE(pick.picked());
    CHECK(near(pick.picked()->point, {0, 0, 1}, 1e-6));
    CHECK(near(pick.picked()->normal, {0, 0, 1}, 1e-6));
}
