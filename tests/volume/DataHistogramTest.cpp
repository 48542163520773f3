// The histogram of a grid and the first transfer function chosen from it: synthetic volumes
// with a known background and known structures, the function sampled at each class and
// composited along a ray through the middle. Rendered pixels of such a volume are checked in
// tests/volumescene/SceneForFileTest.cpp.

#include <doctest/doctest.h>

#include <cmath>

#include <volsg/volume/DataHistogram.h>
#include <volsg/volume/VolumeGrid.h>

using namespace volsg;

namespace {

// n^3 SHORT volume: `air` everywhere, a ball of radius 0.3 n of `tissue` in the middle, and,
// when `bone` is not 0, a smaller ball (0.1 n) of `bone` inside it.
ref_ptr<VolumeGrid> ballInAir(int n, double air, double tissue, double bone = 0.0) {
    ref_ptr<VolumeGrid> g = VolumeGrid::create(glm::ivec3(n), VoxelType::Short);
    const double c = 0.5 * (n - 1);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double r =
                    std::sqrt((i - c) * (i - c) + (j - c) * (j - c) + (k - c) * (k - c));
                double v = r < 0.3 * n ? tissue : air;
                if (bone != 0.0 && r < 0.1 * n) v = bone;
                g->setValue(i, j, k, v);
            }
    return g;
}

double opacityAt(const TransferFunction1D& tf, double value) {
    const glm::dvec2 r = *tf.dataRange();
    return tf.evaluate(TransferFunction1D::Alpha, TransferFunction1D::normalise(value, r.x, r.y));
}

// The opacity a ray along x through the volume's centre accumulates, compositing one
// reference-length step per voxel.
double rayOpacity(const TransferFunction1D& tf, const VolumeGrid& grid) {
    const int n = grid.dimensions().x;
    double transparency = 1.0;
    for (int i = 0; i < n; ++i)
        transparency *= 1.0 - opacityAt(tf, grid.value(i, n / 2, n / 2));
    return 1.0 - transparency;
}

} // namespace

TEST_CASE("histogram: the data's own range, one bin per integer value when few") {
    ref_ptr<VolumeGrid> g = ballInAir(20, -1000, 40);
    const DataHistogram h = histogramOf(*g);
    CHECK(h.minimum == -1000.0);
    CHECK(h.maximum == 40.0);
    CHECK(h.counts.size() == 256); // 1041 distinct values possible: 256 bins
    CHECK(h.total == 8000);
    CHECK(h.counts.front() + h.counts.back() == 8000);

    ref_ptr<VolumeGrid> few = ballInAir(10, 3, 7);
    const DataHistogram f = histogramOf(*few);
    CHECK(f.counts.size() == 5); // values 3..7
    CHECK(f.lo == 2.5);
    CHECK(f.hi == 7.5);
    CHECK(f.counts[0] + f.counts[4] == 1000);
}

TEST_CASE("an 80% air volume with a ball of tissue: air transparent, the ball visible") {
    // The ball of radius 0.3 n fills 11% of the box; the rest is air.
    ref_ptr<VolumeGrid> g = ballInAir(32, -1000, 40);
    const TransferFunction1D tf = transferFunctionFromHistogram(histogramOf(*g));
    REQUIRE(tf.dataRange());
    CHECK(*tf.dataRange() == glm::dvec2(-1000, 40)); // the data's range, not SHORT's
    CHECK(opacityAt(tf, -1000) == 0.0);
    CHECK(opacityAt(tf, 40) > 0.3);
    // A ray through the middle: 0 through air alone, well over half opaque through the ball.
    CHECK(rayOpacity(tf, *g) > 0.9);
    ref_ptr<VolumeGrid> empty = ballInAir(32, -1000, -1000);
    empty->setValue(0, 0, 0, 40); // one voxel of tissue in a corner, off the ray
    CHECK(rayOpacity(transferFunctionFromHistogram(histogramOf(*empty)), *empty) == 0.0);
}

TEST_CASE("tissue see-through, bone dense: the common class fainter than the rare one") {
    ref_ptr<VolumeGrid> g = ballInAir(40, 0, 1000, 3000);
    const TransferFunction1D tf = transferFunctionFromHistogram(histogramOf(*g));
    CHECK(opacityAt(tf, 0) == 0.0);
    CHECK(opacityAt(tf, 1000) > 0.0);
    CHECK(opacityAt(tf, 1000) < 0.2);
    CHECK(opacityAt(tf, 3000) > 0.5);
}

TEST_CASE("a bright background: the ramp runs the other way") {
    ref_ptr<VolumeGrid> g = ballInAir(32, 4000, 500);
    const TransferFunction1D tf = transferFunctionFromHistogram(histogramOf(*g));
    CHECK(opacityAt(tf, 4000) == 0.0);
    CHECK(opacityAt(tf, 500) > 0.3);
}

TEST_CASE("a constant volume gets a usable function, not a division by zero") {
    ref_ptr<VolumeGrid> g = VolumeGrid::create(glm::ivec3(4), VoxelType::Float);
    const TransferFunction1D tf = transferFunctionFromHistogram(histogramOf(*g));
    CHECK(*tf.dataRange() == glm::dvec2(0, 0));
    CHECK(opacityAt(tf, 0.0) > 0.0);
}
