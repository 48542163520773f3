// The series step cache without GL: file patterns, eviction and spill under a small budget
// (every step comes back bit for bit), prefetch in the direction of play, clean shutdown.
#include <doctest/doctest.h>

#include <volsg/core/Error.h>
#include <volsg/series/FilePattern.h>
#include <volsg/series/MovingSphere.h>
#include <volsg/series/SeriesCache.h>
#include <volsg/series/SpillFile.h>
#include <volsg/shearwarp/VoxelObject.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

using namespace volsg;

namespace {

constexpr int kSide = 32;

SeriesStepLoader sphereLoader(int steps, std::atomic<int>* loads = nullptr) {
    return [steps, loads](int index) {
        if (loads) ++*loads;
        return SeriesStepVolume{makeMovingSphere(kSide, double(index) / double(steps - 1)),
                                nullptr};
    };
}

/// Visible voxels under a ramp that hides the lowest values (so the lists are not the grid).
ExtractionSpec visibleSpec() {
    ExtractionSpec spec;
    spec.transferFunction.setChannel(TransferFunction1D::Alpha,
                                     {{0.0, 0.0}, {0.1, 0.0}, {1.0, 0.6}});
    return spec;
}

bool sameArrays(const VoxelObject& a, const VoxelObject& b) {
    const VoxelObject::Arrays x = a.arrays(), y = b.arrays();
    return x.dimensions == y.dimensions && x.spacing == y.spacing &&
           x.maxMagnitude == y.maxMagnitude && x.i == y.i && x.j == y.j && x.k == y.k &&
           x.value12 == y.value12 && x.gradientCode == y.gradientCode &&
           x.magnitude8 == y.magnitude8;
}

bool sameRenderList(VoxelObject& a, VoxelObject& b, int axis) {
    const RenderList& x = a.renderList(axis);
    const RenderList& y = b.renderList(axis);
    if (x.packed != y.packed || x.value12 != y.value12 || x.gradientCode != y.gradientCode ||
        x.magnitude8 != y.magnitude8 || x.entries.size() != y.entries.size())
        return false;
    for (std::size_t e = 0; e < x.entries.size(); ++e)
        if (x.entries[e].first != y.entries[e].first ||
            x.entries[e].lastInSlice != y.entries[e].lastInSlice)
            return false;
    return true;
}

std::size_t threadCount() {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& entry :
         std::filesystem::directory_iterator("/proc/self/task"))
        ++n;
    return n;
}

} // namespace

TEST_CASE("file patterns format step numbers and refuse malformed patterns") {
    CHECK(FilePattern("step_%04d.nrrd").format(7) == "step_0007.nrrd");
    CHECK(FilePattern("s%d").format(12345) == "s12345");
    CHECK(FilePattern("s%3i.raw").format(5) == "s  5.raw");
    CHECK(FilePattern("100%%_%02d").format(3) == "100%_03");
    CHECK(FilePattern("n%03d").format(-4) == "n-04");
    for (const char* bad : {"a%s", "a%n", "%d%d", "a%", "%04", "%x", "%10d", "%-4d", "%.3d", "%ld",
                            "plain.nrrd", "%004d"})
        CHECK_THROWS_WITH_AS(FilePattern{bad}, doctest::Contains("series file pattern"), Error);
}

TEST_CASE("spill files give the voxel object back bit for bit and refuse damaged files") {
    const ref_ptr<VoxelObject> object =
        VoxelObject::extract(*makeMovingSphere(kSide, 0.5), nullptr, visibleSpec());
    REQUIRE(object->voxelCount() > 1000u);
    const std::string path =
        (std::filesystem::temp_directory_path() / "volsg-spill-test.voxels").string();
    const std::size_t bytes = writeSpillFile(path, *object);
    CHECK(bytes == std::filesystem::file_size(path));
    const ref_ptr<VoxelObject> back = readSpillFile(path);
    CHECK(sameArrays(*object, *back));
    CHECK(sameRenderList(*object, *back, 2));
    std::filesystem::resize_file(path, bytes - 3);
    CHECK_THROWS_WITH_AS(readSpillFile(path), doctest::Contains("wrong size"), Error);
    std::filesystem::remove(path);
    CHECK_THROWS_AS(readSpillFile(path), Error);
}

