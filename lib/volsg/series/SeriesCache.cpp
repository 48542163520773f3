#include <volsg/series/SeriesCache.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <tuple>
#include <vector>

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

#include <volsg/core/Error.h>
#include <volsg/core/KeyMixing.h>
#include <volsg/series/SpillFile.h>

namespace volsg {

namespace {

constexpr int kMaxPrefetchSteps = 64;

std::string makeDiskFolder(const std::string& parent) {
    std::filesystem::path base =
        parent.empty() ? std::filesystem::temp_directory_path() : std::filesystem::path(parent);
    std::string pattern = (base / "volsg-series-XXXXXX").string();
    if (!::mkdtemp(pattern.data()))
        throw Error("cannot create the series disk cache folder in " + base.string());
    return pattern;
}

/// Bit a set: the object has its RenderList for axis a.
unsigned listMaskOf(const VoxelObject& object) {
    unsigned mask = 0;
    for (int axis = 0; axis < 3; ++axis)
        if (object.hasRenderList(axis)) mask |= 1u << axis;
    return mask;
}

std::size_t gridBytesOf(const SeriesStepVolume& v) {
    return (v.data ? v.data->byteSize() : 0) + (v.tags ? v.tags->byteSize() : 0);
}

void mixChannel(std::uint64_t& key, const PiecewiseLinear& channel) {
    key = mixKey(key, channel.points().size());
    for (const PiecewiseLinear::Point& p : channel.points())
        key = mixKey(mixKey(key, bitsOf(p.x)), bitsOf(p.y));
}

} // namespace

std::uint64_t SeriesCache::extractionKey(const ExtractionSpec& spec) {
    std::uint64_t key = 0xcbf29ce484222325ULL;
    key = mixKey(key, std::uint64_t(spec.source.kind));
    key = mixKey(key, std::uint64_t(std::int64_t(spec.source.tag)));
    key = mixKey(key, bitsOf(spec.source.low));
    key = mixKey(key, bitsOf(spec.source.high));
    key = mixKey(key, std::uint64_t(spec.selection));
    key = mixKey(key, bitsOf(spec.gradientThreshold));
    const TransferFunction1D& tf = spec.transferFunction;
    if (const auto& range = tf.dataRange())
        key = mixKey(mixKey(mixKey(key, 1), bitsOf(range->x)), bitsOf(range->y));
    // As VolumeObject's own cache: the function's shape selects voxels only here.
    if (spec.selection == VoxelSelection::Visible || spec.source.kind == ObjectSource::Whole)
        for (int c = 0; c < 4; ++c)
            mixChannel(key, tf.channel(TransferFunction1D::Channel(c)));
    return key;
}

SeriesCache::SeriesCache(int stepCount, SeriesStepLoader loader, SeriesCacheSettings settings)
    : stepCount_(stepCount), loader_(std::move(loader)), settings_(std::move(settings)) {
    if (stepCount_ < 1) throw Error("a volume series needs at least one step");
    if (!loader_) throw Error("a volume series needs a step loader");
    settings_.prefetchSteps = std::clamp(settings_.prefetchSteps, 0, kMaxPrefetchSteps);
    diskFolder_ = makeDiskFolder(settings_.diskParent);
    worker_ = std::thread([this] { workerLoop(); });
}

SeriesCache::~SeriesCache() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
        dirty_ = true;
    }
    changed_.notify_all();
    worker_.join();
    std::error_code ignored; // nothing useful to do about a folder that will not go
    std::filesystem::remove_all(diskFolder_, ignored);
}

int SeriesCache::shownStep() const {
    std::lock_guard lock(mutex_);
    return shown_;
}

