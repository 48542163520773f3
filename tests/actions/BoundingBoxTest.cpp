// World bounding boxes of scenes built in code, against boxes worked out by hand.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/Cone.h>
#include <volsg/nodes/Coordinate3.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/IndexedFaceSet.h>
#include <volsg/nodes/IndexedLineSet.h>
#include <volsg/nodes/Light.h>
#include <volsg/nodes/MatrixTransform.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Sphere.h>
#include <volsg/nodes/Switch.h>
#include <volsg/nodes/Transform.h>

using namespace volsg;

namespace {

ref_ptr<Transform> translation(double x, double y, double z) {
    auto t = Transform::create();
    t->translation = glm::vec3(x, y, z);
    return t;
}

/// Both corners equal the expected ones within `tolerance` per coordinate.
bool boxNear(const Box3& box, const glm::dvec3& min, const glm::dvec3& max,
             double tolerance = 1e-6) {
    return glm::all(glm::lessThanEqual(glm::abs(box.min - min), glm::dvec3(tolerance))) &&
           glm::all(glm::lessThanEqual(glm::abs(box.max - max), glm::dvec3(tolerance)));
}

} // namespace

TEST_CASE("empty scene has an empty bounding box") {
    auto root = Separator::create();
    CHECK(computeBoundingBox(*root).isEmpty());
    root->addChild(Transform::create());
    root->addChild(Separator::create());
    CHECK(computeBoundingBox(*root).isEmpty());
}

TEST_CASE("default shapes have Inventor's default boxes") {
    auto cube = Cube::create();
    CHECK(boxNear(computeBoundingBox(*cube), glm::dvec3(-1), glm::dvec3(1), 0.0));
    auto sphere = Sphere::create();
    CHECK(boxNear(computeBoundingBox(*sphere), glm::dvec3(-1), glm::dvec3(1), 1e-7));
    auto cone = Cone::create();
    CHECK(boxNear(computeBoundingBox(*cone), glm::dvec3(-1), glm::dvec3(1), 1e-7));
}

TEST_CASE("transform translation rotation and scale move the box of the corners") {
    // Cube 2x2x2, scaled x2 along X: [-2,2]x[-1,1]x[-1,1]; rotated 90 degrees about Z:
    // (x, y) -> (-y, x) gives [-1,1]x[-2,2]x[-1,1]; translated by (1, 2, 3).
    auto root = Separator::create();
    auto t = Transform::create();
    t->translation = glm::vec3(1, 2, 3);
    t->rotation = Rotation{glm::vec3(0, 0, 1), float(std::numbers::pi / 2)};
    t->scaleFactor = glm::vec3(2, 1, 1);
    root->addChild(t);
    root->addChild(Cube::create());
    CHECK(boxNear(computeBoundingBox(*root), {0, 0, 2}, {2, 4, 4}, 1e-6));
}

TEST_CASE("a cube rotated 45 degrees about Y is sqrt 2 wide") {
    auto root = Separator::create();
    auto t = Transform::create();
    const float angle = float(std::numbers::pi / 4);
    t->rotation = Rotation{glm::vec3(0, 1, 0), angle};
    root->addChild(t);
    root->addChild(Cube::create());
    // The box of the rotated corners: half width cos a + sin a, with a the float angle.
    const double half = std::cos(double(angle)) + std::sin(double(angle));
    CHECK(half == doctest::Approx(std::sqrt(2.0)).epsilon(1e-7));
    CHECK(boxNear(computeBoundingBox(*root), {-half, -1, -half}, {half, 1, half}, 1e-9));
}

TEST_CASE("matrix transform applies its matrix") {
    auto root = Separator::create();
    auto m = MatrixTransform::create();
    glm::mat4 matrix(1.0f);
    matrix[3] = glm::vec4(10, 0, -4, 1); // translation column
    matrix[1][1] = 3.0f;                 // scale Y
    m->matrix = matrix;
    root->addChild(m);
    root->addChild(Cube::create());
    CHECK(boxNear(computeBoundingBox(*root), {9, -3, -5}, {11, 3, -3}, 0.0));
}

TEST_CASE("separator scopes a transform and a group does not") {
    auto root = Separator::create();
    auto inner = Separator::create();
    inner->addChild(translation(5, 0, 0));
    inner->addChild(Cube::create());
    root->addChild(inner);
    root->addChild(Cube::create()); // back at the origin
    CHECK(boxNear(computeBoundingBox(*root), {-1, -1, -1}, {6, 1, 1}, 0.0));

    auto groupRoot = Separator::create();
    auto group = Group::create();
    group->addChild(translation(5, 0, 0));
    group->addChild(Cube::create());
    groupRoot->addChild(group);
    groupRoot->addChild(Cube::create()); // still moved by the group's transform
    CHECK(boxNear(computeBoundingBox(*groupRoot), {4, -1, -1}, {6, 1, 1}, 0.0));
}