TEST_CASE("a read-back object adopts the spilled RenderLists as they were: identical, no sort") {
    const ref_ptr<VoxelObject> object =
        VoxelObject::extract(*makeMovingSphere(kSide, 0.5), nullptr, visibleSpec());
    // Lists as the renderer leaves them: arranged for a clip state and tables, masks made.
    RenderList& z = object->renderList(2);
    z.clipKey = 0x1234;
    z.tableKey = 0x5678;
    z.clippedLayout = PackedLayout::GradientValue;
    z.contributesUnclipped.assign(std::size_t(1) << 16, 1);
    z.contributesUnclipped[7] = 0;
    z.entries.front().optimized = true;
    z.entries.front().last = z.entries.front().first; // the optimizer moved them all behind
    object->renderList(0);
    REQUIRE(object->renderListBuilds() == 2u);

    const std::string path =
        (std::filesystem::temp_directory_path() / "volsg-spill-lists-test.voxels").string();
    writeSpillFile(path, *object);
    const ref_ptr<VoxelObject> back = readSpillFile(path);
    std::filesystem::remove(path);
    CHECK(sameArrays(*object, *back));
    CHECK(back->hasRenderList(0));
    CHECK_FALSE(back->hasRenderList(1));
    CHECK(back->hasRenderList(2));
    CHECK(back->renderList(2).sameContent(object->renderList(2)));
    CHECK(back->renderList(0).sameContent(object->renderList(0)));
    CHECK(back->renderListBuilds() == 0u); // adopted: nothing was sorted
    back->renderList(1);                   // a list the file did not hold is sorted as before
    CHECK(back->renderListBuilds() == 1u);
    CHECK(back->renderList(1).sameContent(object->renderList(1)));

    // Arrays only (SeriesCacheSettings::spillRenderLists false): the read-back sorts again.
    writeSpillFile(path, *object, false);
    const ref_ptr<VoxelObject> arraysOnly = readSpillFile(path);
    std::filesystem::remove(path);
    CHECK_FALSE(arraysOnly->hasRenderList(2));
    CHECK(arraysOnly->renderList(2).packed == object->renderList(2).packed);
    CHECK(arraysOnly->renderListBuilds() == 1u);
}

TEST_CASE("spill files of another version or with damaged bytes are refused, naming the file") {
    const ref_ptr<VoxelObject> object =
        VoxelObject::extract(*makeMovingSphere(kSide, 0.5), nullptr, visibleSpec());
    object->renderList(2);
    const std::string path =
        (std::filesystem::temp_directory_path() / "volsg-spill-damage-test.voxels").string();
    auto patch = [&](std::streamoff at, const std::string& bytes) {
        writeSpillFile(path, *object);
        std::fstream file(path, std::ios::binary | std::ios::in | std::ios::out);
        file.seekp(at);
        file.write(bytes.data(), std::streamsize(bytes.size()));
    };
    patch(8, std::string("\x01\0\0\0", 4)); // the version field after the 8-byte magic
    CHECK_THROWS_WITH_AS(readSpillFile(path), doctest::Contains("format version 1"), Error);
    CHECK_THROWS_WITH_AS(readSpillFile(path), doctest::Contains(path.c_str()), Error);
    // One voxel's attribute in the middle of the file: sizes still match, the checksum not.
    patch(std::streamoff(std::filesystem::file_size(path) / 2), "\x5a\xa5");
    CHECK_THROWS_WITH_AS(readSpillFile(path), doctest::Contains("checksum"), Error);
    CHECK_THROWS_WITH_AS(readSpillFile(path), doctest::Contains(path.c_str()), Error);
    patch(0, "XXXX");
    CHECK_THROWS_WITH_AS(readSpillFile(path), doctest::Contains("not a series disk cache"), Error);
    std::filesystem::remove(path);
}

