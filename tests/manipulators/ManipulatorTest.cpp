// Manipulator nodes: they stand in for their plain node, their handles are pickable, drags
// change the fields by the analytic amounts, and detaching writes plain fields back.
#include <doctest/doctest.h>

#include <cmath>

#include <volsg/actions/PickAction.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/manipulators/BoxClipManip.h>
#include <volsg/manipulators/ClipPlaneManip.h>
#include <volsg/manipulators/DragMath.h>
#include <volsg/manipulators/TransformManip.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/Separator.h>

using namespace volsg;

namespace {

/// The pick path of a world ray, as the viewer gets it before beginDrag.
std::vector<Node*> pickPath(Node& root, const Ray& ray) {
    PickAction pick;
    pick.setRay(ray);
    pick.apply(root);
    return pick.picked() ? pick.picked()->path : std::vector<Node*>{};
}

Ray downZ(double x, double y) {
    return {{x, y, 50.0}, {0.0, 0.0, -1.0}};
}

/// A ray at 45 degrees in the x-z plane that crosses z = 0 at (x, y).
Ray oblique(double x, double y) {
    return {{x + 10.0, y, 10.0}, glm::normalize(glm::dvec3(-1.0, 0.0, -1.0))};
}

} // namespace

TEST_CASE("a clip-plane manipulator replaces its node and writes the plane back on detach") {
    auto root = Separator::create();
    auto plane = ClipPlane::create();
    plane->plane = Plane{glm::vec3(0.0f, 0.0f, 1.0f), 0.0f};
    root->addChild(plane);
    root->addChild(plane); // USEd twice: both places are replaced

    auto manip = ClipPlaneManip::create();
    REQUIRE(manip->attach(*root, *plane));
    CHECK(root->getChild(0) == manip.get());
    CHECK(root->getChild(1) == manip.get());
    CHECK(manip->plane().normal == glm::vec3(0.0f, 0.0f, 1.0f));

    manip->setHandleSize(4.0);
    manip->setAnchor({0.0, 0.0, 0.0});
    // Handles are drawn (and picked) at the plane point nearest the anchor: the square spans
    // x, y in [-2, 2] at z = 0.
    // A ray at 45 degrees in the y-z plane (so the normal z can be dragged along) crossing the
    // square at (1, 0.5, 0): it lies on the line y - z = 0.5, nearest the z axis at z = -0.5.
    const glm::dvec3 along = glm::normalize(glm::dvec3(0.0, -1.0, -1.0));
    const Ray grab{{1.0, 10.5, 10.0}, along};
    const auto path = pickPath(*root, grab);
    REQUIRE_FALSE(path.empty());
    REQUIRE(manip->beginDrag(grab, path));
    CHECK(manip->activePart() == ClipPlaneManip::Square);
    // The ray moved to the line y - z = -0.5: nearest the z axis at z = +0.5, one unit further.
    manip->drag(Ray{{1.0, 10.5, 11.0}, along});
    CHECK(manip->plane().distance == doctest::Approx(1.0).epsilon(1e-5));
    CHECK(plane->plane().distance == doctest::Approx(1.0).epsilon(1e-5)); // written back at once
    manip->endDrag();

    manip->detach();
    CHECK(root->getChild(0) == plane.get());
    CHECK(root->getChild(1) == plane.get());
    CHECK(plane->plane().distance == doctest::Approx(1.0).epsilon(1e-5));
    CHECK_FALSE(manip->isAttached());
}

