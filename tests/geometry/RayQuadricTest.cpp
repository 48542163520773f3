// The exact ray crossings of the sphere, cylinder and cone (what picking reports), against
// hand-computed points: each hit lies on its surface, within its part, with the outward normal.
#include <doctest/doctest.h>

#include <cmath>

#include <volsg/geometry/RayQuadric.h>

using namespace volsg;

TEST_CASE("A ray through a sphere's centre crosses it at both poles of its path") {
    const auto hits = intersectSphere(Ray{{0, 0, 10}, {0, 0, -1}}, 2.0);
    REQUIRE(hits.size() == 2);
    CHECK(hits[0].t == doctest::Approx(8.0));
    CHECK(hits[1].t == doctest::Approx(12.0));
    CHECK(hits[0].normal.z == doctest::Approx(1.0));
    CHECK(hits[1].normal.z == doctest::Approx(-1.0));
    // Off-centre at x = 0.6 of a unit sphere: z = +-0.8, normal (0.6, 0, 0.8).
    const auto side = intersectSphere(Ray{{0.6, 0, 5}, {0, 0, -1}}, 1.0);
    REQUIRE(side.size() == 2);
    CHECK(side[0].point.z == doctest::Approx(0.8));
    CHECK(side[0].normal.x == doctest::Approx(0.6));
    CHECK(intersectSphere(Ray{{1.01, 0, 5}, {0, 0, -1}}, 1.0).empty());
    // A transformed ray is not unit length; t stays the parameter along it.
    const auto scaled = intersectSphere(Ray{{0, 0, 10}, {0, 0, -2}}, 2.0);
    REQUIRE(scaled.size() == 2);
    CHECK(scaled[0].t == doctest::Approx(4.0));
    CHECK(intersectSphere(Ray{{0, 0, 10}, {0, 0, -1}}, 0.0).empty());
    CHECK(intersectSphere(Ray{{0, 0, 10}, {0, 0, -1}}, std::nan("")).empty());
}

TEST_CASE("A cylinder's side stops at its height, its caps are discs") {
    // Radius 1, height 2: a horizontal ray at y = 0.5 crosses the side at x = +-1.
    const auto side = intersectCylinderSide(Ray{{5, 0.5, 0}, {-1, 0, 0}}, 1.0, 2.0);
    REQUIRE(side.size() == 2);
    CHECK(side[0].point.x == doctest::Approx(1.0));
    CHECK(side[0].normal.x == doctest::Approx(1.0));
    CHECK(side[0].normal.y == 0.0);
    // Above the top (y = 1.5) it misses the side.
    CHECK(intersectCylinderSide(Ray{{5, 1.5, 0}, {-1, 0, 0}}, 1.0, 2.0).empty());
    // Down the axis: no side crossing (parallel), the top disc at y = 1.
    CHECK(intersectCylinderSide(Ray{{0, 5, 0}, {0, -1, 0}}, 1.0, 2.0).empty());
    const auto top = intersectDisc(Ray{{0.5, 5, 0}, {0, -1, 0}}, 1.0, 1.0, 1.0);
    REQUIRE(top.size() == 1);
    CHECK(top[0].t == doctest::Approx(4.0));
    CHECK(top[0].normal.y == 1.0);
    CHECK(intersectDisc(Ray{{1.5, 5, 0}, {0, -1, 0}}, 1.0, 1.0, 1.0).empty());
}

TEST_CASE("A cone's side narrows to its apex") {
    // Bottom radius 1, height 2: the radius at y is (1 - y) / 2, so 0.25 at y = 0.5.
    const auto hits = intersectConeSide(Ray{{5, 0.5, 0}, {-1, 0, 0}}, 1.0, 2.0);
    REQUIRE(hits.size() == 2);
    CHECK(hits[0].point.x == doctest::Approx(0.25));
    CHECK(hits[1].point.x == doctest::Approx(-0.25));
    // The outward normal leans up by the half-angle: (2, 1, 0) / sqrt 5.
    CHECK(hits[0].normal.x == doctest::Approx(2.0 / std::sqrt(5.0)));
    CHECK(hits[0].normal.y == doctest::Approx(1.0 / std::sqrt(5.0)));
    // Above the apex the mirrored cone is not part of it; below the base neither.
    CHECK(intersectConeSide(Ray{{5, 1.5, 0}, {-1, 0, 0}}, 1.0, 2.0).empty());
    CHECK(intersectConeSide(Ray{{5, -1.5, 0}, {-1, 0, 0}}, 1.0, 2.0).empty());
    // Down the axis: the apex.
    const auto apex = intersectConeSide(Ray{{0, 5, 0}, {0, -1, 0}}, 1.0, 2.0);
    REQUIRE(!apex.empty());
    CHECK(apex[0].point.y == doctest::Approx(1.0));
}
