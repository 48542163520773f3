#pragma once
// The idle-time optimizer (RTVR section 3.5): moves voxels that cannot contribute under the
// current tables to the end of their range, so that rendering never touches them.

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include <volsg/core/Object.h>
#include <volsg/shearwarp/VoxelObject.h>

namespace volsg {

/// A background thread that optimizes the RenderLists of the current view when asked to
/// (after a frame: the renderer is idle until the next one). It works in small chunks of
/// entries, each under the list's lock, so a frame waits at most for one chunk. Entries are
/// marked for re-optimisation by ShearWarpRenderer::prepare when tables change.
///
/// The classification uses RenderList::contributesUnclipped / contributesClipped: a voxel
/// whose attributes map to zero opacity under every view stays behind `last` / `lastClipped`.
/// Voxel order within a part is kept (stable partition), so the image does not change.
class VoxelListOptimizer {
public:
    VoxelListOptimizer();
    ~VoxelListOptimizer();
    VoxelListOptimizer(const VoxelListOptimizer&) = delete;
    VoxelListOptimizer& operator=(const VoxelListOptimizer&) = delete;

    /// Optimizes up to `maxEntries` entries of `list` that are not optimized yet, locking it.
    /// Returns how many it optimized.
    static std::size_t optimize(RenderList& list, std::size_t maxEntries = std::size_t(-1));
    /// Entries of `list` not optimized yet (locks it).
    static std::size_t pendingEntries(const RenderList& list);

    /// The lists the last frame drew (object and principal axis); starts the thread on them.
    void schedule(std::vector<std::pair<ref_ptr<VoxelObject>, int>> lists);
    /// Blocks until every scheduled list is fully optimized (for tests and benchmarks).
    void waitUntilIdle();

private:
    void run();
    std::mutex mutex_;
    std::condition_variable wake_, idle_;
    std::vector<std::pair<ref_ptr<VoxelObject>, int>> lists_;
    bool work_ = false, busy_ = false, stop_ = false;
    std::thread thread_;
};

} // namespace volsg
