#pragma once
// The step cache of a volume series (RTVR sections 3.1 and 5: hundreds of time steps browsed
// interactively): each step's grid and extracted voxel lists, a memory tier with a byte
// budget, a disk tier in a private temporary folder, and one background thread that spills,
// reads back and prefetches in the direction of play. Design and locking: README.md here.
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <volsg/core/Object.h>
#include <volsg/shearwarp/VoxelObject.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

/// One time step's voxels (and labels, or null).
struct SeriesStepVolume {
    ref_ptr<const VolumeGrid> data, tags;
};

/// Makes step `index` (0 .. stepCount-1). Runs on the caller's thread or the cache's worker:
/// it must not touch scene nodes that another thread may change. Throws Error on failure.
using SeriesStepLoader = std::function<SeriesStepVolume(int index)>;

struct SeriesCacheSettings {
    /// Bytes of voxel lists kept in memory (the shown step's lists always stay, whatever
    /// their size); above it the worker spills the least useful lists to disk.
    std::size_t memoryBudget = std::size_t(256) << 20;
    int prefetchSteps = 2;  ///< steps made ready ahead in the direction of play
    bool loop = true;       ///< playing wraps around: prefetch past the last step goes to 0
    std::string diskParent; ///< where the cache's folder is made; empty: the system temp folder
    /// Spill files hold the RenderLists too (9 bytes a voxel per list), so a read-back step is
    /// drawn without a sort; false: the extracted arrays only (11 bytes a voxel), sorted again
    /// on read-back (less disk; the benchmark's "before").
    bool spillRenderLists = true;
};

struct SeriesCacheStats {
    std::uint64_t extractions = 0;     ///< voxel-list extractions (any thread)
    std::uint64_t gridLoads = 0;       ///< steps loaded or generated
    std::uint64_t spills = 0;          ///< lists written to disk
    std::uint64_t diskReads = 0;       ///< lists read back from disk
    std::uint64_t memoryHits = 0;      ///< requests answered from memory
    std::uint64_t waits = 0;           ///< requests that waited for the worker's work in flight
    std::uint64_t renderListSorts = 0; ///< RenderLists the cache sorted (read-backs adopt theirs)
    std::uint64_t damagedFiles = 0;    ///< spill files refused on read (the step is re-extracted)
    std::size_t memoryBytes = 0;       ///< voxel lists in memory now
    std::size_t memoryHighWater = 0;   ///< largest memoryBytes seen
    std::size_t gridBytes = 0;         ///< grids held now (shown step and prefetched ones)
    std::size_t gridHighWater = 0;
    std::size_t diskBytes = 0; ///< bytes in the disk tier
};

/// Thread-safe. The render thread calls show() when the step changes, then volume() and
/// voxelObject() for what it draws; the worker prepares everything else. A request never
/// loses a step: in memory, on disk, or in flight (then the request waits for it), else it is
/// made on the spot.
class SeriesCache {
public:
    /// Creates the disk folder (`volsg-series-XXXXXX`) and starts the worker. stepCount >= 1.
    SeriesCache(int stepCount, SeriesStepLoader loader, SeriesCacheSettings settings = {});
    /// Stops the worker (after the task in hand), joins it, removes the disk folder.
    ~SeriesCache();
    SeriesCache(const SeriesCache&) = delete;
    SeriesCache& operator=(const SeriesCache&) = delete;

    int stepCount() const { return stepCount_; }
    /// The step now shown and the direction of play (+1, -1; 0: paused, prefetch both ways).
    /// Its lists are pinned in memory; the worker then prefetches the next steps.
    void show(int step, int direction);
    int shownStep() const;
    void setMemoryBudget(std::size_t bytes);
    /// SeriesCacheSettings::spillRenderLists for the spills from now on.
    void setSpillRenderLists(bool spill);
    /// The principal axis the renderer drew last: the worker builds that RenderList of the
    /// lists it prefetches, so showing them costs no sort.
    void setViewAxis(int axis);

