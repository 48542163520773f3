// The examiner viewer's camera math: each navigation moves the camera as its analytic
// description says.
#include <doctest/doctest.h>

#include <cmath>

#include <volsg/manipulators/ExaminerNavigation.h>

using namespace volsg;

namespace {
ref_ptr<PerspectiveCamera> cameraAt(double z, double focal) {
    auto camera = PerspectiveCamera::create();
    camera->position = glm::vec3(0.0f, 0.0f, float(z));
    camera->focalDistance = float(focal);
    camera->heightAngle = float(glm::radians(60.0));
    return camera;
}
} // namespace

TEST_CASE("a horizontal trackball drag orbits the camera about the focal point") {
    ExaminerNavigation nav(cameraAt(5.0, 5.0), 400, 400);
    // From the centre to the right: the scene turns about +y, the camera moves to -x.
    nav.rotate({200.0, 200.0}, {260.0, 200.0});
    const glm::dvec3 p(nav.camera().position());
    CHECK(glm::length(nav.focalPoint()) < 1e-5);                        // focus stays put
    CHECK(glm::length(p) == doctest::Approx(5.0).epsilon(1e-5));        // same distance
    CHECK(p.x < -0.5);                                                  // went left
    CHECK(std::abs(p.y) < 1e-5);                                        // no vertical part
    CHECK(glm::length(nav.viewDirection() + glm::normalize(p)) < 1e-5); // still looks at it
    // Bell's trackball: the angle between the two sphere vectors (r = 0.8 of 200 px).
    const glm::dvec3 a(0.0, 0.0, 0.8), b(0.3, 0.0, std::sqrt(0.64 - 0.09));
    const double expected = std::acos(glm::dot(a, b) / (glm::length(a) * glm::length(b)));
    CHECK(std::atan2(-p.x, p.z) == doctest::Approx(expected).epsilon(1e-5));
    // Dragging back returns the camera where it was.
    nav.rotate({260.0, 200.0}, {200.0, 200.0});
    CHECK(glm::length(glm::dvec3(nav.camera().position()) - glm::dvec3(0, 0, 5)) < 1e-4);
}

TEST_CASE("panning moves the focal point with the mouse at the focal distance") {
    ExaminerNavigation nav(cameraAt(5.0, 5.0), 400, 200); // wider than tall
    nav.pan({100.0, 100.0}, {140.0, 80.0});
    // 60 degrees high at distance 5: 2 * 5 * tan 30 world units over 200 pixels.
    const double perPixel = 2.0 * 5.0 * std::tan(glm::radians(30.0)) / 200.0;
    const glm::dvec3 p(nav.camera().position());
    CHECK(p.x == doctest::Approx(-40.0 * perPixel).epsilon(1e-5)); // scene right: camera left
    CHECK(p.y == doctest::Approx(-20.0 * perPixel).epsilon(1e-5)); // mouse up: camera down
    CHECK(p.z == doctest::Approx(5.0).epsilon(1e-6));
}

TEST_CASE("dolly halves the distance to the focal point and zoom narrows the angle") {
    ExaminerNavigation nav(cameraAt(8.0, 6.0), 300, 300); // focus at z = 2
    nav.dolly(0.5);
    CHECK(nav.camera().position().z == doctest::Approx(5.0).epsilon(1e-6));
    CHECK(nav.camera().focalDistance() == doctest::Approx(3.0).epsilon(1e-6));
    CHECK(nav.focalPoint().z == doctest::Approx(2.0).epsilon(1e-6));
    nav.zoom(0.5);
    CHECK(static_cast<PerspectiveCamera&>(nav.camera()).heightAngle() ==
          doctest::Approx(glm::radians(30.0)).epsilon(1e-6));
}

TEST_CASE("seek moves half way to the picked point and focuses on it") {
    ExaminerNavigation nav(cameraAt(10.0, 10.0), 300, 300);
    nav.seek({1.0, 0.0, 2.0});
    // 8 units along the view to the point: half way leaves 4.
    CHECK(nav.camera().focalDistance() == doctest::Approx(4.0).epsilon(1e-6));
    CHECK(glm::length(nav.focalPoint() - glm::dvec3(1.0, 0.0, 2.0)) < 1e-5);
}

