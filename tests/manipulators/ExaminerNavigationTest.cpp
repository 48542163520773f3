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
