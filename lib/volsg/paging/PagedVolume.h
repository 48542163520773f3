#pragma once
// A volume too large for memory, drawn from its OME-Zarr pyramid brick by brick: the source,
// the brick octree, the host brick cache and the levels kept whole (issue 26, part 2).

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <volsg/paging/BrickCache.h>
#include <volsg/paging/PagedLayout.h>
#include <volsg/volume/VolumeGrid.h>
#include <volsg/volumeio/PyramidSource.h>

namespace volsg {

/// How a PagedVolume uses memory.
struct PagedVolumeOptions {
    /// Host bytes for voxels: bricks, decoded chunks and the levels kept whole, together.
    std::uint64_t hostBudget = std::uint64_t(1) << 30;
    /// The coarse levels kept whole from the start (the stand-in and those above it) take at
    /// most this: the finest level that fits is the stand-in every whole-grid consumer sees.
    std::uint64_t standInBytes = 16u << 20;
    std::uint64_t chunkCacheBytes = 32u << 20; ///< decoded chunks shared by neighbouring bricks
    int loaderThreads = 2;
};

/// A pyramid opened for paging. The levels from the stand-in up are read whole when it opens
/// (the first image never waits for more); finer bricks load on the cache's threads when a
/// frame wants them. Brick edge: level 0's chunk edge (largest axis) less 2, so that a brick's
/// texture with its guard voxels is the size of a chunk (less 4 once the guard is wide).
class PagedVolume {
public:
    /// Opens `path` (PyramidSource's errors); an Error when the budget cannot hold the levels
    /// kept whole, the chunk cache and a few bricks of level 0.
    PagedVolume(const std::string& path, const PagedVolumeOptions& options);
    ~PagedVolume();

    const PyramidSource& source() const { return source_; }
    const PagedLayout& layout() const { return layout_; }
    const PagedVolumeOptions& options() const { return options_; }

    /// The stand-in: the finest level that fits standInBytes, whole, with its spacing set so
    /// that its box is level 0's (the whole-grid consumers see the volume in the right place).
    ref_ptr<const VolumeGrid> standIn() const { return whole_.at(standInLevel_); }
    int standInLevel() const { return standInLevel_; }
    /// A level kept whole (the stand-in or one above it), null for finer levels. The stand-in's
    /// spacing is adjusted (above); the others have their level's own.
    const VolumeGrid* keptWhole(int level) const {
        const auto it = whole_.find(level);
        return it == whole_.end() ? nullptr : it->second.get();
    }
    /// Level 0's smallest voxel edge: the opacity unit L0 of the rendering model.
    double finestSpacing() const;

    /// The brick's voxels when they can be had without waiting: cut from a level kept whole,
    /// or held by the cache (marked used). Null otherwise.
    std::shared_ptr<const HostBrick> find(const BrickKey& key);
    /// Whether find() would answer (without marking anything used).
    bool available(const BrickKey& key) const;
    /// Whether the brick could not be read (BrickCache::errors() says why): never wanted
    /// again, its parent stands in for it.
    bool failed(const BrickKey& key) const { return cache_->failed(key); }
    /// Asks the loaders for these bricks, most urgent first (levels kept whole are left out),
    /// as many as fill half the cache's budget: the caller takes them to the GPU and asks for
    /// the next ones in a later frame.
    void request(const std::vector<BrickKey>& wanted);

    /// For renderers that need the volume whole (shear-warp, whose voxel lists are made from
    /// one grid): the grid of level `wanted` when it is held, else the finest level held
    /// whole (the stand-in at least) while `wanted` loads on a background thread. A level
    /// wanted is first made coarser until it takes at most wholeLevelBudget(). `drawn` is the
    /// level returned, `loading` whether a finer one is on its way. Its spacing makes its box
    /// level 0's, as the stand-in's. Thread-safe; one level loads at a time, and the level
    /// held before is let go when a new one arrives.
    ref_ptr<const VolumeGrid> wholeLevel(int wanted, int& drawn, bool& loading);
    /// Bytes a level read whole for wholeLevel may take: half of what the bricks may.
    std::uint64_t wholeLevelBudget() const;
    /// Why a level could not be read whole (empty if none failed); it is not tried again.
    std::string wholeLevelError() const;

    /// Gives every brick a second guard voxel beyond each inner face (PagedLayout::reach 1),
    /// for a Volume that samples around its points: lighting's central differences read one
    /// voxel either side of a point, past the first guard voxel at seams, where a brick's
    /// texture would clamp (seams in the image). Once wide, for good: the PagedVolume is
    /// shared by every Volume of its VolumeData, which cannot know when it is opened how they
    /// draw it, and a lit and an unlit Volume would reload each other's bricks every frame if
    /// the guard followed the one drawing (the wide guard serves both: trilinear sampling
    /// never reads the extra layer). The bricks held are dropped (waiting for the loads under
    /// way): their voxels, and the octree (bricks of 2 cells fewer, so a texture stays the
    /// size of a chunk), change; textures made of the narrow ones are the caller's to drop
    /// (the slicer keys them by wideGuard()). Not while a frame uses layout().
    void widenGuard();
    bool wideGuard() const { return layout_.reach() > 0; }

    BrickCache& cache() { return *cache_; }
    const BrickCache& cache() const { return *cache_; }
    /// Host bytes held now: bricks, reserved loads, decoded chunks, levels kept whole.
    std::uint64_t hostBytes() const;
    std::uint64_t brickBytes(const BrickKey& key) const; ///< its voxels, guard included

private:
    PagedVolumeOptions options_;
    PyramidSource source_;
    PagedLayout layout_;
    int standInLevel_ = 0;
    std::map<int, ref_ptr<const VolumeGrid>> whole_; ///< the stand-in and every level above it
    std::uint64_t wholeBytes_ = 0;
    std::unique_ptr<BrickCache> cache_;
    /// wholeLevel's level beyond those kept whole, and its loader.
    mutable std::mutex levelMutex_;
    int extraLevel_ = -1;
    ref_ptr<const VolumeGrid> extraGrid_;
    int loadingLevel_ = -1;
    std::string levelError_;
    std::thread levelLoader_;
    std::uint64_t levelBytes(int level) const;
    /// A level read whole with its spacing making its box level 0's.
    ref_ptr<VolumeGrid> readWholeLevel(int level) const;
};

} // namespace volsg