TEST_CASE("the projection toggle keeps the visible height at the focal distance") {
    ExaminerNavigation nav(cameraAt(5.0, 4.0), 300, 300);
    nav.toggleProjection();
    REQUIRE(nav.isOrthographic());
    const double expectedHeight = 2.0 * 4.0 * std::tan(glm::radians(30.0));
    CHECK(static_cast<OrthographicCamera&>(nav.camera()).height() ==
          doctest::Approx(expectedHeight).epsilon(1e-5));
    CHECK(nav.camera().position().z == doctest::Approx(5.0).epsilon(1e-6));
    nav.toggleProjection();
    REQUIRE_FALSE(nav.isOrthographic());
    CHECK(static_cast<PerspectiveCamera&>(nav.camera()).heightAngle() ==
          doctest::Approx(glm::radians(60.0)).epsilon(1e-5));
}

TEST_CASE("home restores the camera saved at the start after any navigation") {
    ExaminerNavigation nav(cameraAt(5.0, 5.0), 300, 300);
    nav.rotate({150.0, 150.0}, {200.0, 120.0});
    nav.dolly(0.3);
    nav.toggleProjection();
    nav.goHome();
    CHECK_FALSE(nav.isOrthographic());
    CHECK(glm::length(glm::dvec3(nav.camera().position()) - glm::dvec3(0, 0, 5)) < 1e-6);
    CHECK(nav.camera().orientation().angle == 0.0f);
    CHECK(nav.camera().focalDistance() == doctest::Approx(5.0).epsilon(1e-6));
}

TEST_CASE("view all puts the whole box in front of the camera and clipping brackets it") {
    ExaminerNavigation nav(cameraAt(5.0, 5.0), 300, 300);
    Box3 box;
    box.extendBy(glm::dvec3(9.0, 9.0, -1.0));
    box.extendBy(glm::dvec3(11.0, 11.0, 1.0));
    nav.viewAll(box);
    nav.adjustClipping(box);
    const double r = 0.5 * glm::length(box.size());
    const double d = glm::length(box.center() - glm::dvec3(nav.camera().position()));
    CHECK(d * std::sin(glm::radians(30.0)) == doctest::Approx(r).epsilon(1e-5)); // fits the angle
    CHECK(nav.camera().nearDistance() <= d - r);
    CHECK(nav.camera().farDistance() >= d + r);
}

TEST_CASE("the pixel ray through the centre is the view axis") {
    ExaminerNavigation nav(cameraAt(5.0, 5.0), 200, 100);
    const Ray centre = nav.pixelRay({100.0, 50.0});
    CHECK(glm::length(centre.direction - glm::dvec3(0, 0, -1)) < 1e-9);
    CHECK(std::abs(centre.origin.x) < 1e-9);
    // The top edge's centre is heightAngle / 2 above the axis.
    const Ray top = nav.pixelRay({100.0, 0.0});
    CHECK(std::atan2(top.direction.y, -top.direction.z) ==
          doctest::Approx(glm::radians(30.0)).epsilon(1e-6));
}

