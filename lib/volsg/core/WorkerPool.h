#pragma once
// Threads kept between parallel jobs (a renderer runs two or three jobs a frame).

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace volsg {

/// Runs body(0) ... body(count - 1) at once: index 0 on the calling thread, the others on
/// workers the pool keeps (started on first need). Starting a thread per job cost about 0.1 ms
/// a frame on the shared 2-core machine; waking a kept one costs a few microseconds. One job at
/// a time (run() is not reentrant); the first exception a body throws is rethrown by run().
/// Between jobs a worker spins for a moment before it sleeps, and so does the caller waiting
/// for the workers: a renderer's jobs come microseconds apart, and a futex wake-up costs tens.
class WorkerPool {
public:
    WorkerPool() = default;
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    void run(int count, const std::function<void(int)>& body);

private:
    void work(int index);

    std::mutex mutex_;
    std::condition_variable wake_, finished_;
    std::vector<std::thread> workers_; ///< worker i runs index i + 1
    const std::function<void(int)>* body_ = nullptr;
    int count_ = 0;
    std::atomic<int> running_{0}; ///< workers still in the current job
    std::atomic<std::uint64_t> job_{0};
    bool stop_ = false;
    std::exception_ptr error_;
};

} // namespace volsg
