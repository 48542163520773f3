// TransferFunction1D and PiecewiseLinear: exact piecewise-linear evaluation and normalisation.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include <volsg/core/Error.h>
#include <volsg/volume/TransferFunction1D.h>
#include <volsg/volume/VolumeGrid.h>

using namespace volsg;
using Point = PiecewiseLinear::Point;

TEST_CASE("the default transfer function is the identity on every channel") {
    TransferFunction1D tf;
    for (double v : {0.0, 0.125, 0.5, 0.9, 1.0})
        CHECK(tf.evaluate(v) == glm::dvec4(v));
    CHECK_FALSE(tf.dataRange().has_value());
}

TEST_CASE("control points are sorted by v and interpolated linearly") {
    TransferFunction1D tf;
    tf.setChannel(TransferFunction1D::Alpha, {{1.0, 0.0}, {0.0, 0.0}, {0.5, 0.8}});
    CHECK(tf.channel(TransferFunction1D::Alpha).points().front() == Point{0.0, 0.0});
    CHECK(tf.evaluate(TransferFunction1D::Alpha, 0.25) == doctest::Approx(0.4).epsilon(1e-15));
    CHECK(tf.evaluate(TransferFunction1D::Alpha, 0.5) == 0.8);
    CHECK(tf.evaluate(TransferFunction1D::Alpha, 0.75) == doctest::Approx(0.4).epsilon(1e-15));
}

TEST_CASE("channels are constant beyond their end points") {
    PiecewiseLinear f({{0.2, 0.3}, {0.6, 0.9}});
    CHECK(f(-5.0) == 0.3);
    CHECK(f(0.2) == 0.3);
    CHECK(f(0.6) == 0.9);
    CHECK(f(7.0) == 0.9);
    CHECK(PiecewiseLinear({{0.4, 0.7}})(0.0) == 0.7);
}

TEST_CASE("duplicate v values make a deterministic step") {
    // Stable sort keeps (0.5, 0.1) before (0.5, 0.9): left of 0.5 the curve approaches 0.1,
    // at and right of 0.5 it is 0.9.
    PiecewiseLinear f({{1.0, 1.0}, {0.5, 0.1}, {0.0, 0.0}, {0.5, 0.9}});
    CHECK(f(0.25) == doctest::Approx(0.05).epsilon(1e-15));
    CHECK(f(0.5 - 1e-12) == doctest::Approx(0.1).epsilon(1e-9));
    CHECK(f(0.5) == 0.9);
    CHECK(f(0.75) == doctest::Approx(0.95).epsilon(1e-15));
    CHECK(f.maxOver(0.0, 0.5) == 0.9);
    CHECK(f.minOver(0.5, 1.0) == 0.9);
    CHECK(f.maxOver(0.0, 0.49) == doctest::Approx(0.098).epsilon(1e-12));
}

TEST_CASE("max and min over an interval include interior control points") {
    PiecewiseLinear f({{0.0, 0.0}, {0.3, 0.0}, {0.4, 0.6}, {0.5, 0.0}});
    CHECK(f.maxOver(0.0, 0.2) == 0.0);
    CHECK(f.maxOver(0.0, 1.0) == 0.6);
    CHECK(f.maxOver(0.45, 0.35) == doctest::Approx(0.6)); // either order
    CHECK(f.minOver(0.35, 0.45) == doctest::Approx(0.3).epsilon(1e-12));
}

TEST_CASE("outputs are clamped to the unit interval and bad channels rejected") {
    TransferFunction1D tf;
    tf.setChannel(TransferFunction1D::Red, {{0.0, -0.5}, {1.0, 1.5}});
    CHECK(tf.evaluate(TransferFunction1D::Red, 0.0) == 0.0);
    CHECK(tf.evaluate(TransferFunction1D::Red, 1.0) == 1.0);
    CHECK(tf.evaluate(TransferFunction1D::Red, 0.5) == 0.5);
    CHECK_THROWS_AS(tf.setChannel(TransferFunction1D::Green, {}), Error);
    CHECK_THROWS_AS(
        tf.setChannel(TransferFunction1D::Green, {{std::numeric_limits<double>::quiet_NaN(), 0.0}}),
        Error);
    CHECK_THROWS_AS(tf.setDataRange(0.0, std::numeric_limits<double>::infinity()), Error);
}

TEST_CASE("data values normalise through the data range and clamp") {
    CHECK(TransferFunction1D::normalise(50.0, 0.0, 200.0) == 0.25);
    CHECK(TransferFunction1D::normalise(-10.0, 0.0, 200.0) == 0.0);
    CHECK(TransferFunction1D::normalise(250.0, 0.0, 200.0) == 1.0);
    CHECK(TransferFunction1D::normalise(150.0, 200.0, 0.0) == 0.25); // inverted range
    CHECK(TransferFunction1D::normalise(std::numeric_limits<double>::quiet_NaN(), 0, 1) == 0.0);
    CHECK(TransferFunction1D::normalise(std::numeric_limits<double>::infinity(), 0, 1) == 1.0);
    CHECK(TransferFunction1D::normalise(-std::numeric_limits<double>::infinity(), 0, 1) == 0.0);
}

TEST_CASE("an empty data range is a step at lo") {
    CHECK(TransferFunction1D::normalise(99.999, 100.0, 100.0) == 0.0);
    CHECK(TransferFunction1D::normalise(100.0, 100.0, 100.0) == 1.0);
    CHECK(TransferFunction1D::normalise(100.001, 100.0, 100.0) == 1.0);
}

TEST_CASE("without a data range the grid type's range applies") {
    TransferFunction1D tf;
    auto u16 = VolumeGrid::create({1, 1, 1}, VoxelType::UShort);
    CHECK(tf.resolvedDataRange(*u16) == glm::dvec2(0.0, 65535.0));
    auto f = VolumeGrid::create({2, 1, 1}, VoxelType::Float);
    f->setValue(0, 0, 0, -1.0);
    f->setValue(1, 0, 0, 3.0);
    CHECK(tf.resolvedDataRange(*f) == glm::dvec2(-1.0, 3.0));
    tf.setDataRange(10.0, 20.0);
    CHECK(tf.resolvedDataRange(*u16) == glm::dvec2(10.0, 20.0));
    tf.clearDataRange();
    CHECK(tf.resolvedDataRange(*u16) == glm::dvec2(0.0, 65535.0));
}

TEST_CASE("lineAt gives the straight piece the curve follows at a point") {
    PiecewiseLinear f({{0.0, 1.0}, {0.5, 0.0}, {0.5, 0.8}, {1.0, 0.8}});
    const auto down = f.lineAt(0.25);
    CHECK(down.slope == -2.0);
    CHECK(down(0.5) == 0.0); // the left piece extended to the jump: its one-sided limit
    const auto flat = f.lineAt(0.5);
    CHECK(flat.slope == 0.0);
    CHECK(flat(0.5) == 0.8);
    CHECK(f.lineAt(-3.0)(-3.0) == 1.0); // constant beyond the ends
    CHECK(f.lineAt(9.0)(9.0) == 0.8);
    for (double x : {0.1, 0.3, 0.7})
        CHECK(f.lineAt(x)(x) == doctest::Approx(f(x)).epsilon(1e-15));
}