TEST_CASE("dragging the clip-plane knob turns the normal about the handle centre") {
    auto root = Separator::create();
    auto plane = ClipPlane::create();
    plane->plane = Plane{glm::vec3(0.0f, 0.0f, 1.0f), 0.0f};
    root->addChild(plane);
    auto manip = ClipPlaneManip::create();
    REQUIRE(manip->attach(*root, *plane));
    manip->setHandleSize(10.0); // arm 3.5 long: the knob is at (0, 0, 3.5), radius 0.35
    // A ray from the side (along -x) through the knob.
    const Ray atKnob{{20.0, 0.0, 3.5}, {-1.0, 0.0, 0.0}};
    const auto path = pickPath(*root, atKnob);
    REQUIRE(manip->beginDrag(atKnob, path));
    CHECK(manip->activePart() == ClipPlaneManip::Knob);
    // Drag to the point (0, 3.5 sin 30, 3.5 cos 30) of the trackball sphere (radius 3.5).
    const double a = glm::radians(30.0);
    manip->drag(Ray{{20.0, 3.5 * std::sin(a), 3.5 * std::cos(a)}, {-1.0, 0.0, 0.0}});
    const glm::dvec3 n(manip->plane().normal);
    CHECK(glm::length(n - glm::dvec3(0.0, std::sin(a), std::cos(a))) < 1e-5);
    CHECK(manip->plane().distance == doctest::Approx(0.0).epsilon(1e-6)); // through the centre
    manip->detach();
    CHECK(glm::length(glm::dvec3(plane->plane().normal) - n) < 1e-6);
}

TEST_CASE("box manipulator faces and corners move the box by the drag") {
    auto root = Separator::create();
    auto box = BoxClip::create();
    box->origin = glm::vec3(-1.0f);
    box->extent = glm::vec3(2.0f);
    root->addChild(box);
    auto manip = BoxClipManip::create();
    REQUIRE(manip->attach(*root, *box));
    manip->setHandleSize(4.0);

    // The +x face handle, seen obliquely (from the front an edge covers it): dragging the ray
    // 0.5 along x moves the face by 0.5.
    const Ray atFace = oblique(1.0, 0.0);
    auto path = pickPath(*root, atFace);
    REQUIRE(manip->beginDrag(atFace, path));
    CHECK(manip->activePart() == BoxClipManip::firstFace + 1);
    manip->drag(oblique(1.5, 0.3)); // y motion does not move an x face
    manip->endDrag();
    CHECK(box->origin().x == doctest::Approx(-1.0).epsilon(1e-6));
    CHECK(box->extent().x == doctest::Approx(2.5).epsilon(1e-6));
    CHECK(box->extent().y == doctest::Approx(2.0).epsilon(1e-6));

    // The (-x, -y, +z) corner (number 4), dragged in the view plane by (-0.5, -0.25).
    const Ray atCorner = downZ(-1.0, -1.0);
    path = pickPath(*root, atCorner);
    REQUIRE(manip->beginDrag(atCorner, path));
    CHECK(manip->activePart() == BoxClipManip::firstCorner + 4);
    manip->drag(downZ(-1.5, -1.25));
    manip->endDrag();
    CHECK(box->origin().x == doctest::Approx(-1.5).epsilon(1e-6));
    CHECK(box->origin().y == doctest::Approx(-1.25).epsilon(1e-6));
    CHECK(box->extent().x == doctest::Approx(3.0).epsilon(1e-6)); // max x 1.5 stays
    CHECK(box->extent().y == doctest::Approx(2.25).epsilon(1e-6));
    CHECK(box->origin().z == doctest::Approx(-1.0).epsilon(1e-6)); // view-plane drag: no z
    CHECK(box->extent().z == doctest::Approx(2.0).epsilon(1e-6));

    // A face can not be dragged through the opposite one.
    path = pickPath(*root, oblique(1.5, -0.125));
    REQUIRE(manip->beginDrag(oblique(1.5, -0.125), path));
    CHECK(manip->activePart() == BoxClipManip::firstFace + 1);
    manip->drag(oblique(-10.0, -0.125));
    CHECK(box->extent().x == doctest::Approx(BoxClipManip::minimumExtent).epsilon(1e-3));
    manip->detach();
}

