#include <volsg/paging/BrickCache.h>

#include <algorithm>
#include <chrono>

#include <volsg/core/Error.h>

namespace volsg {

namespace {

constexpr std::size_t kMaxErrors = 16;

std::string keyText(const BrickKey& key) {
    return "brick " + std::to_string(key.index.x) + " " + std::to_string(key.index.y) + " " +
           std::to_string(key.index.z) + " of level " + std::to_string(key.level);
}

} // namespace

BrickCache::BrickCache(std::uint64_t budgetBytes, int threads, Loader load, Size sizeOf)
    : budget_(budgetBytes), load_(std::move(load)), sizeOf_(std::move(sizeOf)) {
    stats_.budgetBytes = budget_;
    for (int t = 0; t < std::max(threads, 1); ++t)
        threads_.emplace_back([this] { work(); });
}

BrickCache::~BrickCache() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
        queue_.clear();
        next_ = 0;
    }
    wake_.notify_all();
    for (std::thread& t : threads_)
        t.join();
}

std::shared_ptr<const HostBrick> BrickCache::find(const BrickKey& key) {
    std::lock_guard lock(mutex_);
    const auto it = held_.find(key);
    if (it == held_.end()) return nullptr;
    recent_.splice(recent_.begin(), recent_, it->second.place);
    return it->second.brick;
}

bool BrickCache::holds(const BrickKey& key) const {
    std::lock_guard lock(mutex_);
    return held_.count(key) != 0;
}

bool BrickCache::failed(const BrickKey& key) const {
    std::lock_guard lock(mutex_);
    return failed_.count(key) != 0;
}

void BrickCache::request(std::vector<BrickKey> wanted) {
    {
        std::lock_guard lock(mutex_);
        queue_ = std::move(wanted);
        next_ = 0;
    }
    wake_.notify_all();
    settled_.notify_all();
}

void BrickCache::clear() {
    std::unique_lock lock(mutex_);
    queue_.clear();
    next_ = 0;
    settled_.wait(lock, [&] { return loading_.empty(); });
    held_.clear();
    recent_.clear();
    failed_.clear();
    stats_.residentBytes = 0;
    wake_.notify_all(); // loaders waiting for room re-check the (empty) list
    settled_.notify_all();
}

bool BrickCache::takeable(std::size_t& at) const {
    while (at < queue_.size()) {
        const BrickKey& key = queue_[at];
        if (!held_.count(key) && !loading_.count(key) && !failed_.count(key)) return true;
        ++at;
    }
    return false;
}

bool BrickCache::idle() const {
    std::lock_guard lock(mutex_);
    std::size_t at = next_;
    return loading_.empty() && !takeable(at);
}

bool BrickCache::waitIdle(int milliseconds) const {
    std::unique_lock lock(mutex_);
    return settled_.wait_for(lock, std::chrono::milliseconds(milliseconds), [&] {
        std::size_t at = next_;
        return loading_.empty() && !takeable(at);
    });
}

BrickCacheStats BrickCache::stats() const {
    std::lock_guard lock(mutex_);
    BrickCacheStats s = stats_;
    s.resident = int(held_.size());
    s.loading = int(loading_.size());
    std::size_t at = next_;
    int queued = 0;
    while (takeable(at)) {
        ++queued;
        ++at;
    }
    s.queued = queued;
    return s;
}

std::vector<std::string> BrickCache::errors() const {
    std::lock_guard lock(mutex_);
    return errors_;
}

bool BrickCache::makeRoom(std::uint64_t bytes) {
    while (stats_.residentBytes + stats_.loadingBytes + bytes > budget_) {
        if (recent_.empty()) return false; // loads under way hold the rest: wait for them
        const auto victim = held_.find(recent_.back());
        stats_.residentBytes -= victim->second.bytes;
        held_.erase(victim);
        recent_.pop_back();
        ++stats_.evicted;
    }
    return true;
}

void BrickCache::work() {
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [&] { return stopping_ || takeable(next_); });
        if (stopping_) return;
        const BrickKey key = queue_[next_];
        const std::uint64_t bytes = sizeOf_(key);
        if (bytes > budget_) {
            failed_.insert(key);
            ++stats_.failed;
            if (errors_.size() < kMaxErrors)
                errors_.push_back(keyText(key) + " takes " + std::to_string(bytes) +
                                  " bytes, more than the host budget of " +
                                  std::to_string(budget_));
            settled_.notify_all();
            continue;
        }
        if (!makeRoom(bytes)) {
            // Woken again when a load finishes (its bytes become evictable) or the list changes.
            wake_.wait(lock);
            continue;
        }
        ++next_;
        loading_.insert(key);
        stats_.loadingBytes += bytes;
        stats_.peakBytes = std::max(stats_.peakBytes, stats_.residentBytes + stats_.loadingBytes);
        lock.unlock();

        const auto started = std::chrono::steady_clock::now();
        HostBrick brick;
        std::string error;
        try {
            brick = load_(key);
            if (!brick.voxels) error = keyText(key) + ": the loader returned no voxels";
        } catch (const std::exception& e) {
            error = e.what();
        }
        const double milliseconds =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
                .count();

        lock.lock();
        loading_.erase(key);
        stats_.loadingBytes -= bytes;
        stats_.loadMilliseconds += milliseconds;
        if (!error.empty()) {
            failed_.insert(key);
            ++stats_.failed;
            if (errors_.size() < kMaxErrors) errors_.push_back(error);
        } else if (!stopping_) {
            recent_.push_front(key);
            held_[key] =
                Entry{std::make_shared<const HostBrick>(std::move(brick)), bytes, recent_.begin()};
            stats_.residentBytes += bytes;
            ++stats_.loaded;
            stats_.loadedBytes += bytes;
        }
        wake_.notify_all();
        settled_.notify_all();
    }
}

} // namespace volsg