TEST_CASE("switch contributes only the traversed children") {
    auto root = Separator::create();
    auto sw = Switch::create();
    for (double x : {-10.0, 10.0}) {
        auto child = Separator::create();
        child->addChild(translation(x, 0, 0));
        child->addChild(Cube::create());
        sw->addChild(child);
    }
    root->addChild(sw);
    sw->whichChild = 1;
    CHECK(boxNear(computeBoundingBox(*root), {9, -1, -1}, {11, 1, 1}, 0.0));
    sw->whichChild = 0;
    CHECK(boxNear(computeBoundingBox(*root), {-11, -1, -1}, {-9, 1, 1}, 0.0));
    sw->whichChild = Switch::SWITCH_NONE;
    CHECK(computeBoundingBox(*root).isEmpty());
    sw->whichChild = 7; // out of range: nothing
    CHECK(computeBoundingBox(*root).isEmpty());
    sw->whichChild = Switch::SWITCH_ALL;
    CHECK(boxNear(computeBoundingBox(*root), {-11, -1, -1}, {11, 1, 1}, 0.0));
}

TEST_CASE("a node USEd twice counts at both places") {
    auto shared = Sphere::create();
    shared->radius = 0.5f;
    auto root = Separator::create();
    for (auto [x, y] : {std::pair{-3.0, 0.0}, std::pair{0.0, 7.0}}) {
        auto place = Separator::create();
        place->addChild(translation(x, y, 0));
        place->addChild(shared);
        root->addChild(place);
    }
    CHECK(boxNear(computeBoundingBox(*root), {-3.5, -0.5, -0.5}, {0.5, 7.5, 0.5}, 1e-7));
}

TEST_CASE("cameras lights and clip planes add nothing to the box") {
    auto root = Separator::create();
    auto camera = PerspectiveCamera::create();
    camera->position = glm::vec3(0, 0, 100);
    root->addChild(camera);
    auto ortho = OrthographicCamera::create();
    ortho->position = glm::vec3(-50, 0, 0);
    root->addChild(ortho);
    auto point = PointLight::create();
    point->location = glm::vec3(0, 40, 0);
    root->addChild(point);
    root->addChild(DirectionalLight::create());
    auto clip = ClipPlane::create();
    clip->plane = Plane{glm::vec3(1, 0, 0), 0.5f}; // keeps x >= 0.5, but the box ignores it
    root->addChild(clip);
    root->addChild(Cube::create());
    CHECK(boxNear(computeBoundingBox(*root), glm::dvec3(-1), glm::dvec3(1), 0.0));
}

TEST_CASE("indexed shapes are bounded by the points they use") {
    auto root = Separator::create();
    auto coords = Coordinate3::create();
    coords->point.setValues({{0, 0, 0}, {2, 0, 0}, {2, 3, 0}, {-4, -4, -4}, {0, 1, 1}});
    root->addChild(coords);
    auto faces = IndexedFaceSet::create();
    faces->coordIndex.setValues({0, 1, 2, -1});
    root->addChild(faces);
    CHECK(boxNear(computeBoundingBox(*root), {0, 0, 0}, {2, 3, 0}, 0.0));
    auto lines = IndexedLineSet::create();
    lines->coordIndex.setValues({0, 4});
    root->addChild(lines);
    CHECK(boxNear(computeBoundingBox(*root), {0, 0, 0}, {2, 3, 1}, 0.0));
}

TEST_CASE("bounding box action can be applied again to a changed scene") {
    auto root = Separator::create();
    auto t = translation(1, 0, 0);
    root->addChild(t);
    root->addChild(Cube::create());
    BoundingBoxAction action;
    action.apply(*root);
    CHECK(boxNear(action.boundingBox(), {0, -1, -1}, {2, 1, 1}, 0.0));
    t->translation = glm::vec3(0, 0, -2);
    action.apply(*root); // starts from an empty box, not the previous one
    CHECK(boxNear(action.boundingBox(), {-1, -1, -3}, {1, 1, -1}, 0.0));
}

TEST_CASE("a shape's box follows edits of the points its mesh is built from") {
    // The mesh's bounds are kept with the mesh (found once per build, not per instance); an
    // edit that rebuilds the mesh must move them, in every instance.
    auto root = Separator::create();
    auto coords = Coordinate3::create();
    coords->point.setValues({{0, 0, 0}, {2, 0, 0}, {2, 3, 0}});
    root->addChild(coords);
    auto faces = IndexedFaceSet::create();
    faces->coordIndex.setValues({0, 1, 2, -1});
    root->addChild(faces);
    root->addChild(translation(10, 0, 0));
    root->addChild(faces); // a second instance, 10 to the right
    CHECK(boxNear(computeBoundingBox(*root), {0, 0, 0}, {12, 3, 0}, 0.0));
    coords->point.set1Value(2, {2, 5, -1});
    CHECK(boxNear(computeBoundingBox(*root), {0, 0, -1}, {12, 5, 0}, 0.0));
    faces->coordIndex.setValues({0, 1, -1}); // a degenerate face: no triangle, no points used
    CHECK(computeBoundingBox(*root).isEmpty());
}
