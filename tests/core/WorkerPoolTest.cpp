#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include <volsg/core/WorkerPool.h>

using namespace volsg;

TEST_CASE("a worker pool runs every index of each job once, index 0 on the caller") {
    WorkerPool pool;
    const std::thread::id caller = std::this_thread::get_id();
    // Jobs of changing sizes reuse the workers: a job smaller than the pool leaves the extra
    // workers out, a larger one starts more.
    for (int count : {3, 1, 2, 4, 2, 0, 3}) {
        std::vector<std::atomic<int>> runs(std::size_t(std::max(count, 1)));
        std::atomic<bool> zeroOnCaller{false};
        std::mutex mutex;
        std::set<std::thread::id> threads;
        pool.run(count, [&](int i) {
            runs[std::size_t(i)] += 1;
            if (i == 0) zeroOnCaller = std::this_thread::get_id() == caller;
            std::lock_guard<std::mutex> lock(mutex);
            threads.insert(std::this_thread::get_id());
        });
        for (int i = 0; i < count; ++i)
            CHECK(runs[std::size_t(i)] == 1);
        if (count > 0) CHECK(zeroOnCaller);
        CHECK(int(threads.size()) == count); // each index on its own thread
    }
}

TEST_CASE("a worker pool rethrows what a body throws and stays usable") {
    WorkerPool pool;
    CHECK_THROWS_AS(pool.run(3,
                             [](int i) {
                                 if (i == 2) throw std::runtime_error("worker");
                             }),
                    std::runtime_error);
    CHECK_THROWS_AS(pool.run(2,
                             [](int i) {
                                 if (i == 0) throw std::logic_error("caller");
                             }),
                    std::logic_error);
    std::atomic<int> sum{0};
    pool.run(3, [&](int i) { sum += i + 1; });
    CHECK(sum == 6);
}
