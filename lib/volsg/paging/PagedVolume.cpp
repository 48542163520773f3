#include <volsg/paging/PagedVolume.h>

#include <algorithm>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <volsg/core/Error.h>

namespace volsg {

namespace {

/// The bricks' edge: level 0's chunk edge less the guard voxels (two; four when `reach` is 1),
/// so that a texture is the chunk's size (64^3 for chunks of 64): llvmpipe pads each texture
/// row to 64 bytes, and a 66-texel R16 row would take 192 bytes for 132 (the memory budget
/// would be a fiction). A brick then reads up to 8 chunks; the chunk cache shares them with
/// its neighbours. Chunks under 16 voxels make 16^3 textures all the same.
int brickCellsOf(const PyramidSource& source, int reach) {
    const glm::ivec3 chunk = source.level(0).chunk;
    return std::clamp(std::max({chunk.x, chunk.y, chunk.z}), 16, 256) - 2 - 2 * reach;
}

PagedLayout layoutOf(const PyramidSource& source, int reach) {
    std::vector<PagedLevel> levels;
    for (int l = 0; l < source.levelCount(); ++l)
        levels.push_back({source.level(l).dimensions, source.level(l).scale});
    return PagedLayout(levels, source.level(0).spacing, brickCellsOf(source, reach), reach);
}

/// A brick cut from a level held whole.
HostBrick cutBrick(const VolumeGrid& level, glm::ivec3 first, glm::ivec3 count) {
    auto grid = VolumeGrid::create(count, level.type(), level.spacing());
    const std::size_t size = voxelTypeSize(level.type());
    const std::span<const std::byte> from = level.bytes();
    const std::span<std::byte> to = grid->bytes();
    for (int z = 0; z < count.z; ++z)
        for (int y = 0; y < count.y; ++y)
            std::memcpy(to.data() + grid->index(0, y, z) * size,
                        from.data() + level.index(first.x, first.y + y, first.z + z) * size,
                        std::size_t(count.x) * size);
    const auto [lo, hi] = grid->minMax();
    return {grid, lo, hi};
}

} // namespace

PagedVolume::PagedVolume(const std::string& path, const PagedVolumeOptions& options)
    : options_(options), source_(path, options.chunkCacheBytes), layout_(layoutOf(source_, 0)) {
#if defined(__GLIBC__)
    // Bricks and chunks (64^3 voxels: 256 KiB and more) are made on the loader threads and
    // freed on others, for ever. glibc raises its mmap threshold after the first such free,
    // and from then on serves them from per-thread arenas, which keep the high-water mark of
    // every thread resident: the 2048^3 run held 460 MiB beyond its budgets that way. A fixed
    // threshold gives each large buffer its own mapping, returned to the system when freed.
    mallopt(M_MMAP_THRESHOLD, 128 * 1024);
#endif
    const std::size_t size = voxelTypeSize(source_.type());
    auto levelBytes = [&](int l) {
        const glm::ivec3 d = source_.level(l).dimensions;
        return std::uint64_t(d.x) * std::uint64_t(d.y) * std::uint64_t(d.z) * size;
    };
    standInLevel_ = source_.levelCount() - 1;
    while (standInLevel_ > 0 && levelBytes(standInLevel_ - 1) <= options_.standInBytes)
        --standInLevel_;
    std::uint64_t whole = 0;
    for (int l = standInLevel_; l < source_.levelCount(); ++l)
        whole += levelBytes(l);
    glm::ivec3 first, count;
    layout_.texels({0, glm::ivec3(0)}, first, count);
    const std::uint64_t brick = std::uint64_t(count.x) * count.y * count.z * size;
    const std::uint64_t needed = whole + options_.chunkCacheBytes + 8 * brick;
    if (options_.hostBudget < needed)
        throw Error("a host memory budget of " + std::to_string(options_.hostBudget) +
                        " bytes cannot hold the coarse levels kept whole (" +
                        std::to_string(whole) + "), the chunk cache (" +
                        std::to_string(options_.chunkCacheBytes) + ") and 8 bricks (" +
                        std::to_string(8 * brick) + "): at least " + std::to_string(needed),
                    path);
    for (int l = source_.levelCount() - 1; l >= standInLevel_; --l) {
        const glm::ivec3 d = source_.level(l).dimensions;
        whole_[l] = l == standInLevel_ ? readWholeLevel(l) : source_.readBox(l, glm::ivec3(0), d);
        wholeBytes_ += levelBytes(l);
    }
    cache_ = std::make_unique<BrickCache>(
        options_.hostBudget - wholeBytes_ - options_.chunkCacheBytes, options_.loaderThreads,
        [this](const BrickKey& key) {
            glm::ivec3 f, c;
            layout_.texels(key, f, c);
            ref_ptr<VolumeGrid> grid = source_.readBox(key.level, f, c);
            const auto [lo, hi] = grid->minMax();
            return HostBrick{grid, lo, hi};
        },
        [this](const BrickKey& key) { return brickBytes(key); });
}

PagedVolume::~PagedVolume() {
    if (levelLoader_.joinable()) levelLoader_.join(); // it reads source_
    cache_.reset(); // the loaders read source_ and layout_: stop them first
}

std::uint64_t PagedVolume::levelBytes(int level) const {
    const glm::ivec3 d = source_.level(level).dimensions;
    return std::uint64_t(d.x) * std::uint64_t(d.y) * std::uint64_t(d.z) *
           voxelTypeSize(source_.type());
}

ref_ptr<VolumeGrid> PagedVolume::readWholeLevel(int level) const {
    const glm::ivec3 d = source_.level(level).dimensions;
    ref_ptr<VolumeGrid> grid = source_.readBox(level, glm::ivec3(0), d);
    // Its box is level 0's: an odd axis rounds up when halved, so the spacing shrinks by a
    // fraction of a voxel instead.
    grid->setSpacing(glm::dvec3(source_.level(0).dimensions) * source_.level(0).spacing /
                     glm::dvec3(d));
    grid->setGeometry(source_.geometry());
    return grid;
}

std::uint64_t PagedVolume::wholeLevelBudget() const {
    return cache_->stats().budgetBytes / 2;
}

std::string PagedVolume::wholeLevelError() const {
    std::lock_guard<std::mutex> lock(levelMutex_);
    return levelError_;
}

ref_ptr<const VolumeGrid> PagedVolume::wholeLevel(int wanted, int& drawn, bool& loading) {
    wanted = std::clamp(wanted, 0, standInLevel_);
    while (wanted < standInLevel_ && levelBytes(wanted) > wholeLevelBudget())
        ++wanted;
    std::lock_guard<std::mutex> lock(levelMutex_);
    if (wanted == standInLevel_ || wanted == extraLevel_) {
        drawn = wanted;
        loading = false;
        return wanted == extraLevel_ ? extraGrid_ : whole_.at(standInLevel_);
    }
    // Not held: load it (one level at a time; a level that failed is not tried again).
    if (loadingLevel_ < 0 && levelError_.empty()) {
        if (levelLoader_.joinable()) levelLoader_.join(); // the last load, finished
        loadingLevel_ = wanted;
        levelLoader_ = std::thread([this, wanted] {
            ref_ptr<const VolumeGrid> grid;
            std::string error;
            try {
                grid = readWholeLevel(wanted);
            } catch (const std::exception& e) {
                error = e.what();
            }
            std::lock_guard<std::mutex> done(levelMutex_);
            loadingLevel_ = -1;
            if (grid) {
                extraGrid_ = grid; // the level held before goes
                extraLevel_ = wanted;
            } else {
                levelError_ = error;
            }
        });
    }
    loading = loadingLevel_ >= 0;
    // Meanwhile the finer of what is held.
    if (extraGrid_ && extraLevel_ < standInLevel_) {
        drawn = extraLevel_;
        return extraGrid_;
    }
    drawn = standInLevel_;
    return whole_.at(standInLevel_);
}

void PagedVolume::widenGuard() {
    if (wideGuard()) return;
    cache_->clear(); // the loaders read the layout: idle them first
    layout_ = layoutOf(source_, 1);
}

double PagedVolume::finestSpacing() const {
    const glm::dvec3 s = layout_.spacing();
    return std::min({s.x, s.y, s.z});
}

std::uint64_t PagedVolume::brickBytes(const BrickKey& key) const {
    glm::ivec3 first, count;
    layout_.texels(key, first, count);
    return std::uint64_t(count.x) * count.y * count.z * voxelTypeSize(source_.type());
}

std::shared_ptr<const HostBrick> PagedVolume::find(const BrickKey& key) {
    if (const auto it = whole_.find(key.level); it != whole_.end()) {
        glm::ivec3 first, count;
        layout_.texels(key, first, count);
        return std::make_shared<const HostBrick>(cutBrick(*it->second, first, count));
    }
    return cache_->find(key);
}

bool PagedVolume::available(const BrickKey& key) const {
    return whole_.count(key.level) != 0 || cache_->holds(key);
}

void PagedVolume::request(const std::vector<BrickKey>& wanted) {
    // At most half the cache's budget at a time: more would evict the first arrivals before
    // a frame takes them to the GPU, and loads would chase each other for ever.
    std::vector<BrickKey> loadable;
    std::uint64_t bytes = 0;
    const std::uint64_t room = cache_->stats().budgetBytes / 2;
    for (const BrickKey& key : wanted) {
        if (whole_.count(key.level)) continue;
        bytes += brickBytes(key);
        if (bytes > room && !loadable.empty()) break;
        loadable.push_back(key);
    }
    cache_->request(std::move(loadable));
}

std::uint64_t PagedVolume::hostBytes() const {
    const BrickCacheStats s = cache_->stats();
    return s.residentBytes + s.loadingBytes + source_.chunkCacheBytes() + wholeBytes_;
}

} // namespace volsg
