// VolumeGrid: layout, types, ranges and size checks.
#include <doctest/doctest.h>

#include <climits>
#include <cmath>
#include <limits>

#include <volsg/core/Error.h>
#include <volsg/volume/VolumeGrid.h>

using namespace volsg;

TEST_CASE("grid stores x fastest, then y, then z") {
    auto g = VolumeGrid::create({3, 4, 5}, VoxelType::UShort);
    CHECK(g->voxelCount() == 60);
    CHECK(g->byteSize() == 120);
    CHECK(g->index(1, 0, 0) == 1);
    CHECK(g->index(0, 1, 0) == 3);
    CHECK(g->index(0, 0, 1) == 12);
    CHECK(g->index(2, 3, 4) == 59);
    g->setValue(2, 1, 3, 1234.0);
    CHECK(g->data<std::uint16_t>()[2 + 3 * (1 + 4 * 3)] == 1234);
    CHECK(g->value(2, 1, 3) == 1234.0);
    CHECK(g->value(0, 0, 0) == 0.0); // zero-filled
}

TEST_CASE("voxel centres sit in the middle of their cells around the local origin") {
    auto g = VolumeGrid::create({4, 2, 1}, VoxelType::UByte, {0.5, 1.5, 2.0});
    CHECK(g->extent() == glm::dvec3(2.0, 3.0, 2.0));
    CHECK(g->voxelCenter(0, 0, 0) == glm::dvec3(-0.75, -0.75, 0.0));
    CHECK(g->voxelCenter(3, 1, 0) == glm::dvec3(0.75, 0.75, 0.0));
    CHECK(g->smallestSpacing() == 0.5);
}

TEST_CASE("dimensions below one are rejected") {
    CHECK_THROWS_AS(VolumeGrid::create({0, 4, 4}, VoxelType::UByte), Error);
    CHECK_THROWS_AS(VolumeGrid::create({4, -1, 4}, VoxelType::UByte), Error);
    CHECK_THROWS_AS(VolumeGrid::create({4, 4, 0}, VoxelType::Float), Error);
}

TEST_CASE("spacing must be finite and positive") {
    CHECK_THROWS_AS(VolumeGrid::create({2, 2, 2}, VoxelType::UByte, {1.0, 0.0, 1.0}), Error);
    CHECK_THROWS_AS(VolumeGrid::create({2, 2, 2}, VoxelType::UByte, {1.0, -2.0, 1.0}), Error);
    CHECK_THROWS_AS(VolumeGrid::create({2, 2, 2}, VoxelType::UByte,
                                       {1.0, 1.0, std::numeric_limits<double>::quiet_NaN()}),
                    Error);
    auto g = VolumeGrid::create({2, 2, 2}, VoxelType::UByte);
    CHECK_THROWS_AS(g->setSpacing({1.0, 1.0, std::numeric_limits<double>::infinity()}), Error);
    g->setSpacing({1.0, 2.0, 3.0});
    CHECK(g->spacing() == glm::dvec3(1.0, 2.0, 3.0));
}

TEST_CASE("an overflowing voxel count is an error, not an allocation") {
    CHECK_THROWS_AS(VolumeGrid::create({INT_MAX, INT_MAX, INT_MAX}, VoxelType::Float), Error);
    CHECK_THROWS_AS(VolumeGrid::checkedByteSize({INT_MAX, INT_MAX, INT_MAX}, VoxelType::UByte,
                                                std::numeric_limits<std::uint64_t>::max()),
                    Error);
}

TEST_CASE("the allocation limit is checked before allocating and can be changed") {
    // 2048^3 floats = 32 GiB: above the default 4 GiB limit.
    CHECK(VolumeGrid::defaultByteLimit == 4ull * 1024 * 1024 * 1024);
    CHECK_THROWS_AS(VolumeGrid::create({2048, 2048, 2048}, VoxelType::Float), Error);
    CHECK(VolumeGrid::checkedByteSize({10, 10, 5}, VoxelType::UShort, 1000) == 1000);
    CHECK_THROWS_AS(VolumeGrid::create({10, 10, 10}, VoxelType::UShort, glm::dvec3(1.0), 1999),
                    Error);
    auto g = VolumeGrid::create({10, 10, 10}, VoxelType::UShort, glm::dvec3(1.0), 2000);
    CHECK(g->byteSize() == 2000);
}

