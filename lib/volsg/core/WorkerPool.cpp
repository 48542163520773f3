#include <volsg/core/WorkerPool.h>

#include <chrono>

namespace volsg {

namespace {

/// How long a thread spins for the next job or the end of this one before it sleeps.
constexpr auto kSpin = std::chrono::microseconds(200);

/// Spins until done() or kSpin has passed; true when done() held.
template <class Done> bool spinUntil(Done done) {
    const auto until = std::chrono::steady_clock::now() + kSpin;
    for (int i = 0;; ++i) {
        if (done()) return true;
#if defined(__x86_64__) || defined(__i386__)
        __builtin_ia32_pause(); // tells the core it is a spin loop
#endif
        if ((i & 63) == 63 && std::chrono::steady_clock::now() > until) return false;
    }
}

} // namespace

WorkerPool::~WorkerPool() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : workers_)
        t.join();
}

void WorkerPool::run(int count, const std::function<void(int)>& body) {
    if (count <= 1) {
        if (count == 1) body(0);
        return;
    }
    {
        std::lock_guard<std::mutex> lock(mutex_);
        while (int(workers_.size()) < count - 1) {
            const int index = int(workers_.size()) + 1;
            workers_.emplace_back([this, index] { work(index); });
        }
        body_ = &body;
        count_ = count;
        running_ = count - 1;
        error_ = nullptr;
        ++job_;
    }
    wake_.notify_all();
    std::exception_ptr callerError;
    try {
        body(0);
    } catch (...) {
        callerError = std::current_exception();
    }
    spinUntil([this] { return running_.load() == 0; });
    std::unique_lock<std::mutex> lock(mutex_);
    finished_.wait(lock, [this] { return running_.load() == 0; });
    body_ = nullptr;
    if (callerError) std::rethrow_exception(callerError);
    if (error_) std::rethrow_exception(error_);
}

void WorkerPool::work(int index) {
    std::uint64_t seen = 0;
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        if (!stop_ && job_.load() == seen) {
            lock.unlock();
            spinUntil([&] { return job_.load() != seen; });
            lock.lock();
        }
        wake_.wait(lock, [&] { return stop_ || job_.load() != seen; });
        if (stop_) return;
        seen = job_;
        if (index >= count_) continue; // a job with fewer indices: not counted in running_
        const std::function<void(int)>* body = body_;
        lock.unlock();
        std::exception_ptr error;
        try {
            (*body)(index);
        } catch (...) {
            error = std::current_exception();
        }
        lock.lock();
        if (error && !error_) error_ = error;
        if (--running_ == 0) finished_.notify_one();
    }
}

} // namespace volsg