TEST_CASE("a damaged spill file costs a re-extraction of its step, never the step") {
    constexpr int steps = 4;
    const ExtractionSpec spec = visibleSpec();
    const ref_ptr<VoxelObject> expected =
        VoxelObject::extract(*makeMovingSphere(kSide, 0.0), nullptr, spec);
    SeriesCacheSettings settings;
    settings.memoryBudget = 1; // everything but the shown step goes to disk
    settings.prefetchSteps = 0;
    SeriesCache cache(steps, sphereLoader(steps), settings);
    cache.show(0, +1);
    cache.voxelObject(0, spec)->renderList(2);
    cache.show(1, +1);
    cache.voxelObject(1, spec);
    cache.waitUntilIdle();
    REQUIRE(cache.isOnDisk(0, spec));
    REQUIRE_FALSE(cache.isInMemory(0, spec));
    int damaged = 0;
    for (const auto& file : std::filesystem::directory_iterator(cache.diskFolder()))
        if (file.path().filename().string().rfind("step-0-", 0) == 0) {
            std::fstream out(file.path(), std::ios::binary | std::ios::in | std::ios::out);
            out.seekp(std::streamoff(file.file_size() / 2));
            out.write("\x5a\xa5\x5a", 3);
            ++damaged;
        }
    REQUIRE(damaged == 1);
    const std::uint64_t extractionsBefore = cache.stats().extractions;
    cache.show(0, -1);
    const ref_ptr<VoxelObject> back = cache.voxelObject(0, spec);
    CHECK(sameArrays(*back, *expected));
    CHECK(sameRenderList(*back, *expected, 2));
    const SeriesCacheStats stats = cache.stats();
    CHECK(stats.damagedFiles == 1u);
    CHECK(stats.extractions == extractionsBefore + 1);
}

TEST_CASE("every step survives eviction and spill under a small budget, bit for bit") {
    constexpr int steps = 12;
    const ExtractionSpec spec = visibleSpec();
    std::map<int, ref_ptr<VoxelObject>> expected;
    std::size_t largest = 0;
    for (int s = 0; s < steps; ++s) {
        expected[s] =
            VoxelObject::extract(*makeMovingSphere(kSide, double(s) / (steps - 1)), nullptr, spec);
        expected[s]->renderList(2);
        largest = std::max(largest, expected[s]->memoryBytes());
    }
    SeriesCacheSettings settings;
    settings.memoryBudget = 2 * largest; // room for about two of the twelve steps
    settings.prefetchSteps = 1;
    SeriesCache cache(steps, sphereLoader(steps), settings);
    cache.setViewAxis(2);
    for (int s = 0; s < steps; ++s) { // play once through
        cache.show(s, +1);
        const ref_ptr<VoxelObject> shown = cache.voxelObject(s, spec);
        CHECK(sameArrays(*shown, *expected[s]));
        shown->renderList(2);
    }
    cache.waitUntilIdle();
    SeriesCacheStats stats = cache.stats();
    CHECK(stats.extractions == std::uint64_t(steps)); // each step extracted exactly once
    CHECK(stats.spills >= std::uint64_t(steps - 4));
    CHECK(stats.memoryBytes <= settings.memoryBudget + largest);
    CHECK(stats.memoryHighWater <= settings.memoryBudget + 2 * largest);
    int onDisk = 0;
    for (int s = 0; s < steps; ++s) {
        const bool memory = cache.isInMemory(s, spec), disk = cache.isOnDisk(s, spec);
        CHECK((memory || disk)); // no step lost
        onDisk += disk && !memory ? 1 : 0;
    }
    CHECK(onDisk >= steps - 4);

    // Play backwards: every step comes back from memory or disk, never extracted again.
    for (int s = steps - 1; s >= 0; --s) {
        cache.show(s, -1);
        const ref_ptr<VoxelObject> back = cache.voxelObject(s, spec);
        CHECK(sameArrays(*back, *expected[s]));
        CHECK(sameRenderList(*back, *expected[s], 2));
    }
    cache.waitUntilIdle();
    const std::uint64_t sortsForward = stats.renderListSorts;
    stats = cache.stats();
    CHECK(stats.extractions == std::uint64_t(steps));
    CHECK(stats.diskReads >= std::uint64_t(steps - 4));
    // Read-backs adopt the spilled lists: the backward pass sorted none.
    CHECK(stats.renderListSorts == sortsForward);
    CHECK(stats.memoryHighWater <= settings.memoryBudget + 2 * largest);
}

