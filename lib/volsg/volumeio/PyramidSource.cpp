#include <volsg/volumeio/PyramidSource.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <tuple>

#include <volsg/core/Error.h>
#include <volsg/volumeio/OmeZarrLevels.h>

namespace volsg {

namespace {

std::string zarrayOf(const std::string& arrayFolder) {
    return (std::filesystem::path(arrayFolder) / ".zarray").string();
}

std::string text(glm::ivec3 v) {
    return std::to_string(v.x) + " x " + std::to_string(v.y) + " x " + std::to_string(v.z);
}

/// How level `next` reduces level `previous` along each axis (1 or 2), or an Error naming its
/// .zarray when it is no halving.
glm::ivec3 reductionOf(const PyramidSourceLevel& previous, const PyramidSourceLevel& next,
                       int index) {
    glm::ivec3 factor(1);
    for (int a = 0; a < 3; ++a) {
        const int n = previous.dimensions[a], m = next.dimensions[a];
        const double ratio = next.spacing[a] / previous.spacing[a];
        if (m == n && std::abs(ratio - 1.0) < 1e-3) continue;
        if ((m == (n + 1) / 2 || m == n / 2) && m >= 1 && std::abs(ratio - 2.0) < 2e-3) {
            factor[a] = 2;
            continue;
        }
        throw Error("level " + std::to_string(index) + " (" + text(next.dimensions) +
                        " voxels) does not halve or keep each axis of level " +
                        std::to_string(index - 1) + " (" + text(previous.dimensions) +
                        ") with its spacing doubled or kept: volsg pages pyramids of halvings",
                    zarrayOf(next.arrayFolder));
    }
    return factor;
}

} // namespace

bool PyramidSource::ChunkKey::operator<(const ChunkKey& o) const {
    return std::tie(level, index.z, index.y, index.x) <
           std::tie(o.level, o.index.z, o.index.y, o.index.x);
}

PyramidSource::PyramidSource(const std::string& path, std::uint64_t chunkCacheBytes)
    : path_(path), cacheBudget_(chunkCacheBytes) {
    std::error_code ec;
    if (!std::filesystem::is_directory(path, ec))
        throw Error(std::string("cannot open OME-Zarr image: ") +
                        (std::filesystem::exists(path, ec) ? "not a folder" : "no such folder"),
                    path);
    const int count = omeZarrLevelCount(path);
    for (int l = 0; l < count; ++l) {
        const OmeZarrLevel where = findOmeZarrLevel(path, l);
        PyramidSourceLevel level;
        level.arrayFolder = where.arrayFolder;
        // Chunks, not levels, are what is ever held whole: the level may exceed memory.
        level.layout = readZarrArrayLayout(where.arrayFolder, limits::maxVolumeBytes);
        const std::size_t rank = level.layout.shape.size();
        if (where.axisCount != 0 && where.axisCount != rank)
            throw Error("shape has " + std::to_string(rank) +
                            " axes, the multiscales metadata "
                            "names " +
                            std::to_string(where.axisCount),
                        zarrayOf(where.arrayFolder));
        level.dimensions = {int(level.layout.shape[rank - 1]), int(level.layout.shape[rank - 2]),
                            int(level.layout.shape[rank - 3])};
        level.chunk = {int(level.layout.chunks[rank - 1]), int(level.layout.chunks[rank - 2]),
                       int(level.layout.chunks[rank - 3])};
        level.spacing = where.spacing;
        if (l == 0) {
            geometry_ = where.geometry;
        } else {
            const PyramidSourceLevel& finer = levels_.back();
            if (level.layout.type != finer.layout.type)
                throw Error(std::string("level ") + std::to_string(l) + " holds " +
                                voxelTypeName(level.layout.type) + ", level 0 " +
                                voxelTypeName(finer.layout.type),
                            zarrayOf(where.arrayFolder));
            level.scale = finer.scale * reductionOf(finer, level, l);
        }
        levels_.push_back(std::move(level));
    }
}

PyramidSource::~PyramidSource() = default;

PyramidSource::ChunkBytes PyramidSource::chunk(int level, glm::ivec3 index) const {
    const ChunkKey key{level, index};
    {
        std::lock_guard lock(mutex_);
        if (const auto it = cache_.find(key); it != cache_.end()) {
            recent_.splice(recent_.begin(), recent_, it->second.place);
            return it->second.bytes;
        }
    }
    // Decoded outside the lock: two threads may decode the same chunk, which costs time but
    // never a wrong voxel.
    const PyramidSourceLevel& where = levels_[std::size_t(level)];
    const std::size_t rank = where.layout.shape.size();
    std::vector<std::uint64_t> position(rank, 0); // leading axes (t, c) at 0
    position[rank - 3] = std::uint64_t(index.z);
    position[rank - 2] = std::uint64_t(index.y);
    position[rank - 1] = std::uint64_t(index.x);
    ZarrChunkLoader loader(zarrayOf(where.arrayFolder), where.layout);
    const std::span<const std::byte> voxels = loader.load(position);
    auto bytes = std::make_shared<const std::vector<std::byte>>(voxels.begin(), voxels.end());

    std::lock_guard lock(mutex_);
    ++decoded_;
    if (cache_.count(key)) return bytes; // another thread's copy is cached already
    if (bytes->size() <= cacheBudget_) {
        recent_.push_front(key);
        cache_.emplace(key, Cached{bytes, recent_.begin()});
        cachedBytes_ += bytes->size();
        while (cachedBytes_ > cacheBudget_) {
            const auto victim = cache_.find(recent_.back());
            cachedBytes_ -= victim->second.bytes->size();
            cache_.erase(victim);
            recent_.pop_back();
        }
    }
    return bytes;
}

ref_ptr<VolumeGrid> PyramidSource::readBox(int level, glm::ivec3 first, glm::ivec3 count) const {
    if (level < 0 || level >= levelCount())
        throw Error("level " + std::to_string(level) + " asked for, the pyramid has levels 0.." +
                        std::to_string(levelCount() - 1),
                    path_);
    const PyramidSourceLevel& where = levels_[std::size_t(level)];
    const glm::ivec3 end = first + count;
    if (glm::any(glm::lessThan(first, glm::ivec3(0))) ||
        glm::any(glm::lessThan(count, glm::ivec3(1))) ||
        glm::any(glm::greaterThan(end, where.dimensions)))
        throw Error("box from voxel " + text(first) + " of " + text(count) +
                        " voxels lies outside level " + std::to_string(level) + " (" +
                        text(where.dimensions) + ")",
                    zarrayOf(where.arrayFolder));
    ref_ptr<VolumeGrid> grid = VolumeGrid::create(count, where.layout.type, where.spacing);
    const std::span<std::byte> out = grid->bytes();
    const std::size_t size = voxelTypeSize(where.layout.type);
    const glm::ivec3 c = where.chunk;
    const glm::ivec3 firstChunk = first / c, lastChunk = (end - 1) / c;
    for (int cz = firstChunk.z; cz <= lastChunk.z; ++cz)
        for (int cy = firstChunk.y; cy <= lastChunk.y; ++cy)
            for (int cx = firstChunk.x; cx <= lastChunk.x; ++cx) {
                const ChunkBytes bytes = chunk(level, {cx, cy, cz});
                const glm::ivec3 origin = glm::ivec3(cx, cy, cz) * c;
                const glm::ivec3 from = glm::max(origin, first);
                const glm::ivec3 to = glm::min(origin + c, end);
                const std::size_t row = std::size_t(to.x - from.x) * size;
                for (int z = from.z; z < to.z; ++z)
                    for (int y = from.y; y < to.y; ++y) {
                        const std::size_t in = ((std::size_t(z - origin.z) * std::size_t(c.y) +
                                                 std::size_t(y - origin.y)) *
                                                    std::size_t(c.x) +
                                                std::size_t(from.x - origin.x)) *
                                               size;
                        const std::size_t at =
                            grid->index(from.x - first.x, y - first.y, z - first.z) * size;
                        std::memcpy(out.data() + at, bytes->data() + in, row);
                    }
            }
    return grid;
}

std::uint64_t PyramidSource::decodedChunks() const {
    std::lock_guard lock(mutex_);
    return decoded_;
}

std::uint64_t PyramidSource::chunkCacheBytes() const {
    std::lock_guard lock(mutex_);
    return cachedBytes_;
}

} // namespace volsg
