#pragma once
// An OME-Zarr pyramid read box by box: any voxel box of any level, chunk by chunk, without
// reading a level whole (issue 26, part 2: out-of-core rendering).

#include <cstdint>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/volume/VolumeGrid.h>
#include <volsg/volumeio/ZarrArray.h>

namespace volsg {

/// One level of a pyramid as PyramidSource sees it.
struct PyramidSourceLevel {
    std::string arrayFolder;
    ZarrArrayLayout layout;
    glm::ivec3 dimensions{1};
    glm::ivec3 chunk{1};     ///< chunk edge along x, y, z
    glm::dvec3 spacing{1.0}; ///< from the metadata
    /// Level-0 voxels per voxel of this level along x, y, z (1, 2, 4, ...): each level halves
    /// an axis or keeps it (an axis of one voxel), as volsg-pyramid writes them.
    glm::ivec3 scale{1};
};

/// Opens the levels of the OME-Zarr image at `path` (a folder with .zattrs, or one array's
/// folder: a pyramid of one level) and reads boxes of voxels from them. The metadata is read
/// and checked once here: every level's .zarray (one VoxelType, 3 to 5 axes), and that each
/// level halves each axis of the one before or keeps it (dimensions ceil(n / 2) or floor, the
/// spacing doubled within 0.1%), else an Error naming the .zarray.
///
/// readBox() is safe to call from several threads at once: decoded chunks are shared through
/// a small cache (`chunkCacheBytes`, least recently used out first) so the guard voxels of
/// neighbouring boxes do not decode the same chunk again and again.
class PyramidSource {
public:
    explicit PyramidSource(const std::string& path, std::uint64_t chunkCacheBytes = 64u << 20);
    ~PyramidSource();
    PyramidSource(const PyramidSource&) = delete;
    PyramidSource& operator=(const PyramidSource&) = delete;

    const std::string& path() const { return path_; }
    int levelCount() const { return int(levels_.size()); }
    const PyramidSourceLevel& level(int l) const { return levels_.at(std::size_t(l)); }
    VoxelType type() const { return levels_.front().layout.type; }
    const VolumeGeometry& geometry() const { return geometry_; } ///< level 0's placement

    /// The voxels [first, first + count) of level `level` as a grid of `count` voxels with the
    /// level's spacing. Throws Error for a box outside the level, and (naming the chunk file)
    /// for a chunk that cannot be read.
    ref_ptr<VolumeGrid> readBox(int level, glm::ivec3 first, glm::ivec3 count) const;

    /// Stored chunk bytes decoded so far and how many chunks (cache hits not counted).
    std::uint64_t decodedChunks() const;
    std::uint64_t chunkCacheBytes() const; ///< decoded chunks held now

private:
    struct ChunkKey {
        int level;
        glm::ivec3 index;
        bool operator<(const ChunkKey& o) const;
    };
    using ChunkBytes = std::shared_ptr<const std::vector<std::byte>>;
    ChunkBytes chunk(int level, glm::ivec3 index) const;

    std::string path_;
    std::vector<PyramidSourceLevel> levels_;
    VolumeGeometry geometry_;
    std::uint64_t cacheBudget_;

    mutable std::mutex mutex_;           ///< guards the chunk cache and the counters
    mutable std::list<ChunkKey> recent_; ///< most recently used first
    struct Cached {
        ChunkBytes bytes;
        std::list<ChunkKey>::iterator place;
    };
    mutable std::map<ChunkKey, Cached> cache_;
    mutable std::uint64_t cachedBytes_ = 0;
    mutable std::uint64_t decoded_ = 0;
};

} // namespace volsg
