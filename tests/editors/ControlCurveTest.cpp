// Control-point editing, freehand simplification and linear segments of ControlCurve.
#include <doctest/doctest.h>

#include <cmath>

#include <volsg/editors/ControlCurve.h>

using namespace volsg;

TEST_CASE("adding points keeps them sorted and replaces a point at the same x") {
    ControlCurve c({{0, 0}, {1, 1}});
    CHECK(c.add({0.5f, 0.9f}) == 1);
    CHECK(c.add({0.25f, 0.1f}) == 1);
    REQUIRE(c.points().size() == 4);
    CHECK(c.points()[2] == glm::vec2(0.5f, 0.9f));
    CHECK(c.add({0.5f, 0.2f}) == 2); // same x: replaced, not added
    CHECK(c.points().size() == 4);
    CHECK(c.points()[2].y == 0.2f);
    CHECK(c.add({1.5f, 2.0f}) == 3); // clamped into [0, 1] x [0, 1]: replaces (1, 1)
    CHECK(c.points()[3] == glm::vec2(1.0f, 1.0f));
    CHECK(c.valueAt(0.375f) == doctest::Approx(0.15f).epsilon(1e-6));
}

TEST_CASE("a moved point stays between its neighbours and deleting keeps one point") {
    ControlCurve c({{0, 0}, {0.5f, 0.5f}, {1, 1}});
    c.move(1, {0.9f, 0.7f});
    CHECK(c.points()[1] == glm::vec2(0.9f, 0.7f));
    c.move(1, {1.2f, -3.0f}); // past the right neighbour, below the range
    CHECK(c.points()[1].x == doctest::Approx(1.0f - ControlCurve::minimumGap).epsilon(1e-6));
    CHECK(c.points()[1].y == 0.0f);
    CHECK(c.points()[0].x < c.points()[1].x);
    CHECK(c.points()[1].x < c.points()[2].x);
    CHECK(c.remove(0));
    CHECK(c.remove(0));
    CHECK_FALSE(c.remove(0)); // the last point stays
    CHECK(c.points().size() == 1);
}

TEST_CASE("the nearest point is found within a pixel radius") {
    ControlCurve c({{0, 0}, {0.5f, 0.5f}, {1, 1}});
    const glm::vec2 pixels(200.0f, 100.0f);              // a 200 x 100 canvas
    CHECK(c.nearest({0.52f, 0.47f}, 6.0f, pixels) == 1); // 4 px right, 3 px down: 5 px away
    CHECK(c.nearest({0.55f, 0.5f}, 6.0f, pixels) == -1); // 10 px away
}

TEST_CASE("a line replaces the points between its ends") {
    ControlCurve c({{0, 0}, {0.3f, 0.8f}, {0.5f, 0.1f}, {0.7f, 0.9f}, {1, 1}});
    c.drawLine({0.6f, 0.2f}, {0.2f, 0.6f}); // drawn right to left
    REQUIRE(c.points().size() == 5);
    CHECK(c.points()[1] == glm::vec2(0.2f, 0.6f));
    CHECK(c.points()[2] == glm::vec2(0.6f, 0.2f));
    CHECK(c.valueAt(0.4f) == doctest::Approx(0.4f).epsilon(1e-6));
    CHECK(c.points()[3] == glm::vec2(0.7f, 0.9f)); // outside the line: kept
}

TEST_CASE("simplification keeps every input point within the tolerance") {
    std::vector<glm::vec2> line;
    for (int i = 0; i <= 200; ++i) {
        const float x = float(i) / 200.0f;
        line.push_back({x, 0.5f + 0.4f * std::sin(6.0f * x)});
    }
    for (float tolerance : {0.001f, 0.01f, 0.05f}) {
        const auto simplified = ControlCurve::simplify(line, tolerance);
        CHECK(simplified.front() == line.front());
        CHECK(simplified.back() == line.back());
        CHECK(simplified.size() < line.size());
        const ControlCurve curve(simplified);
        float worst = 0.0f;
        for (const glm::vec2& p : line)
            worst = std::max(worst, std::abs(curve.valueAt(p.x) - p.y));
        CHECK(worst <= tolerance * 1.0001f);
    }
    // A straight stroke needs only its end points.
    const auto straight =
        ControlCurve::simplify({{0, 0}, {0.25f, 0.25f}, {0.5f, 0.5f}, {1, 1}}, 1e-4f);
    CHECK(straight.size() == 2);
}

TEST_CASE("a freehand stroke becomes a function of x over its span only") {
    ControlCurve c({{0, 0}, {0.1f, 0.9f}, {0.95f, 0.3f}, {1, 1}});
    // Drawn right to left with a wobble back: the last value drawn at an x wins.
    std::vector<glm::vec2> stroke;
    for (int i = 80; i >= 20; --i)
        stroke.push_back({float(i) / 100.0f, 0.5f});
    stroke.push_back({0.5f, 0.8f}); // drawn again at x = 0.5, later
    c.drawFreehand(stroke, 0.01f);
    CHECK(c.valueAt(0.5f) == doctest::Approx(0.8f).epsilon(1e-6));
    CHECK(c.valueAt(0.3f) == doctest::Approx(0.5f).epsilon(1e-6));
    CHECK(c.valueAt(0.8f) == doctest::Approx(0.5f).epsilon(1e-6));
    // Outside the stroke's span [0.2, 0.8] the old points stay.
    CHECK(c.points().front() == glm::vec2(0, 0));
    CHECK(c.points()[1] == glm::vec2(0.1f, 0.9f));
    CHECK(c.points()[c.points().size() - 2] == glm::vec2(0.95f, 0.3f));
    // Few points: the flat runs need only their ends.
    CHECK(c.points().size() <= 9);
}