TEST_CASE("prefetch prepares the steps ahead in the direction of play") {
    constexpr int steps = 20;
    const ExtractionSpec spec = visibleSpec();
    SeriesCacheSettings settings;
    settings.prefetchSteps = 2;
    SeriesCache cache(steps, sphereLoader(steps), settings);
    cache.show(10, +1);
    cache.voxelObject(10, spec);
    cache.waitUntilIdle();
    CHECK(cache.isInMemory(11, spec));
    CHECK(cache.isInMemory(12, spec));
    CHECK_FALSE(cache.isInMemory(13, spec));
    CHECK_FALSE(cache.isInMemory(9, spec));
    CHECK(cache.stats().extractions == 3u);

    cache.show(5, -1);
    cache.voxelObject(5, spec);
    cache.waitUntilIdle();
    CHECK(cache.isInMemory(4, spec));
    CHECK(cache.isInMemory(3, spec));
    CHECK_FALSE(cache.isInMemory(6, spec));
    CHECK(cache.stats().extractions == 6u);

    cache.show(19, +1); // playing forward wraps around
    cache.voxelObject(19, spec);
    cache.waitUntilIdle();
    CHECK(cache.isInMemory(0, spec));
    CHECK(cache.isInMemory(1, spec));
    CHECK(cache.stats().extractions == 9u);
    const std::uint64_t hits = cache.stats().memoryHits;
    cache.show(0, +1);
    cache.voxelObject(0, spec); // prefetched: a memory hit, no extraction
    CHECK(cache.stats().memoryHits == hits + 1);
    CHECK(cache.stats().extractions == 9u);
}

TEST_CASE("a full memory tier makes room for the prefetch window: the next steps are ready") {
    // Budget for about four steps: once the first pass filled it with steps behind the
    // player, the steps ahead must still be prefetched (the steps behind go to disk), so that
    // a second pass finds every next step in memory and never reads one itself.
    constexpr int steps = 12;
    const ExtractionSpec spec = visibleSpec();
    std::size_t largest = 0;
    for (int s = 0; s < steps; ++s)
        largest = std::max(
            largest,
            VoxelObject::extract(*makeMovingSphere(kSide, double(s) / (steps - 1)), nullptr, spec)
                ->memoryBytes());
    SeriesCacheSettings settings;
    settings.memoryBudget = 4 * largest;
    settings.prefetchSteps = 2;
    SeriesCache cache(steps, sphereLoader(steps), settings);
    for (int pass = 0; pass < 2; ++pass)
        for (int s = 0; s < steps; ++s) {
            cache.show(s, +1);
            cache.voxelObject(s, spec);
            cache.waitUntilIdle();
            INFO("pass " << pass << ", step " << s);
            CHECK(cache.isInMemory((s + 1) % steps, spec));
            CHECK(cache.isInMemory((s + 2) % steps, spec));
        }
    const SeriesCacheStats stats = cache.stats();
    CHECK(stats.extractions == std::uint64_t(steps)); // the second pass read back, never extracted
    CHECK(stats.diskReads >= std::uint64_t(steps - 4));
    CHECK(stats.memoryHighWater <= settings.memoryBudget + 2 * largest);
}

TEST_CASE("a step that fails to load is reported and does not stop the others") {
    SeriesCache cache(4, [](int index) {
        if (index == 2) throw Error("step 2 is missing");
        return SeriesStepVolume{makeMovingSphere(16, 0.5), nullptr};
    });
    const ExtractionSpec spec = visibleSpec();
    cache.show(1, +1);
    CHECK(cache.voxelObject(1, spec));
    cache.waitUntilIdle(); // the worker tried step 2 and gave up quietly
    cache.show(2, +1);
    CHECK_THROWS_WITH_AS(cache.voxelObject(2, spec), doctest::Contains("step 2 is missing"), Error);
    cache.show(3, +1);
    CHECK(cache.voxelObject(3, spec));
}

TEST_CASE("destroying the cache stops its worker and removes the disk folder") {
    const std::size_t threadsBefore = threadCount();
    std::string folder;
    {
        SeriesCacheSettings settings;
        settings.memoryBudget = 0; // spill everything but the shown step
        settings.prefetchSteps = 6;
        SeriesCache cache(40, sphereLoader(40), settings);
        folder = cache.diskFolder();
        CHECK(std::filesystem::is_directory(folder));
        CHECK(threadCount() == threadsBefore + 1);
        const ExtractionSpec spec = visibleSpec();
        for (int s = 0; s < 3; ++s) {
            cache.show(s, +1);
            cache.voxelObject(s, spec);
        }
        cache.waitUntilIdle();
        CHECK(cache.stats().spills >= 2u);
        CHECK_FALSE(std::filesystem::is_empty(folder));
        cache.show(20, +1); // leave the worker busy prefetching
        cache.voxelObject(20, spec);
    }
    CHECK_FALSE(std::filesystem::exists(folder));
    CHECK(threadCount() == threadsBefore);
}