TEST_CASE("an animated seek starts at the camera and ends exactly where the instant seek goes") {
    auto tilted = [] {
        auto camera = cameraAt(10.0, 10.0);
        camera->position = glm::vec3(1.0f, 2.0f, 9.0f);
        camera->orientation = Rotation{glm::vec3(1.0f, 1.0f, 0.0f), 0.3f};
        return camera;
    };
    const glm::dvec3 point(1.5, 2.5, 1.0);
    ExaminerNavigation instant(tilted(), 300, 300);
    instant.seek(point);
    ExaminerNavigation animated(tilted(), 300, 300);
    const glm::dvec3 start(animated.camera().position());
    REQUIRE(animated.startSeek(point, 0.5, 0.5));
    CHECK(animated.isSeeking());
    // t = 0 is the camera as it was (position within float rounding, 1e-6 relative).
    const CameraPose p0 = animated.seekPose(0.0);
    CHECK(glm::length(p0.position - start) < 1e-5);
    CHECK(std::abs(glm::dot(p0.orientation, animated.camera().orientation().quat())) ==
          doctest::Approx(1.0).epsilon(1e-9));
    CHECK(p0.focalDistance == doctest::Approx(10.0).epsilon(1e-9));

    // 1/30 s frames: the distance to the picked point shrinks at every step, the orientation
    // stays a unit quaternion, and after 0.5 s the seek is over.
    double last = glm::length(start - point);
    int frames = 0;
    while (animated.stepSeek(1.0 / 30.0)) {
        ++frames;
        const double d = glm::length(glm::dvec3(animated.camera().position()) - point);
        CHECK(d < last);
        last = d;
        CHECK(glm::length(animated.seekPose(frames / 30.0).orientation) ==
              doctest::Approx(1.0).epsilon(1e-12));
        REQUIRE(frames < 100);
    }
    CHECK(frames == 14); // the 15th frame reaches t = 0.5 and ends it
    CHECK_FALSE(animated.isSeeking());
    // The end: bit for bit the fields the instant seek sets.
    CHECK(animated.camera().position() == instant.camera().position());
    CHECK(animated.camera().focalDistance() == instant.camera().focalDistance());
    CHECK(animated.camera().orientation().axis == instant.camera().orientation().axis);
    CHECK(animated.camera().orientation().angle == instant.camera().orientation().angle);
    CHECK(glm::length(animated.focalPoint() - point) < 1e-5);
}

TEST_CASE("seek easing and pose interpolation start and stop at rest on unit quaternions") {
    CHECK(seekEasing(0.0) == 0.0);
    CHECK(seekEasing(1.0) == 1.0);
    CHECK(seekEasing(0.5) == doctest::Approx(0.5).epsilon(1e-12));
    CHECK(seekEasing(0.01) < 0.001); // slope 0 at the ends: 3 s^2
    CHECK(seekEasing(-1.0) == 0.0);
    CHECK(seekEasing(2.0) == 1.0);
    // A quarter turn about y between two poses: half way is an eighth turn, unit length.
    CameraPose a, b;
    a.position = glm::dvec3(0.0, 0.0, 4.0);
    b.position = glm::dvec3(4.0, 0.0, 0.0);
    b.orientation = glm::angleAxis(glm::radians(90.0), glm::dvec3(0.0, 1.0, 0.0));
    a.focalDistance = 4.0;
    b.focalDistance = 2.0;
    for (double s = 0.0; s <= 1.0; s += 0.125) {
        const CameraPose p = interpolatePose(a, b, s);
        CHECK(glm::length(p.orientation) == doctest::Approx(1.0).epsilon(1e-12));
        CHECK(glm::angle(p.orientation) == doctest::Approx(s * glm::radians(90.0)).epsilon(1e-9));
        CHECK(p.focalDistance == doctest::Approx(4.0 - 2.0 * s).epsilon(1e-12));
    }
    // The negated (same) end orientation goes the same, shorter, way.
    CameraPose c = b;
    c.orientation = -b.orientation;
    CHECK(glm::angle(interpolatePose(a, c, 0.5).orientation) ==
          doctest::Approx(glm::radians(45.0)).epsilon(1e-9));
}

TEST_CASE("a seek to a point behind the camera does nothing and navigation stops a seek") {
    ExaminerNavigation nav(cameraAt(10.0, 10.0), 300, 300);
    CHECK_FALSE(nav.startSeek({0.0, 0.0, 12.0}));
    CHECK_FALSE(nav.isSeeking());
    CHECK(nav.camera().position().z == 10.0f);
    REQUIRE(nav.startSeek({0.0, 0.0, 2.0}, 0.5, 1.0));
    nav.stepSeek(0.5);
    const float half = nav.camera().position().z;
    CHECK(half == doctest::Approx(8.0).epsilon(1e-6)); // smoothstep(0.5): half way, z 10 -> 6
    nav.dolly(0.5);
    CHECK_FALSE(nav.isSeeking());
    CHECK_FALSE(nav.stepSeek(0.5)); // nothing left to run
    // A zero duration seeks at once.
    REQUIRE(nav.startSeek({0.0, 0.0, 2.0}, 0.5, 0.0));
    CHECK_FALSE(nav.isSeeking());
    CHECK(glm::length(nav.focalPoint() - glm::dvec3(0.0, 0.0, 2.0)) < 1e-5);
}
