// PyramidSource: boxes of any level read chunk by chunk equal the same voxels of the level
// read whole, and what cannot be read is one Error line naming the file.
#include "volumeio/ZarrTestSupport.h"

#include <random>
#include <thread>
#include <vector>

#include <volsg/volumeio/OmeZarrLevels.h>
#include <volsg/volumeio/OmeZarrPyramid.h>
#include <volsg/volumeio/PyramidSource.h>
#include <volsg/volumeio/VolumeReader.h>

using namespace volsg;
using namespace zarrtest;

namespace {

/// The sub-box [first, first + count) of `grid`.
ref_ptr<VolumeGrid> cut(const VolumeGrid& grid, glm::ivec3 first, glm::ivec3 count) {
    auto out = VolumeGrid::create(count, grid.type(), grid.spacing());
    for (int z = 0; z < count.z; ++z)
        for (int y = 0; y < count.y; ++y)
            for (int x = 0; x < count.x; ++x)
                out->setValue(x, y, z, grid.value(first.x + x, first.y + y, first.z + z));
    return out;
}

std::string writePyramid(const TempDir& dir, glm::ivec3 dims, VoxelType type) {
    const std::string folder = dir.file("p.zarr");
    PyramidOptions options;
    options.chunk = 8;
    writeOmeZarrPyramid(*patternGrid(dims, type, {0.5, 0.75, 1.0}), folder, options);
    return folder;
}

} // namespace

TEST_CASE("a box read chunk by chunk equals the same box of the level read whole") {
    const TempDir dir;
    for (const VoxelType type : {VoxelType::UByte, VoxelType::UShort, VoxelType::Float}) {
        const std::string folder = writePyramid(dir, {37, 20, 45}, type);
        const PyramidSource source(folder, 4096); // a cache of a few chunks: evictions happen
        REQUIRE(source.levelCount() == omeZarrLevelCount(folder));
        REQUIRE(source.levelCount() == 4);
        std::mt19937 random(7);
        for (int l = 0; l < source.levelCount(); ++l) {
            const ref_ptr<VolumeGrid> whole = readOmeZarr(folder, l);
            const PyramidSourceLevel& level = source.level(l);
            CHECK(level.dimensions == whole->dimensions());
            CHECK(level.scale == glm::ivec3(1 << l));
            for (int trial = 0; trial < 12; ++trial) {
                glm::ivec3 first, count;
                for (int a = 0; a < 3; ++a) {
                    first[a] = int(random() % unsigned(level.dimensions[a]));
                    count[a] = 1 + int(random() % unsigned(level.dimensions[a] - first[a]));
                }
                const ref_ptr<VolumeGrid> box = source.readBox(l, first, count);
                std::string firstDifference;
                CHECK_MESSAGE(countDifferences(*box, *cut(*whole, first, count), firstDifference) ==
                                  0,
                              "level " << l << ": " << firstDifference);
                CHECK(box->spacing() == whole->spacing());
            }
        }
        std::filesystem::remove_all(folder);
    }
}

TEST_CASE("boxes read from several threads at once equal the level read whole") {
    const TempDir dir;
    const std::string folder = writePyramid(dir, {40, 33, 29}, VoxelType::UShort);
    const PyramidSource source(folder, 8 * 8 * 8 * 2 * 6);
    const ref_ptr<VolumeGrid> whole = readOmeZarr(folder, 0);
    std::atomic<int> wrong{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&, t] {
            for (int i = 0; i < 40; ++i) {
                const glm::ivec3 first((t * 7 + i * 3) % 30, (i * 5) % 25, (t + i) % 20);
                const glm::ivec3 count(10, 8, 9);
                std::string ignored;
                if (countDifferences(*source.readBox(0, first, count), *cut(*whole, first, count),
                                     ignored) != 0)
                    ++wrong;
            }
        });
    for (std::thread& t : threads)
        t.join();
    CHECK(wrong == 0);
    CHECK(source.chunkCacheBytes() <= 8 * 8 * 8 * 2 * 6);
}

TEST_CASE("a box outside the level, a corrupt chunk and a level that is no halving are errors") {
    const TempDir dir;
    const std::string folder = writePyramid(dir, {20, 20, 20}, VoxelType::UByte);
    {
        const PyramidSource source(folder);
        const std::string outside = errorOf([&] { source.readBox(1, {5, 5, 5}, {6, 1, 1}); });
        CHECK_HAS(outside, "lies outside level 1 (10 x 10 x 10)");
        CHECK_HAS(outside, ".zarray");
        CHECK_HAS(errorOf([&] { source.readBox(7, {0, 0, 0}, {1, 1, 1}); }), "levels 0..2");
    }
    writeFile(folder + "/0/1/0/1", "not zstd at all");
    {
        const PyramidSource source(folder);
        const std::string corrupt = errorOf([&] { source.readBox(0, {0, 0, 0}, {20, 20, 20}); });
        CHECK_HAS(corrupt, "0/1/0/1");
        // Boxes that do not touch the chunk still read.
        CHECK(source.readBox(0, {0, 0, 0}, {8, 8, 8})->voxelCount() == 512);
    }
    // Level 1 claims 20 voxels a side with doubled spacing: not a halving of level 0.
    std::string zarray = readFile(folder + "/1/.zarray");
    const auto at = zarray.find("\"shape\"");
    REQUIRE(at != std::string::npos);
    const auto end = zarray.find(']', at);
    zarray.replace(at, end - at + 1, "\"shape\": [20, 20, 20]");
    writeFile(folder + "/1/.zarray", zarray);
    const std::string notHalving = errorOf([&] { PyramidSource source(folder); });
    CHECK_HAS(notHalving, "level 1 (20 x 20 x 20 voxels) does not halve");
    CHECK_HAS(notHalving, "1/.zarray");
}
