// The cursor readout and region histogram against hand-computed counts on a small grid.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include <volsg/editors/RegionHistogram.h>
#include <volsg/volume/VolumeGrid.h>

using namespace volsg;

namespace {
/// 4x4x4 UBYTE voxels with d = 10 x + 3 y + 40 z (0 .. 159).
ref_ptr<VolumeGrid> rampGrid() {
    auto grid = VolumeGrid::create({4, 4, 4}, VoxelType::UByte, {0.5, 0.5, 0.5});
    for (int z = 0; z < 4; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x)
                grid->setValue(x, y, z, 10.0 * x + 3.0 * y + 40.0 * z);
    return grid;
}
} // namespace

TEST_CASE("the readout is the cursor voxel and a 3^3 region counts its 27 values") {
    auto grid = rampGrid();
    // Range 0..160 in 5 bins: bin round(d / 160 * 4), so edges at 20, 60, 100, 140.
    const auto r = RegionHistogram::of(*grid, {1, 2, 1}, 3, {0.0, 160.0}, 5);
    REQUIRE(r);
    CHECK(r->value == 10.0 + 6.0 + 40.0);
    CHECK(r->first == glm::ivec3(0, 1, 0));
    CHECK(r->last == glm::ivec3(2, 3, 2));
    CHECK(r->samples == 27);
    // By hand: x in {0,10,20}, y in {3,6,9}, z in {0,40,80}; the 27 sums are
    // z=0: 3 6 9 13 16 19 23 26 29 -> below 20: 3 6 9 13 16 19 (6), 20..59: 3
    // z=40: 43..69 -> 43 46 49 53 56 59 (6) in bin 1, 63 66 69 (3) in bin 2
    // z=80: 83..109 -> 83 86 89 93 96 99 (6) in bin 2, 103 106 109 (3) in bin 3
    CHECK(r->counts == std::vector<std::uint64_t>{6, 9, 9, 3, 0});
    CHECK(r->minimum == 3.0);
    CHECK(r->maximum == 109.0);
    CHECK(r->mean == doctest::Approx(56.0).epsilon(1e-12)); // 10 + 6 + 40 by symmetry
}

TEST_CASE("a region at the grid's corner is clipped and an even k reaches one more below") {
    auto grid = rampGrid();
    const auto corner = RegionHistogram::of(*grid, {0, 0, 0}, 3, {0.0, 160.0}, 5);
    REQUIRE(corner);
    CHECK(corner->samples == 8); // 2^3 inside the grid
    // 0 3 10 13 40 43 50 53 -> bins 0 0 0 0 1 1 1 1
    CHECK(corner->counts == std::vector<std::uint64_t>{4, 4, 0, 0, 0});
    const auto even = RegionHistogram::of(*grid, {2, 2, 2}, 2, {0.0, 160.0}, 5);
    REQUIRE(even);
    CHECK(even->first == glm::ivec3(1, 1, 1));
    CHECK(even->last == glm::ivec3(2, 2, 2));
    CHECK(even->samples == 8);
    const auto one = RegionHistogram::of(*grid, {3, 3, 3}, 1, {0.0, 160.0}, 5);
    REQUIRE(one);
    CHECK(one->samples == 1);
    CHECK(one->counts == std::vector<std::uint64_t>{0, 0, 0, 0, 1}); // 159 -> round(3.975)
    CHECK_FALSE(RegionHistogram::of(*grid, {4, 0, 0}, 3, {0.0, 160.0}));
    CHECK_FALSE(RegionHistogram::of(*grid, {1, 1, 1}, 0, {0.0, 160.0}));
}

TEST_CASE("values outside the data range clamp to the end bins and NaN is not counted") {
    auto grid = VolumeGrid::create({3, 1, 1}, VoxelType::Float);
    grid->setValue(0, 0, 0, -5.0);
    grid->setValue(1, 0, 0, std::numeric_limits<double>::quiet_NaN());
    grid->setValue(2, 0, 0, 7.5);
    const auto r = RegionHistogram::of(*grid, {1, 0, 0}, 3, {0.0, 5.0}, 3);
    REQUIRE(r);
    CHECK(std::isnan(r->value));
    CHECK(r->samples == 2);
    CHECK(r->counts == std::vector<std::uint64_t>{1, 0, 1});
    CHECK(r->minimum == -5.0);
    CHECK(r->maximum == 7.5);
}

TEST_CASE("a local point maps to the voxel whose cell holds it") {
    auto grid = rampGrid(); // extent 2: the box is -1 .. 1, cells 0.5 wide
    CHECK(RegionHistogram::voxelAt(*grid, {-0.99, -0.99, -0.99}) == glm::ivec3(0));
    CHECK(RegionHistogram::voxelAt(*grid, {0.1, -0.4, 0.6}) == glm::ivec3(2, 1, 3));
    CHECK(RegionHistogram::voxelAt(*grid, {1.0, 1.0, 1.0}) == glm::ivec3(3)); // far faces
    CHECK_FALSE(RegionHistogram::voxelAt(*grid, {1.01, 0.0, 0.0}));
    CHECK_FALSE(RegionHistogram::voxelAt(*grid, {0.0, -1.2, 0.0}));
}
