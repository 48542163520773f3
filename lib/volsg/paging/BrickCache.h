#pragma once
// Bricks of voxels in host memory, loaded on background threads under a byte budget.

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <volsg/paging/BrickKey.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

/// A loaded brick: its voxels (guard voxels included) and their range, measured on the loader
/// thread so that the renderer can tell an empty brick without touching its voxels.
struct HostBrick {
    ref_ptr<const VolumeGrid> voxels;
    double minimum = 0.0, maximum = 0.0; ///< finite values only
};

/// What a BrickCache holds and has done (a snapshot).
struct BrickCacheStats {
    std::uint64_t budgetBytes = 0;
    std::uint64_t residentBytes = 0; ///< bricks held
    std::uint64_t loadingBytes = 0;  ///< reserved by loads under way
    std::uint64_t peakBytes = 0;     ///< largest residentBytes + loadingBytes so far
    int resident = 0, loading = 0, queued = 0;
    std::uint64_t loaded = 0, evicted = 0, failed = 0;
    std::uint64_t loadedBytes = 0;
    double loadMilliseconds = 0.0; ///< summed over the loader threads
};

/// Host bricks under a byte budget, loaded by `threads` background threads.
///
/// - request() replaces the list of bricks wanted, most urgent first (the renderer asks each
///   frame: coarse levels first, then nearest to the viewer); the loaders take them in that
///   order, skipping those held or loading. Requests never block.
/// - A load reserves its brick's bytes (`sizeOf`, known before reading) before it starts: the
///   held bytes plus the reserved ones never exceed the budget. Room is made by evicting the
///   least recently used bricks (find() marks a brick used); a brick larger than the budget is
///   an error, not a load.
/// - find() answers at once: the brick, or null when it is not held.
/// - A load that throws is recorded (errors(), once per brick, first message kept) and not
///   retried.
/// - The destructor drops what is queued, waits for the loads under way, and joins.
///
/// Bricks handed out by find() are shared: one held by a caller after its eviction is memory
/// the budget no longer counts, so callers keep them only while they use them (an upload).
class BrickCache {
public:
    using Loader = std::function<HostBrick(const BrickKey&)>;
    using Size = std::function<std::uint64_t(const BrickKey&)>;

    BrickCache(std::uint64_t budgetBytes, int threads, Loader load, Size sizeOf);
    ~BrickCache();
    BrickCache(const BrickCache&) = delete;
    BrickCache& operator=(const BrickCache&) = delete;

    /// The brick when held (and marks it used), else null.
    std::shared_ptr<const HostBrick> find(const BrickKey& key);
    /// Whether the brick is held, without marking it used.
    bool holds(const BrickKey& key) const;
    /// Whether the brick failed to load.
    bool failed(const BrickKey& key) const;

    /// The bricks wanted now, most urgent first; replaces the previous list.
    void request(std::vector<BrickKey> wanted);

    /// Drops the wanted list, waits for the loads under way, then drops every brick held and
    /// the record of failures (the caller's keys may name other bricks from now on). The
    /// loaders stay idle until the next request().
    void clear();

    /// Nothing queued and nothing loading.
    bool idle() const;
    /// Waits until idle() or `milliseconds` pass; returns idle().
    bool waitIdle(int milliseconds) const;

    BrickCacheStats stats() const;
    /// The first message of each brick that failed (at most 16).
    std::vector<std::string> errors() const;

private:
    void work();
    bool makeRoom(std::uint64_t bytes); ///< under the lock
    /// Moves `at` to the first queued brick neither held, loading nor failed; under the lock.
    bool takeable(std::size_t& at) const;

    struct Entry {
        std::shared_ptr<const HostBrick> brick;
        std::uint64_t bytes = 0;
        std::list<BrickKey>::iterator place;
    };

    const std::uint64_t budget_;
    const Loader load_;
    const Size sizeOf_;

    mutable std::mutex mutex_;
    mutable std::condition_variable wake_;    ///< loaders: work queued, room made, or stop
    mutable std::condition_variable settled_; ///< waitIdle: a load finished or the queue changed
    bool stopping_ = false;
    std::vector<BrickKey> queue_; ///< wanted, most urgent first
    std::size_t next_ = 0;        ///< the first entry of queue_ not yet taken
    std::set<BrickKey> loading_;
    std::set<BrickKey> failed_;
    std::vector<std::string> errors_;
    std::map<BrickKey, Entry> held_;
    std::list<BrickKey> recent_; ///< held bricks, most recently used first
    BrickCacheStats stats_;
    std::vector<std::thread> threads_;
};

} // namespace volsg
