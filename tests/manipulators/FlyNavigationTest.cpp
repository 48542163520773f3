// The fly viewer's camera math: after N steps of known steering and speed the camera is where
// the analytic path says.
#include <doctest/doctest.h>

#include <cmath>

#include <glm/gtc/constants.hpp>

#include <volsg/manipulators/FlyNavigation.h>

using namespace volsg;

namespace {
ref_ptr<PerspectiveCamera> cameraAt(const glm::vec3& position) {
    auto camera = PerspectiveCamera::create();
    camera->position = position; // default orientation: looking along -z, up +y
    return camera;
}
glm::dvec3 forwardOf(const Camera& c) {
    return c.orientation().quat() * glm::dvec3(0.0, 0.0, -1.0);
}
glm::dvec3 upOf(const Camera& c) {
    return c.orientation().quat() * glm::dvec3(0.0, 1.0, 0.0);
}
} // namespace

TEST_CASE("speed steps go from rest to the base speed, double, and come back to rest") {
    FlyNavigation fly(cameraAt({0, 0, 0}));
    fly.setBaseSpeed(0.5);
    CHECK(fly.speed() == 0.0);
    fly.speedUp();
    CHECK(fly.speed() == doctest::Approx(0.5).epsilon(1e-12));
    fly.speedUp();
    CHECK(fly.speed() == doctest::Approx(1.0).epsilon(1e-12));
    fly.slowDown();
    fly.slowDown();
    CHECK(fly.speed() == 0.0); // half of the base speed is rest
    fly.slowDown();
    CHECK(fly.speed() == doctest::Approx(-0.5).epsilon(1e-12)); // backwards
    fly.speedUp();
    CHECK(fly.speed() == 0.0);
}

TEST_CASE("with the mouse at the centre the camera flies straight along its view") {
    FlyNavigation fly(cameraAt({1, 2, 3}), 400, 300);
    fly.setBaseSpeed(2.0);
    fly.speedUp();
    fly.speedUp(); // 4 units per second
    for (int i = 0; i < 50; ++i)
        fly.step({200.0, 150.0}, 0.02); // 50 steps of 20 ms: one second
    const glm::dvec3 p(fly.camera().position());
    CHECK(p.x == doctest::Approx(1.0).epsilon(1e-6));
    CHECK(p.y == doctest::Approx(2.0).epsilon(1e-6));
    CHECK(p.z == doctest::Approx(3.0 - 4.0).epsilon(1e-5));
    CHECK(glm::length(forwardOf(fly.camera()) - glm::dvec3(0, 0, -1)) < 1e-6);
}

TEST_CASE("steering at the right edge flies a closed polygon back to the start") {
    // Turn then move: N steps of angle t = kTurnRate * dt with N t = 2 pi visit the corners of
    // a regular N-gon with side v dt, so the camera comes back to where it began, and the
    // farthest corner (after N/2 steps) is the circumscribed circle's diameter away.
    FlyNavigation fly(cameraAt({0, 0, 0}), 400, 300);
    const int n = 64;
    const double t = 2.0 * glm::pi<double>() / n, dt = t / FlyNavigation::kTurnRate;
    fly.setBaseSpeed(1.5);
    fly.speedUp();
    const glm::dvec2 rightEdge(400.0, 150.0);
    double farthest = 0.0;
    for (int i = 0; i < n; ++i) {
        fly.step(rightEdge, dt);
        farthest = std::max(farthest, glm::length(glm::dvec3(fly.camera().position())));
        CHECK(std::abs(fly.camera().position().y) < 1e-6); // level flight
    }
    const double side = 1.5 * dt, diameter = side / std::sin(0.5 * t);
    CHECK(glm::length(glm::dvec3(fly.camera().position())) < 1e-4);
    CHECK(farthest == doctest::Approx(diameter).epsilon(1e-4));
    // Steering right turns right: the first corner lies at -z, bent towards +x.
    FlyNavigation once(cameraAt({0, 0, 0}), 400, 300);
    once.setBaseSpeed(1.0);
    once.speedUp();
    once.step(rightEdge, 0.1);
    CHECK(once.camera().position().x == doctest::Approx(0.1 * std::sin(0.1)).epsilon(1e-5));
    CHECK(once.camera().position().z == doctest::Approx(-0.1 * std::cos(0.1)).epsilon(1e-5));
}

TEST_CASE("steering up raises the nose without rolling and stops short of the zenith") {
    FlyNavigation fly(cameraAt({0, 0, 0}), 200, 200);
    fly.step({100.0, 0.0}, 0.3); // top edge: 0.3 rad up
    const glm::dvec3 f = forwardOf(fly.camera());
    CHECK(std::asin(f.y) == doctest::Approx(0.3).epsilon(1e-5));
    CHECK(std::abs(f.x) < 1e-6);
    CHECK(std::abs(glm::dot(glm::cross(forwardOf(fly.camera()), upOf(fly.camera())),
                            glm::dvec3(0, 1, 0))) < 1e-6); // the camera's x axis stays level
    for (int i = 0; i < 20; ++i)
        fly.step({100.0, 0.0}, 0.5);
    CHECK(std::asin(forwardOf(fly.camera()).y) ==
          doctest::Approx(FlyNavigation::kMaxElevation).epsilon(1e-5));
}