TEST_CASE("transform manipulator arrows translate and the ball rotates about the pivot") {
    auto root = Separator::create();
    auto transform = Transform::create();
    transform->translation = glm::vec3(1.0f, 0.0f, 0.0f);
    root->addChild(transform);
    auto manip = TransformManip::create();
    REQUIRE(manip->attach(*root, *transform));
    manip->setHandleSize(4.0); // ball radius 1, arrows 2 long from the pivot (1, 0, 0)

    // The y arrow's tip cone spans y in [1.6, 2.0]; grab its shaft at y = 1.4, seen from +z.
    const Ray atArrow = downZ(1.0, 1.4);
    auto path = pickPath(*root, atArrow);
    REQUIRE(manip->beginDrag(atArrow, path));
    CHECK(manip->activePart() == TransformManip::ShaftY);
    manip->drag(downZ(1.3, 2.15)); // x motion ignored: only y follows
    manip->endDrag();
    CHECK(glm::length(glm::dvec3(transform->translation()) - glm::dvec3(1.0, 0.75, 0.0)) < 1e-5);

    // The ball: pivot now (1, 0.75, 0), radius 1. Grab its front pole, drag to 30 degrees right.
    const glm::dvec3 pivot(1.0, 0.75, 0.0);
    const Ray front{pivot + glm::dvec3(0.0, -0.5, 10.0), {0.0, 0.0, -1.0}};
    path = pickPath(*root, front);
    REQUIRE(manip->beginDrag(front, path));
    CHECK(manip->activePart() == TransformManip::Ball);
    const glm::dvec3 grabbed = trackballPoint(front, pivot, 1.0);
    const glm::dvec3 target =
        pivot + glm::dvec3(std::sin(glm::radians(30.0)), grabbed.y - pivot.y, 0.0);
    // A ray down -z through the target's x and y lands on the sphere's near side there.
    manip->drag(Ray{{target.x, target.y, 10.0}, {0.0, 0.0, -1.0}});
    manip->endDrag();
    const glm::dquat q = transform->rotation().quat();
    const glm::dvec3 expectedTo =
        trackballPoint(Ray{{target.x, target.y, 10.0}, {0, 0, -1}}, pivot, 1.0) - pivot;
    CHECK(glm::length(q * (grabbed - pivot) - expectedTo) < 1e-4);
    // A rotation about the pivot leaves the translation alone (center is 0).
    CHECK(glm::length(glm::dvec3(transform->translation()) - glm::dvec3(1.0, 0.75, 0.0)) < 1e-5);
    manip->detach();
    CHECK(root->getChild(0) == transform.get());
}

TEST_CASE("a scene saved after detaching holds plain nodes with only the fields that were set") {
    ref_ptr<Node> root = readSceneFromString("#Inventor V2.1 ascii\n"
                                             "Separator { DEF clip ClipPlane { } Cube { } }\n");
    auto* plane = static_cast<ClipPlane*>(root->children()->at(0).get());
    auto manip = ClipPlaneManip::create();
    REQUIRE(manip->attach(*root, *plane));
    manip->setHandleSize(2.0);
    // Untouched, the plane stays default: writing back keeps the field unset.
    manip->detach();
    CHECK(plane->plane.isDefault());
    const std::string text = writeSceneToString(*root);
    CHECK(text.find("ClipPlaneManip") == std::string::npos);
    CHECK(text.find("plane") == std::string::npos);
}

TEST_CASE("handles on the clipped side of a clip plane in scope can still be grabbed") {
    auto root = Separator::create();
    auto clip = ClipPlane::create();
    clip->plane = Plane{glm::vec3(-1.0f, 0.0f, 0.0f), -0.5f}; // keeps x <= 0.5
    root->addChild(clip);
    auto box = BoxClip::create();
    box->origin = glm::vec3(-1.0f);
    box->extent = glm::vec3(2.0f);
    root->addChild(box);
    auto manip = BoxClipManip::create();
    REQUIRE(manip->attach(*root, *box));
    manip->setHandleSize(4.0);
    // The +x face handle at x = 1 lies where the clip plane removes everything.
    const Ray atFace = oblique(1.0, 0.0);
    const auto path = pickPath(*root, atFace);
    REQUIRE(manip->beginDrag(atFace, path));
    CHECK(manip->activePart() == BoxClipManip::firstFace + 1);
    manip->drag(oblique(1.25, 0.0));
    CHECK(box->extent().x == doctest::Approx(2.25).epsilon(1e-6));
    manip->detach();
}
