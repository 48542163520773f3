#include <volsg/shearwarp/VoxelListOptimizer.h>

#include <volsg/shearwarp/PackedVoxel.h>

namespace volsg {

namespace {

constexpr std::size_t kChunkEntries = 16; // entries per lock: bounds how long a frame waits

} // namespace

VoxelListOptimizer::VoxelListOptimizer() : thread_([this] { run(); }) {}

VoxelListOptimizer::~VoxelListOptimizer() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

std::size_t VoxelListOptimizer::optimize(RenderList& list, std::size_t maxEntries) {
    std::lock_guard lock(list.mutex);
    std::size_t done = 0;
    const auto& unclipped = list.contributesUnclipped;
    const auto& clipped = list.contributesClipped;
    for (RenderListEntry& e : list.entries) {
        if (done >= maxEntries) break;
        if (e.optimized) continue;
        if (!unclipped.empty())
            e.last = list.partition(e.first, e.firstClipped, [&](std::uint32_t i) {
                return unclipped[PackedVoxel::attributes16(list.packed[i])] != 0;
            });
        if (!clipped.empty())
            e.lastClipped = list.partition(e.firstClipped, e.lastInSlice, [&](std::uint32_t i) {
                return clipped[PackedVoxel::attributes16(list.packed[i])] != 0;
            });
        e.optimized = true;
        ++done;
    }
    return done;
}

std::size_t VoxelListOptimizer::pendingEntries(const RenderList& list) {
    std::lock_guard lock(list.mutex);
    std::size_t pending = 0;
    for (const RenderListEntry& e : list.entries)
        pending += e.optimized ? 0 : 1;
    return pending;
}

void VoxelListOptimizer::schedule(std::vector<std::pair<ref_ptr<VoxelObject>, int>> lists) {
    {
        std::lock_guard lock(mutex_);
        lists_ = std::move(lists);
        work_ = true;
    }
    wake_.notify_all();
}

void VoxelListOptimizer::waitUntilIdle() {
    std::unique_lock lock(mutex_);
    idle_.wait(lock, [&] { return !work_ && !busy_; });
}

void VoxelListOptimizer::run() {
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [&] { return work_ || stop_; });
        if (stop_) return;
        auto lists = lists_;
        work_ = false;
        busy_ = true;
        lock.unlock();
        for (auto& [object, axis] : lists) {
            if (!object->hasRenderList(axis)) continue;
            RenderList& list = object->renderList(axis);
            while (optimize(list, kChunkEntries) > 0) {
                std::this_thread::yield(); // let a waiting frame take the lock
                std::lock_guard check(mutex_);
                if (stop_ || work_) break; // new lists (or shutdown): start over
            }
        }
        lock.lock();
        busy_ = false;
        if (!work_) idle_.notify_all();
    }
}

} // namespace volsg
