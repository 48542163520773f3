// The manipulators' geometry: rays against planes, boxes and spheres, line projection, the
// trackball point and rotations between directions.
#include <doctest/doctest.h>

#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include <volsg/manipulators/DragMath.h>

using namespace volsg;

TEST_CASE("a ray meets a plane at the analytic parameter") {
    const Ray ray{{0.0, 0.0, 5.0}, {0.0, 0.0, -2.0}};
    const auto t = intersectRayPlane(ray, {0.0, 0.0, 1.0}, 1.0);
    REQUIRE(t.has_value());
    CHECK(*t == doctest::Approx(2.0).epsilon(1e-12));                      // 5 - 2 * 2 = 1
    CHECK_FALSE(intersectRayPlane(ray, {1.0, 0.0, 0.0}, 0.0).has_value()); // parallel
    CHECK_FALSE(intersectRayPlane(ray, {0.0, 0.0, 1.0}, 6.0).has_value()); // behind
}

TEST_CASE("a ray enters a box through the face it points at") {
    Box3 box;
    box.extendBy(glm::dvec3(-1.0));
    box.extendBy(glm::dvec3(1.0, 2.0, 3.0));
    const auto fromRight = intersectRayBox({{5.0, 0.5, 0.5}, {-1.0, 0.0, 0.0}}, box);
    REQUIRE(fromRight.has_value());
    CHECK(fromRight->face == 1); // +x
    CHECK(fromRight->t == doctest::Approx(4.0).epsilon(1e-12));
    const auto fromBelow = intersectRayBox({{0.0, -4.0, 0.0}, {0.0, 0.5, 0.0}}, box);
    REQUIRE(fromBelow.has_value());
    CHECK(fromBelow->face == 2); // -y
    CHECK(fromBelow->t == doctest::Approx(6.0).epsilon(1e-12));
    const auto inside = intersectRayBox({{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}}, box);
    REQUIRE(inside.has_value());
    CHECK(inside->face == 5); // leaves through +z
    CHECK(inside->t == doctest::Approx(3.0).epsilon(1e-12));
    CHECK_FALSE(intersectRayBox({{5.0, 5.0, 0.0}, {-1.0, 0.0, 0.0}}, box).has_value());
}

TEST_CASE("a ray meets a sphere at its near side") {
    const auto t = intersectRaySphere({{0.0, 0.0, 10.0}, {0.0, 0.0, -1.0}}, {0.0, 0.0, 0.0}, 2.0);
    REQUIRE(t.has_value());
    CHECK(*t == doctest::Approx(8.0).epsilon(1e-12));
    CHECK_FALSE(intersectRaySphere({{3.0, 0.0, 10.0}, {0.0, 0.0, -1.0}}, {}, 2.0).has_value());
}

TEST_CASE("dragging along a line follows the mouse ray's closest point") {
    // Line: the x axis. A ray looking down -z through (2.5, 1, 10) is closest at x = 2.5.
    const auto s = closestLineParameter({{2.5, 1.0, 10.0}, {0.0, 0.0, -1.0}}, {0.0, 0.0, 0.0},
                                        {1.0, 0.0, 0.0});
    REQUIRE(s.has_value());
    CHECK(*s == doctest::Approx(2.5).epsilon(1e-12));
    // A direction of length 2 counts in its own units.
    const auto s2 = closestLineParameter({{2.5, 1.0, 10.0}, {0.0, 0.0, -1.0}}, {0.0, 0.0, 0.0},
                                         {2.0, 0.0, 0.0});
    REQUIRE(s2.has_value());
    CHECK(*s2 == doctest::Approx(1.25).epsilon(1e-12));
    // An oblique ray: the closest point is where the common perpendicular lands.
    const auto s3 =
        closestLineParameter({{0.0, 3.0, 1.0}, {1.0, 0.0, -1.0}}, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0});
    REQUIRE(s3.has_value());
    CHECK(*s3 == doctest::Approx(1.0).epsilon(1e-12)); // the ray crosses z = 0 at x = 1
    CHECK_FALSE(
        closestLineParameter({{0.0, 0.0, 5.0}, {0.0, 0.0, -1.0}}, {}, {0.0, 0.0, 1.0}).has_value());
}

TEST_CASE("the trackball point lies on the sphere, on the silhouette for a miss") {
    const glm::dvec3 c(1.0, 2.0, 3.0);
    const glm::dvec3 hit = trackballPoint({{1.0, 2.0, 13.0}, {0.0, 0.0, -1.0}}, c, 2.0);
    CHECK(glm::length(hit - glm::dvec3(1.0, 2.0, 5.0)) < 1e-12);
    const glm::dvec3 miss = trackballPoint({{6.0, 2.0, 13.0}, {0.0, 0.0, -1.0}}, c, 2.0);
    CHECK(glm::length(miss - c) == doctest::Approx(2.0).epsilon(1e-12));
    CHECK(glm::length(miss - glm::dvec3(3.0, 2.0, 3.0)) < 1e-12);
}

TEST_CASE("rotationBetween turns one direction exactly into the other") {
    const glm::dvec3 pairs[][2] = {{{1, 0, 0}, {0, 1, 0}},
                                   {{0, 0, 1}, {0.3, -0.4, 2.0}},
                                   {{1, 2, 3}, {-1, -2, -3}}, // opposite: a half turn
                                   {{0, 1, 0}, {0, 5, 0}}};
    for (const auto& p : pairs) {
        const glm::dquat q = rotationBetween(p[0], p[1]);
        const glm::dvec3 turned = q * glm::normalize(p[0]);
        CHECK(glm::length(turned - glm::normalize(p[1])) < 1e-9);
        CHECK(glm::length(q) == doctest::Approx(1.0).epsilon(1e-12));
    }
}

TEST_CASE("rotationFromQuat gives the axis and angle a quaternion was made of") {
    const glm::dquat q = glm::angleAxis(1.2, glm::normalize(glm::dvec3(1.0, 2.0, -2.0)));
    const Rotation r = rotationFromQuat(q);
    CHECK(r.angle == doctest::Approx(1.2).epsilon(1e-6));
    const glm::dvec3 axis = glm::normalize(glm::dvec3(1.0, 2.0, -2.0));
    CHECK(glm::length(glm::dvec3(r.axis) - axis) < 1e-6);
    // The same rotation written with the other sign of the quaternion gives the same turn.
    const Rotation back = rotationFromQuat(-q);
    CHECK(back.angle == doctest::Approx(1.2).epsilon(1e-6));
    CHECK(rotationFromQuat(glm::dquat(1.0, 0.0, 0.0, 0.0)).angle == 0.0f);
}
