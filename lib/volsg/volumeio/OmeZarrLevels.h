#pragma once
// The levels of an OME-Zarr image and their chunks, for readers that take a level whole
// (readOmeZarr) or box by box (PyramidSource).

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/volume/VolumeGeometry.h>
#include <volsg/volumeio/ZarrArray.h>

namespace volsg {

/// Where one level's array is and how its voxels map to space, from the multiscales metadata.
struct OmeZarrLevel {
    std::string arrayFolder;
    std::size_t axisCount = 3; ///< 0 when no metadata names the axes (a bare array)
    glm::dvec3 spacing{1.0};   ///< x, y, z
    VolumeGeometry geometry;   ///< from volsg's own metadata, when the writer kept it
};

/// Level `level` of the image folder `path` (with .zattrs), or of one array's folder (with
/// .zarray; then only level 0, spacing from the image around it when that lists it). Throws
/// Error naming the metadata file for anything OMEZARR.md's "Read" refuses.
OmeZarrLevel findOmeZarrLevel(const std::string& path, int level);

/// How many levels findOmeZarrLevel() finds at `path` (1 for one array's folder).
int omeZarrLevelCount(const std::string& path);

/// One chunk's voxels in host byte order, or the fill value where the chunk file is missing
/// (Zarr's rule). One loader per thread: it owns the buffers the spans point into.
class ZarrChunkLoader {
public:
    ZarrChunkLoader(const std::string& zarrayPath, const ZarrArrayLayout& layout);

    /// The chunk at `index` (one entry per array axis), valid until the next call. Throws
    /// Error naming the chunk file when it is truncated, corrupt or too large.
    std::span<const std::byte> load(const std::vector<std::uint64_t>& index);

private:
    std::span<const std::byte> fillChunk();

    std::string zarrayPath_;
    const ZarrArrayLayout& layout_;
    std::vector<std::byte> buffer_, stored_, fill_;
};

} // namespace volsg
