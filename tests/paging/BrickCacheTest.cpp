// BrickCache: the byte budget holds at every moment, eviction is least recently used first,
// loads follow the wanted order, failures are recorded once, and shutdown never hangs.
#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

#include <volsg/core/Error.h>
#include <volsg/paging/BrickCache.h>

using namespace volsg;

namespace {

/// A brick of level l is (4 + l)^3 bytes of UByte voxels, all holding its x index.
std::uint64_t sizeOf(const BrickKey& key) {
    const int side = 4 + key.level;
    return std::uint64_t(side) * side * side;
}

HostBrick makeBrick(const BrickKey& key) {
    const int side = 4 + key.level;
    auto grid = VolumeGrid::create(glm::ivec3(side), VoxelType::UByte);
    for (std::size_t i = 0; i < grid->voxelCount(); ++i)
        grid->setValue(i, double(key.index.x % 256));
    return {grid, double(key.index.x % 256), double(key.index.x % 256)};
}

std::vector<BrickKey> keys(int count, int level = 0) {
    std::vector<BrickKey> out;
    for (int i = 0; i < count; ++i)
        out.push_back({level, {i, 0, 0}});
    return out;
}

} // namespace

TEST_CASE("the held and reserved bytes never exceed the budget, with four loaders") {
    const std::uint64_t budget = 1000; // room for a few bricks of 64 to 343 bytes
    std::atomic<std::uint64_t> worst{0};
    std::atomic<bool> sampling{true};
    {
        BrickCache cache(budget, 4, makeBrick, sizeOf);
        std::thread sampler([&] {
            while (sampling) {
                const BrickCacheStats s = cache.stats();
                std::uint64_t seen = worst;
                const std::uint64_t now = s.residentBytes + s.loadingBytes;
                while (now > seen && !worst.compare_exchange_weak(seen, now)) {
                }
            }
        });
        for (int round = 0; round < 30; ++round) {
            std::vector<BrickKey> wanted;
            for (int i = 0; i < 20; ++i)
                wanted.push_back({i % 4, {(round * 7 + i) % 50, i % 3, 0}});
            cache.request(wanted);
            for (const BrickKey& k : wanted)
                if (const auto brick = cache.find(k)) CHECK(brick->voxels->value(0) == k.index.x);
        }
        CHECK(cache.waitIdle(10000));
        sampling = false;
        sampler.join();
        const BrickCacheStats s = cache.stats();
        CHECK(s.peakBytes <= budget);
        CHECK(s.residentBytes <= budget);
        CHECK(s.loaded > 10);
        CHECK(s.evicted > 0);
    }
    CHECK(worst <= budget);
}

TEST_CASE("the least recently used brick is evicted first") {
    // Three bricks of 64 bytes fit a budget of 200.
    BrickCache cache(200, 1, makeBrick, sizeOf);
    cache.request(keys(3));
    REQUIRE(cache.waitIdle(10000));
    REQUIRE(cache.find({0, {0, 0, 0}})); // brick 0 used now: brick 1 is the oldest
    cache.request({{0, {3, 0, 0}}});
    REQUIRE(cache.waitIdle(10000));
    CHECK(cache.holds({0, {0, 0, 0}}));
    CHECK_FALSE(cache.holds({0, {1, 0, 0}}));
    CHECK(cache.holds({0, {2, 0, 0}}));
    CHECK(cache.holds({0, {3, 0, 0}}));
    CHECK(cache.stats().evicted == 1);
}

TEST_CASE("one loader takes the wanted bricks in the order asked") {
    std::mutex mutex;
    std::vector<int> order;
    std::atomic<bool> release{false};
    BrickCache cache(
        1 << 20, 1,
        [&](const BrickKey& key) {
            while (!release)
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            std::lock_guard lock(mutex);
            order.push_back(key.index.x);
            return makeBrick(key);
        },
        sizeOf);
    cache.request({{0, {9, 0, 0}}}); // taken at once, held back by the loader
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    cache.request({{0, {5, 0, 0}}, {0, {9, 0, 0}}, {0, {2, 0, 0}}, {0, {7, 0, 0}}});
    release = true;
    REQUIRE(cache.waitIdle(10000));
    CHECK(order == std::vector<int>{9, 5, 2, 7});
}

TEST_CASE("a failed load is recorded once with its message and not retried") {
    std::atomic<int> calls{0};
    BrickCache cache(
        1 << 20, 2,
        [&](const BrickKey& key) -> HostBrick {
            ++calls;
            if (key.index.x == 1) throw Error("chunk 0/0/1 is corrupt", "/data/x.zarr/0/.zarray");
            return makeBrick(key);
        },
        sizeOf);
    for (int i = 0; i < 5; ++i) {
        cache.request(keys(3));
        REQUIRE(cache.waitIdle(10000));
    }
    CHECK(calls == 3);
    CHECK(cache.failed({0, {1, 0, 0}}));
    CHECK_FALSE(cache.find({0, {1, 0, 0}}));
    REQUIRE(cache.errors().size() == 1);
    CHECK(cache.errors()[0].find("chunk 0/0/1 is corrupt") != std::string::npos);
    CHECK(cache.stats().failed == 1);
}

TEST_CASE("a brick larger than the budget is an error, not a load") {
    BrickCache cache(100, 1, makeBrick, sizeOf);
    cache.request({{3, {0, 0, 0}}}); // 343 bytes
    REQUIRE(cache.waitIdle(10000));
    CHECK(cache.failed({3, {0, 0, 0}}));
    REQUIRE(cache.errors().size() == 1);
    CHECK(cache.errors()[0].find("more than the host budget of 100") != std::string::npos);
}

TEST_CASE("destroying the cache with a long queue and slow loads returns promptly") {
    const auto started = std::chrono::steady_clock::now();
    {
        BrickCache cache(
            1 << 20, 3,
            [](const BrickKey& key) {
                std::this_thread::sleep_for(std::chrono::milliseconds(20));
                return makeBrick(key);
            },
            sizeOf);
        cache.request(keys(1000));
        std::this_thread::sleep_for(std::chrono::milliseconds(30));
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    CHECK(seconds < 2.0); // 1000 loads of 20 ms on 3 threads would take 7 s
}

TEST_CASE("clear waits for the loads under way, then drops the bricks held and the failures") {
    std::atomic<int> loads{0};
    BrickCache cache(
        1 << 20, 2,
        [&](const BrickKey& key) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            ++loads;
            if (key.index.x == 1) throw Error("unreadable");
            return makeBrick(key);
        },
        sizeOf);
    cache.request(keys(8));
    REQUIRE(cache.waitIdle(5000));
    CHECK(cache.stats().resident == 7);
    CHECK(cache.failed({0, {1, 0, 0}}));
    cache.request(keys(64)); // some under way when cleared, the rest dropped
    cache.clear();
    const BrickCacheStats s = cache.stats();
    CHECK(s.resident == 0);
    CHECK(s.loading == 0);
    CHECK(s.queued == 0);
    CHECK(s.residentBytes == 0);
    CHECK(s.loadingBytes == 0);
    CHECK(cache.idle());
    CHECK_FALSE(cache.failed({0, {1, 0, 0}}));
    const int before = loads;
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    CHECK(loads == before); // idle until asked again
    cache.request(keys(4));
    REQUIRE(cache.waitIdle(5000));
    CHECK(cache.holds({0, {3, 0, 0}}));
    CHECK(cache.failed({0, {1, 0, 0}})); // tried again
    CHECK(cache.stats().resident == 3);
}