    /// The grid of a step, loaded here if it is not ready. Throws what the loader throws.
    /// `prefetchGrids`: from now on the worker also loads the grids of the steps ahead (the
    /// texture path needs them; a bounding box alone does not).
    SeriesStepVolume volume(int step, bool prefetchGrids = true);
    /// The extracted voxels of `step` for `spec`: from memory, from disk, or extracted now.
    /// Registers `spec` as wanted: the worker prefetches it for the next steps.
    ref_ptr<VoxelObject> voxelObject(int step, const ExtractionSpec& spec);

    /// The step play shows after the shown one: in the direction of play (forward when
    /// paused), wrapping when looping; -1 past either end without loop.
    int nextStep() const;
    /// The grids of `step` if they are in memory now (shown or prefetched), else empty; never
    /// loads (the texture path stages the next step's upload only when it is ready).
    SeriesStepVolume peekVolume(int step) const;

    /// The local extent (dimensions * spacing) of a step if known without loading: from its
    /// grid or its lists in memory.
    std::optional<glm::dvec3> knownExtent(int step) const;

    /// What voxelObject() would return from memory, or null; no side effects (for tests).
    ref_ptr<VoxelObject> peek(int step, const ExtractionSpec& spec) const;
    bool isInMemory(int step, const ExtractionSpec& spec) const;
    bool isOnDisk(int step, const ExtractionSpec& spec) const;

    /// Blocks until the worker has nothing left to do (tests, benchmarks).
    void waitUntilIdle();
    SeriesCacheStats stats() const;
    const std::string& diskFolder() const { return diskFolder_; }

    /// The key of an extraction: the spec's content, with the transfer function's points only
    /// where they select voxels (Visible selection or a Whole source), else its data range.
    static std::uint64_t extractionKey(const ExtractionSpec& spec);

private:
    using Key = std::pair<int, std::uint64_t>; // (step, extraction key)
    struct ListEntry {
        ref_ptr<VoxelObject> object; ///< null: not in memory
        std::size_t bytes = 0;       ///< counted in memoryBytes while object is set
        std::size_t diskBytes = 0;   ///< > 0: a copy is on disk
        unsigned diskLists = 0;      ///< bit a: the disk copy holds the RenderList of axis a
        bool busy = false;           ///< a thread is extracting, reading or writing it
        std::uint64_t lastUse = 0;
    };

    const int stepCount_;
    const SeriesStepLoader loader_;
    SeriesCacheSettings settings_;
    std::string diskFolder_;

    mutable std::mutex mutex_;        // guards everything below
    std::condition_variable changed_; // any entry, grid or task state changed
    std::map<Key, ListEntry> lists_;
    std::map<int, SeriesStepVolume> grids_;
    std::set<int> gridsInFlight_;
    std::set<int> failedSteps_; // the worker does not retry these; requests do
    std::map<std::uint64_t, ExtractionSpec> wanted_, requestedSinceShow_;
    bool gridsWanted_ = false, gridsRequestedSinceShow_ = false;
    int shown_ = 0, direction_ = 1, viewAxis_ = -1;
    std::uint64_t tick_ = 0;
    bool workerBusy_ = false, stop_ = false;
    bool dirty_ = false;      // something changed that the worker has not looked at yet
    bool diskFailed_ = false; // a spill failed (disk full): evicted lists are dropped instead
    SeriesCacheStats stats_;
    std::thread worker_;

    void workerLoop();
    bool spillOne(std::unique_lock<std::mutex>& lock);
    /// Spills or drops one list that is not the shown step's (with `outsideWindowOnly`, nor
    /// a prefetch window step's), the least useful first; false when there is none.
    bool evictOne(std::unique_lock<std::mutex>& lock, bool outsideWindowOnly);
    bool prefetchOne(std::unique_lock<std::mutex>& lock);
    void trimGrids();
    std::vector<std::pair<int, int>> windowSteps() const; ///< (step, distance), nearest first
    SeriesStepVolume gridLocked(int step, std::unique_lock<std::mutex>& lock);
    ref_ptr<VoxelObject> produceLocked(const Key& key, const ExtractionSpec& spec,
                                       std::unique_lock<std::mutex>& lock, bool byWorker);
    void addMemory(ListEntry& entry, ref_ptr<VoxelObject> object);
    void dropMemory(ListEntry& entry);
    std::string pathOf(const Key& key) const;
};

} // namespace volsg