void SeriesCache::show(int step, int direction) {
    if (step < 0 || step >= stepCount_)
        throw Error("series step " + std::to_string(step) + " outside 0.." +
                    std::to_string(stepCount_ - 1));
    std::lock_guard lock(mutex_);
    // The lists just shown may have grown RenderLists while drawn: count them now.
    for (auto& [key, entry] : lists_)
        if (key.first == shown_ && entry.object) {
            const std::size_t bytes = entry.object->memoryBytes();
            stats_.memoryBytes = stats_.memoryBytes - entry.bytes + bytes;
            entry.bytes = bytes;
        }
    stats_.memoryHighWater = std::max(stats_.memoryHighWater, stats_.memoryBytes);
    shown_ = step;
    direction_ = direction > 0 ? 1 : direction < 0 ? -1 : 0;
    if (!requestedSinceShow_.empty()) wanted_ = std::move(requestedSinceShow_);
    requestedSinceShow_.clear();
    gridsWanted_ = gridsRequestedSinceShow_ || gridsWanted_;
    gridsRequestedSinceShow_ = false;
    failedSteps_.clear(); // a step that failed may load now; the worker tries once more
    trimGrids();
    dirty_ = true;
    changed_.notify_all();
}

void SeriesCache::setMemoryBudget(std::size_t bytes) {
    std::lock_guard lock(mutex_);
    settings_.memoryBudget = bytes;
    dirty_ = true;
    changed_.notify_all();
}

void SeriesCache::setSpillRenderLists(bool spill) {
    std::lock_guard lock(mutex_);
    settings_.spillRenderLists = spill;
}

void SeriesCache::setViewAxis(int axis) {
    std::lock_guard lock(mutex_);
    if (axis == viewAxis_ || axis < 0 || axis > 2) return;
    viewAxis_ = axis;
    dirty_ = true;
    changed_.notify_all();
}

SeriesStepVolume SeriesCache::volume(int step, bool prefetchGrids) {
    if (step < 0 || step >= stepCount_)
        throw Error("series step " + std::to_string(step) + " outside 0.." +
                    std::to_string(stepCount_ - 1));
    std::unique_lock lock(mutex_);
    if (!prefetchGrids) return gridLocked(step, lock);
    gridsRequestedSinceShow_ = true;
    if (!gridsWanted_) {
        gridsWanted_ = true;
        dirty_ = true;
        changed_.notify_all();
    }
    return gridLocked(step, lock);
}

ref_ptr<VoxelObject> SeriesCache::voxelObject(int step, const ExtractionSpec& spec) {
    if (step < 0 || step >= stepCount_)
        throw Error("series step " + std::to_string(step) + " outside 0.." +
                    std::to_string(stepCount_ - 1));
    const Key key{step, extractionKey(spec)};
    std::unique_lock lock(mutex_);
    requestedSinceShow_.insert_or_assign(key.second, spec);
    if (wanted_.emplace(key.second, spec).second) {
        dirty_ = true;
        changed_.notify_all();
    }
    bool waited = false;
    while (true) {
        ListEntry& entry = lists_[key];
        if (entry.object) {
            entry.lastUse = ++tick_;
            ++stats_.memoryHits;
            return entry.object;
        }
        if (!entry.busy) {
            ref_ptr<VoxelObject> object = produceLocked(key, spec, lock, false);
            // Memory stays bounded when steps are shown faster than the disk takes them: the
            // request waits until the worker has spilled everything but this step beyond the
            // budget (or can spill no more).
            const std::size_t own = object->memoryBytes();
            if (stats_.memoryBytes > settings_.memoryBudget + own) {
                ++stats_.waits;
                changed_.wait(lock, [&] {
                    return stop_ || stats_.memoryBytes <= settings_.memoryBudget + own ||
                           (!workerBusy_ && !dirty_);
                });
            }
            return object;
        }
        if (!waited) ++stats_.waits;
        waited = true;
        changed_.wait(lock);
    }
}

int SeriesCache::nextStep() const {
    std::lock_guard lock(mutex_);
    const int next = shown_ + (direction_ < 0 ? -1 : 1);
    if (settings_.loop) return ((next % stepCount_) + stepCount_) % stepCount_;
    return next >= 0 && next < stepCount_ ? next : -1;
}

SeriesStepVolume SeriesCache::peekVolume(int step) const {
    std::lock_guard lock(mutex_);
    const auto it = grids_.find(step);
    return it == grids_.end() ? SeriesStepVolume{} : it->second;
}

std::optional<glm::dvec3> SeriesCache::knownExtent(int step) const {
    std::lock_guard lock(mutex_);
    if (const auto it = grids_.find(step); it != grids_.end()) return it->second.data->extent();
    for (auto it = lists_.lower_bound({step, 0}); it != lists_.end() && it->first.first == step;
         ++it)
        if (it->second.object)
            return glm::dvec3(it->second.object->dimensions()) * it->second.object->spacing();
    return std::nullopt;
}

