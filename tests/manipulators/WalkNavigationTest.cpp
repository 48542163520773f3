// The walk viewer's camera math: the eye stays exactly at its height, turns are about the up
// direction, and N steps of known input end where the analytic path says.
#include <doctest/doctest.h>

#include <cmath>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

#include <volsg/manipulators/DragMath.h>
#include <volsg/manipulators/WalkNavigation.h>

using namespace volsg;

namespace {
/// At (1, 1.7, 2), looking along -z with up +y (the ground plane is y = 0).
ref_ptr<PerspectiveCamera> uprightCamera() {
    auto camera = PerspectiveCamera::create();
    camera->position = glm::vec3(1.0f, 1.7f, 2.0f);
    return camera;
}
} // namespace

TEST_CASE("walking forward follows the flattened view direction at the eye height") {
    auto camera = uprightCamera();
    WalkNavigation walk(camera, 300, 200);
    walk.tilt(glm::radians(-20.0)); // looking down: the path stays level
    walk.setWalkSpeed(0.8);
    CHECK(walk.eyeHeight() == doctest::Approx(1.7).epsilon(1e-6));
    CHECK(glm::length(walk.heading() - glm::dvec3(0, 0, -1)) < 1e-6);
    for (int i = 0; i < 40; ++i)
        walk.step({150.0, 0.0}, 0.05);   // top edge: full speed forwards for 2 s
    CHECK(camera->position().y == 1.7f); // exactly: the up is an axis
    CHECK(camera->position().x == doctest::Approx(1.0).epsilon(1e-6));
    CHECK(camera->position().z == doctest::Approx(2.0 - 1.6).epsilon(1e-5));
    CHECK(walk.elevation() == doctest::Approx(glm::radians(-20.0)).epsilon(1e-5)); // view kept
    walk.step({150.0, 200.0}, 0.5); // bottom edge: backwards
    CHECK(camera->position().z == doctest::Approx(0.4 + 0.4).epsilon(1e-5));
    CHECK(camera->position().y == 1.7f);
}

TEST_CASE("turning while walking circles back to the start at the same height") {
    auto camera = uprightCamera();
    WalkNavigation walk(camera, 300, 200);
    walk.tilt(glm::radians(10.0));
    walk.setWalkSpeed(1.0);
    // Mouse at the top-left corner: turn left at kTurnRate and walk at full speed. N steps of
    // turn-then-walk with N turns of 2 pi / N close a regular N-gon.
    const int n = 48;
    const double dt = 2.0 * glm::pi<double>() / n / WalkNavigation::kTurnRate;
    for (int i = 0; i < n; ++i) {
        walk.step({0.0, 0.0}, dt);
        CHECK(camera->position().y == 1.7f);
    }
    CHECK(glm::length(glm::dvec3(camera->position()) - glm::dvec3(1.0, 1.7, 2.0)) < 1e-4);
    CHECK(glm::length(walk.heading() - glm::dvec3(0, 0, -1)) < 1e-4);
    // A quarter turn to the left then a walk of 2 goes 2 along -x.
    walk.turn(0.5 * glm::pi<double>());
    walk.walk(2.0);
    CHECK(camera->position().x == doctest::Approx(-1.0).epsilon(1e-4));
    CHECK(camera->position().z == doctest::Approx(2.0).epsilon(1e-4));
    CHECK(camera->position().y == 1.7f);
}

TEST_CASE("the ground plane is perpendicular to the camera's up, even a tilted one") {
    auto camera = PerspectiveCamera::create();
    camera->position = glm::vec3(0.5f, -0.25f, 3.0f);
    // Up is +y turned 30 degrees about z: the ground plane is tilted with it.
    camera->orientation =
        rotationFromQuat(glm::angleAxis(glm::radians(30.0), glm::dvec3(0.0, 0.0, 1.0)));
    WalkNavigation walk(camera, 100, 100);
    const glm::dvec3 up = walk.upDirection();
    const double height = walk.eyeHeight();
    walk.turn(0.7);
    walk.walk(3.0);
    walk.tilt(-0.4);
    walk.walk(-1.25);
    CHECK(glm::dot(glm::dvec3(camera->position()), up) == doctest::Approx(height).epsilon(1e-6));
    CHECK(glm::length(glm::dvec3(camera->position()) - glm::dvec3(0.5, -0.25, 3.0)) ==
          doctest::Approx(1.75).epsilon(1e-5));
    CHECK(walk.elevation() == doctest::Approx(-0.4).epsilon(1e-5));
    walk.tilt(-3.0);
    CHECK(walk.elevation() == doctest::Approx(-WalkNavigation::kMaxTilt).epsilon(1e-5));
}
