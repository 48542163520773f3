// readOmeZarrRegion: a box of one level, read chunk by chunk, opening only the chunks it
// meets (how a sort-last process loads only its own bricks).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include <support/TempDir.h>
#include <volsg/core/Error.h>
#include <volsg/volume/VolumeGrid.h>
#include <volsg/volumeio/OmeZarrPyramid.h>
#include <volsg/volumeio/VolumeReader.h>

using namespace volsg;

namespace {

/// A UShort grid whose every voxel holds a value made of its coordinates.
ref_ptr<VolumeGrid> codedGrid(glm::ivec3 dims) {
    auto grid = VolumeGrid::create(dims, VoxelType::UShort, glm::dvec3(0.5, 0.75, 1.0));
    for (int z = 0; z < dims.z; ++z)
        for (int y = 0; y < dims.y; ++y)
            for (int x = 0; x < dims.x; ++x)
                grid->setValue(grid->index(x, y, z), double(x + 40 * y + 1600 * z));
    return grid;
}

} // namespace

TEST_CASE("a region of an OME-Zarr level equals that box of the whole level") {
    const test::TempDir dir("volsg-zarr-region");
    const std::string image = dir.file("coded.zarr");
    PyramidOptions options;
    options.chunk = 8;
    writeOmeZarrPyramid(*codedGrid({37, 21, 19}), image, options);
    const ref_ptr<VolumeGrid> whole = readOmeZarr(image);
    for (const auto& [first, count] : {std::pair{glm::ivec3(0), glm::ivec3(37, 21, 19)},
                                       {glm::ivec3(7, 9, 3), {18, 5, 13}},
                                       {glm::ivec3(36, 20, 18), glm::ivec3(1)},
                                       {glm::ivec3(8, 0, 16), {8, 8, 3}}}) {
        const ref_ptr<VolumeGrid> part = readOmeZarrRegion(image, 0, first, count);
        REQUIRE(part->dimensions() == count);
        CHECK(part->spacing() == whole->spacing());
        int mismatches = 0;
        for (int z = 0; z < count.z; ++z)
            for (int y = 0; y < count.y; ++y)
                for (int x = 0; x < count.x; ++x)
                    if (part->value(part->index(x, y, z)) !=
                        whole->value(whole->index(first.x + x, first.y + y, first.z + z)))
                        ++mismatches;
        CHECK(mismatches == 0);
    }
}

TEST_CASE("a region opens only the chunks it meets") {
    const test::TempDir dir("volsg-zarr-region");
    const std::string image = dir.file("coded.zarr");
    PyramidOptions options;
    options.chunk = 8;
    writeOmeZarrPyramid(*codedGrid({32, 16, 16}), image, options);
    // Spoil the chunk at z 1, y 1, x 3 (voxels 24..31, 8..15, 8..15): a read that opens it fails.
    std::ofstream(image + "/0/1/1/3", std::ios::binary | std::ios::trunc) << "not a chunk";
    CHECK_THROWS_AS(readOmeZarr(image), Error);
    const ref_ptr<VolumeGrid> part = readOmeZarrRegion(image, 0, {0, 0, 0}, {24, 16, 16});
    CHECK(part->value(part->index(23, 15, 15)) == 23 + 40 * 15 + 1600 * 15);
    CHECK_THROWS_AS(readOmeZarrRegion(image, 0, {20, 8, 8}, {8, 2, 2}), Error);
}

TEST_CASE("a region outside the level is one clear error") {
    const test::TempDir dir("volsg-zarr-region");
    const std::string image = dir.file("coded.zarr");
    writeOmeZarrPyramid(*codedGrid({10, 10, 10}), image);
    try {
        readOmeZarrRegion(image, 0, {5, 0, 0}, {6, 10, 10});
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(std::string(e.what()).find("is not inside the level's 10 x 10 x 10") !=
              std::string::npos);
    }
    CHECK_THROWS_AS(readOmeZarrRegion(image, 0, {0, 0, 0}, {0, 1, 1}), Error);
}

TEST_CASE("the whole level with only a box's chunks read: the box as read whole, fill elsewhere") {
    const test::TempDir dir("volsg-zarr-region");
    const std::string image = dir.file("coded.zarr");
    PyramidOptions options;
    options.chunk = 8;
    writeOmeZarrPyramid(*codedGrid({32, 16, 16}), image, options);
    CHECK(readOmeZarrDimensions(image) == glm::ivec3(32, 16, 16));
    const ref_ptr<VolumeGrid> whole = readOmeZarr(image);
    // The spoiled chunk (voxels 24..31, 8..15, 8..15) lies outside the box: never opened.
    std::ofstream(image + "/0/1/1/3", std::ios::binary | std::ios::trunc) << "not a chunk";
    const glm::ivec3 first(3, 2, 1), count(18, 9, 12);
    const ref_ptr<VolumeGrid> part = readOmeZarrWithin(image, 0, first, count);
    REQUIRE(part->dimensions() == whole->dimensions());
    CHECK(part->spacing() == whole->spacing());
    int inside = 0, outside = 0;
    for (int z = 0; z < 16; ++z)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 32; ++x) {
                const glm::ivec3 v(x, y, z);
                const bool inBox = glm::all(glm::greaterThanEqual(v, first)) &&
                                   glm::all(glm::lessThan(v, first + count));
                const double value = part->value(x, y, z);
                if (inBox && value != whole->value(x, y, z)) ++inside;
                // Outside the box: the chunk's value where a chunk meeting it was read, else 0.
                if (!inBox && value != 0.0 && value != whole->value(x, y, z)) ++outside;
            }
    CHECK(inside == 0);
    CHECK(outside == 0);
    CHECK(part->value(31, 15, 15) == 0.0); // in a chunk the box does not meet
}