ref_ptr<VoxelObject> SeriesCache::peek(int step, const ExtractionSpec& spec) const {
    std::lock_guard lock(mutex_);
    const auto it = lists_.find({step, extractionKey(spec)});
    return it == lists_.end() ? nullptr : it->second.object;
}

bool SeriesCache::isInMemory(int step, const ExtractionSpec& spec) const {
    return bool(peek(step, spec));
}

bool SeriesCache::isOnDisk(int step, const ExtractionSpec& spec) const {
    std::lock_guard lock(mutex_);
    const auto it = lists_.find({step, extractionKey(spec)});
    return it != lists_.end() && it->second.diskBytes > 0 && !it->second.busy;
}

void SeriesCache::waitUntilIdle() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return !workerBusy_ && !dirty_; });
}

SeriesCacheStats SeriesCache::stats() const {
    std::lock_guard lock(mutex_);
    return stats_;
}

std::string SeriesCache::pathOf(const Key& key) const {
    char name[64];
    std::snprintf(name, sizeof name, "/step-%d-%016llx.voxels", key.first,
                  static_cast<unsigned long long>(key.second));
    return diskFolder_ + name;
}

void SeriesCache::addMemory(ListEntry& entry, ref_ptr<VoxelObject> object) {
    entry.bytes = object->memoryBytes();
    entry.object = std::move(object);
    stats_.memoryBytes += entry.bytes;
    stats_.memoryHighWater = std::max(stats_.memoryHighWater, stats_.memoryBytes);
    dirty_ = true; // the worker may have to spill
}

void SeriesCache::dropMemory(ListEntry& entry) {
    if (!entry.object) return;
    stats_.memoryBytes -= entry.bytes;
    entry.object = nullptr; // the renderer may still hold it for a moment: it is ref-counted
}

std::vector<std::pair<int, int>> SeriesCache::windowSteps() const {
    std::vector<std::pair<int, int>> out; // (step, distance), nearest first
    const int directions[2] = {direction_ != 0 ? direction_ : 1, direction_ != 0 ? 0 : -1};
    for (int d = 1; d <= settings_.prefetchSteps; ++d)
        for (int dir : directions) {
            if (dir == 0) continue;
            int s = shown_ + dir * d;
            if (settings_.loop)
                s = ((s % stepCount_) + stepCount_) % stepCount_;
            else if (s < 0 || s >= stepCount_)
                continue;
            if (s == shown_) continue;
            if (std::none_of(out.begin(), out.end(), [&](const auto& p) { return p.first == s; }))
                out.emplace_back(s, d);
        }
    return out;
}

void SeriesCache::trimGrids() {
    const auto window = windowSteps();
    for (auto it = grids_.begin(); it != grids_.end();) {
        const bool keep =
            it->first == shown_ ||
            (gridsWanted_ && std::any_of(window.begin(), window.end(),
                                         [&](const auto& p) { return p.first == it->first; }));
        if (keep) {
            ++it;
        } else {
            stats_.gridBytes -= gridBytesOf(it->second);
            it = grids_.erase(it);
        }
    }
}

SeriesStepVolume SeriesCache::gridLocked(int step, std::unique_lock<std::mutex>& lock) {
    bool waited = false;
    while (true) {
        if (const auto it = grids_.find(step); it != grids_.end()) return it->second;
        if (!gridsInFlight_.count(step)) break;
        if (!waited) ++stats_.waits;
        waited = true;
        changed_.wait(lock);
    }
    gridsInFlight_.insert(step);
    lock.unlock();
    SeriesStepVolume volume;
    try {
        volume = loader_(step);
        if (!volume.data)
            throw Error("the series loader gave no volume for step " + std::to_string(step));
    } catch (...) {
        lock.lock();
        gridsInFlight_.erase(step);
        changed_.notify_all();
        throw;
    }
    lock.lock();
    gridsInFlight_.erase(step);
    ++stats_.gridLoads;
    grids_[step] = volume;
    stats_.gridBytes += gridBytesOf(volume);
    stats_.gridHighWater = std::max(stats_.gridHighWater, stats_.gridBytes);
    changed_.notify_all();
    return volume;
}