TEST_CASE("each type has its natural range") {
    CHECK(VolumeGrid::create({1, 1, 1}, VoxelType::UByte)->naturalRange() == std::pair(0.0, 255.0));
    CHECK(VolumeGrid::create({1, 1, 1}, VoxelType::UShort)->naturalRange() ==
          std::pair(0.0, 65535.0));
    CHECK(VolumeGrid::create({1, 1, 1}, VoxelType::Short)->naturalRange() ==
          std::pair(-32768.0, 32767.0));
    auto f = VolumeGrid::create({3, 1, 1}, VoxelType::Float);
    f->setValue(0, 0, 0, -2.5);
    f->setValue(1, 0, 0, 7.25);
    CHECK(f->naturalRange() == std::pair(-2.5, 7.25));
}

TEST_CASE("integer voxels round to nearest and saturate") {
    auto b = VolumeGrid::create({4, 1, 1}, VoxelType::UByte);
    b->setValue(0, 0, 0, 12.6);
    b->setValue(1, 0, 0, 300.0);
    b->setValue(2, 0, 0, -5.0);
    CHECK(b->value(0, 0, 0) == 13.0);
    CHECK(b->value(1, 0, 0) == 255.0);
    CHECK(b->value(2, 0, 0) == 0.0);
    CHECK_THROWS_AS(b->setValue(3, 0, 0, std::numeric_limits<double>::quiet_NaN()), Error);
    auto s = VolumeGrid::create({2, 1, 1}, VoxelType::Short);
    s->setValue(0, 0, 0, -40000.0);
    s->setValue(1, 0, 0, -1234.4);
    CHECK(s->value(0, 0, 0) == -32768.0);
    CHECK(s->value(1, 0, 0) == -1234.0);
    CHECK(s->minMax() == std::pair(-32768.0, -1234.0));
}

TEST_CASE("float min and max skip NaN and infinities") {
    auto f = VolumeGrid::create({5, 1, 1}, VoxelType::Float);
    f->setValue(0, 0, 0, std::numeric_limits<double>::quiet_NaN());
    f->setValue(1, 0, 0, std::numeric_limits<double>::infinity());
    f->setValue(2, 0, 0, -std::numeric_limits<double>::infinity());
    f->setValue(3, 0, 0, 0.5);
    f->setValue(4, 0, 0, -0.25);
    CHECK(std::isnan(f->value(0, 0, 0)));
    CHECK(f->minMax() == std::pair(-0.25, 0.5));
    auto allNan = VolumeGrid::create({1, 1, 1}, VoxelType::Float);
    allNan->setValue(0, 0, 0, std::numeric_limits<double>::quiet_NaN());
    CHECK(allNan->minMax() == std::pair(0.0, 0.0));
}

TEST_CASE("typed access with the wrong element type throws") {
    auto g = VolumeGrid::create({2, 2, 2}, VoxelType::Short);
    CHECK(g->data<std::int16_t>().size() == 8);
    CHECK_THROWS_AS(g->data<std::uint16_t>(), Error);
    CHECK_THROWS_AS(g->data<float>(), Error);
    CHECK(g->bytes().size() == 16);
}

TEST_CASE("label grids are UByte or UShort grids") {
    CHECK(VolumeGrid::create({1, 1, 1}, VoxelType::UByte)->isLabelType());
    CHECK(VolumeGrid::create({1, 1, 1}, VoxelType::UShort)->isLabelType());
    CHECK_FALSE(VolumeGrid::create({1, 1, 1}, VoxelType::Short)->isLabelType());
    CHECK_FALSE(VolumeGrid::create({1, 1, 1}, VoxelType::Float)->isLabelType());
    CHECK(std::string(voxelTypeName(VoxelType::UShort)) == "USHORT");
    CHECK(voxelTypeSize(VoxelType::Float) == 4);
}