ref_ptr<VoxelObject> SeriesCache::produceLocked(const Key& key, const ExtractionSpec& spec,
                                                std::unique_lock<std::mutex>& lock, bool byWorker) {
    // Entries are never erased while busy, so the reference stays valid across the unlocks.
    ListEntry& entry = lists_[key];
    entry.busy = true;
    const int axis = byWorker ? viewAxis_ : -1;
    bool fromDisk = entry.diskBytes > 0;
    try {
        ref_ptr<VoxelObject> object;
        if (fromDisk) {
            // The file holds the RenderLists too: a read-back step is drawn without a sort.
            const std::string path = pathOf(key);
            lock.unlock();
            try {
                object = readSpillFile(path);
            } catch (const Error&) {
                std::remove(path.c_str()); // damaged or of another version: extract again
            }
            lock.lock();
            if (!object) {
                stats_.diskBytes -= entry.diskBytes;
                entry.diskBytes = 0;
                entry.diskLists = 0;
                ++stats_.damagedFiles;
                fromDisk = false;
            }
        }
        if (!object) {
            const SeriesStepVolume volume = gridLocked(key.first, lock);
            lock.unlock();
            object = VoxelObject::extract(*volume.data, volume.tags.get(), spec);
        } else {
            lock.unlock();
        }
        const bool sort = axis >= 0 && !object->hasRenderList(axis);
        if (sort) object->renderList(axis); // prefetched: ready to draw without a sort
        lock.lock();
        if (sort) ++stats_.renderListSorts;
        ++(fromDisk ? stats_.diskReads : stats_.extractions);
        entry.busy = false;
        addMemory(entry, object);
        entry.lastUse = ++tick_;
        trimGrids();
        changed_.notify_all();
        return object;
    } catch (...) {
        if (!lock.owns_lock()) lock.lock();
        entry.busy = false;
        changed_.notify_all();
        throw;
    }
}

bool SeriesCache::spillOne(std::unique_lock<std::mutex>& lock) {
    if (stats_.memoryBytes <= settings_.memoryBudget) return false;
    return evictOne(lock, false);
}

bool SeriesCache::evictOne(std::unique_lock<std::mutex>& lock, bool outsideWindowOnly) {
    const auto window = windowSteps();
    // Victim: lists nobody wants any more first, then steps outside the prefetch window
    // (least recently used first), then the window's farthest step.
    auto victim = lists_.end();
    std::tuple<int, int, std::uint64_t> best{2, 2, 0};
    for (auto it = lists_.begin(); it != lists_.end(); ++it) {
        const ListEntry& e = it->second;
        if (!e.object || e.busy || it->first.first == shown_) continue;
        const int wanted = wanted_.count(it->first.second) ? 1 : 0;
        const auto w = std::find_if(window.begin(), window.end(),
                                    [&](const auto& p) { return p.first == it->first.first; });
        const int inWindow = w != window.end() ? 1 : 0;
        if (inWindow && outsideWindowOnly) continue;
        const std::uint64_t order =
            inWindow ? std::uint64_t(kMaxPrefetchSteps - w->second) : e.lastUse;
        const std::tuple<int, int, std::uint64_t> rank{wanted, inWindow, order};
        if (victim == lists_.end() || rank < best) {
            victim = it;
            best = rank;
        }
    }
    if (victim == lists_.end()) return false; // only the shown step is left: it stays
    ListEntry& entry = victim->second;
    // A disk copy without a RenderList built since it was read back is written again, so
    // that reading it back once more costs no sort either.
    const bool spillLists = settings_.spillRenderLists;
    const bool diskCopyComplete =
        entry.diskBytes > 0 && (!spillLists || (listMaskOf(*entry.object) & ~entry.diskLists) == 0);
    if (std::get<0>(best) == 0 || diskCopyComplete || diskFailed_) {
        // Unwanted (a stale key), or already on disk, or no disk: memory goes, nothing is
        // lost (a missing list is extracted again from the step's data when asked for).
        dropMemory(entry);
        if (entry.diskBytes == 0) lists_.erase(victim);
        return true;
    }
    entry.busy = true;
    const ref_ptr<VoxelObject> object = entry.object;
    const std::string path = pathOf(victim->first);
    const int step = victim->first.first;
    lock.unlock();
    std::size_t written = 0;
    const unsigned lists = spillLists ? listMaskOf(*object) : 0; // later lists: next spill
    try {
        written = writeSpillFile(path, *object, spillLists);
    } catch (const Error&) {
        written = 0;
    }
    lock.lock();
    entry.busy = false;
    if (written == 0) {
        diskFailed_ = true; // from now on evicted lists are dropped, not spilled
        // A failed rewrite leaves the older copy (the rename never happened): still whole.
    } else {
        stats_.diskBytes = stats_.diskBytes - entry.diskBytes + written;
        entry.diskBytes = written;
        entry.diskLists = lists;
        ++stats_.spills;
    }
    if (step != shown_) dropMemory(entry);
    if (!entry.object && entry.diskBytes == 0) lists_.erase(victim);
    changed_.notify_all();
    return true;
}

bool SeriesCache::prefetchOne(std::unique_lock<std::mutex>& lock) {
    for (const auto& [step, distance] : windowSteps()) {
        if (failedSteps_.count(step)) continue;
        for (const auto& [extraction, spec] : wanted_) {
            const Key key{step, extraction};
            ListEntry& e = lists_[key];
            if (e.busy) continue;
            if (e.object) {
                // Already here; make sure it is ready for the current view axis.
                if (viewAxis_ >= 0 && !e.object->hasRenderList(viewAxis_)) {
                    const ref_ptr<VoxelObject> object = e.object;
                    const int axis = viewAxis_;
                    e.busy = true;
                    lock.unlock();
                    object->renderList(axis);
                    lock.lock();
                    ++stats_.renderListSorts;
                    e.busy = false;
                    if (e.object == object) {
                        const std::size_t bytes = object->memoryBytes();
                        stats_.memoryBytes = stats_.memoryBytes - e.bytes + bytes;
                        stats_.memoryHighWater =
                            std::max(stats_.memoryHighWater, stats_.memoryBytes);
                        e.bytes = bytes;
                    }
                    changed_.notify_all();
                    return true;
                }
                continue;
            }
            // Bring a step in only while it fits the budget; to make it fit, lists of steps
            // outside the window go first (spilled or dropped). Window steps are never
            // evicted for each other, so spilling and prefetching never chase each other.
            const bool fits = e.diskBytes > 0
                                  ? stats_.memoryBytes + e.bytes <= settings_.memoryBudget
                                  : stats_.memoryBytes < settings_.memoryBudget;
            if (!fits) {
                if (evictOne(lock, true)) return true;
                continue;
            }
            const ExtractionSpec specCopy = spec; // wanted_ may change while unlocked
            try {
                produceLocked(key, specCopy, lock, true);
            } catch (...) {
                failedSteps_.insert(step); // the request for it will report the error
            }
            return true;
        }
        if (gridsWanted_ && !grids_.count(step) && !gridsInFlight_.count(step)) {
            try {
                gridLocked(step, lock);
            } catch (...) {
                failedSteps_.insert(step);
            }
            return true;
        }
    }
    return false;
}

void SeriesCache::workerLoop() {
#if defined(__linux__)
    // Below the render threads: on a machine with few cores, reading the next step back
    // must not slow down the frame being drawn (the render thread reads a step itself when
    // the worker had no time for it). Linux nice values are per thread.
    setpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid)), 10);
#endif
    std::unique_lock lock(mutex_);
    while (!stop_) {
        dirty_ = false;
        workerBusy_ = true;
        bool worked = false;
        try {
            worked = spillOne(lock) || (!stop_ && prefetchOne(lock));
        } catch (...) {
            // Nothing may escape the thread; the render thread's own request reports errors.
            if (!lock.owns_lock()) lock.lock();
            worked = false;
        }
        if (worked) continue;
        workerBusy_ = false;
        changed_.notify_all();
        changed_.wait(lock, [&] { return stop_ || dirty_; });
    }
    workerBusy_ = false;
    changed_.notify_all();
}

} // namespace volsg
