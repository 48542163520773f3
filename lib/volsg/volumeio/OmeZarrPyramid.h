#pragma once
// Writing a volume as an OME-Zarr multiscale pyramid (OME-NGFF 0.4 over Zarr v2), level by
// level in one pass over the input's z planes.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/volume/VolumeGrid.h>
#include <volsg/volumeio/ZarrCodec.h>

namespace volsg {

/// How writeOmeZarrPyramid() lays out and reduces the levels.
struct PyramidOptions {
    int chunk = 64;                             ///< chunk edge (an axis shorter than it: that axis)
    ZarrCodec codec = ZarrCodec::named("zstd"); ///< every level's compressor
    /// Label data: each coarser voxel is the most frequent of its (up to) 2x2x2 finer voxels
    /// (ties: the smallest label), so no label is invented; otherwise their mean, rounded to
    /// nearest (ties to even) for integer types.
    bool labels = false;
    std::string unit; ///< the axes' NGFF unit ("millimeter", ...); empty: none written
};

/// One written level.
struct PyramidLevel {
    glm::ivec3 dimensions{0};
    glm::dvec3 spacing{1.0};
    std::uint64_t chunkFiles = 0;
    std::uint64_t storedBytes = 0; ///< chunk files only
};

/// The level sizes for `dimensions`: level 0 is the volume; each next level halves every axis
/// longer than 1 (rounding up: an odd last voxel is reduced from the finer voxels there are)
/// until the longest axis is at most `chunk`.
std::vector<glm::ivec3> pyramidLevelDimensions(glm::ivec3 dimensions, int chunk);

/// Writes `grid` as an OME-Zarr image in the new folder `folder` (an Error if it exists and is
/// not empty): .zgroup, one Zarr v2 array per level ("0" the finest, "1", ...: dtype of the
/// grid in little-endian, C order, fill_value 0, dimension_separator "/", chunks
/// options.chunk^3), and last .zattrs with the multiscales metadata (axes z, y, x; per level
/// scale = the grid's spacing times 2^level on halved axes, and the translation that keeps
/// voxel centres where the finer ones' centres average). Memory beyond the grid: one slab of
/// chunk-deep planes per level, plus two planes per level.
/// `progress` (optional) is called with the fraction of input planes done.
std::vector<PyramidLevel> writeOmeZarrPyramid(const VolumeGrid& grid, const std::string& folder,
                                              const PyramidOptions& options = {},
                                              const std::function<void(double)>& progress = {});

/// The same from planes made on demand, for volumes generated or larger than memory:
/// `plane(z, out)` fills `out` (dimensions.x * dimensions.y values, x fastest, as the type
/// holds them) with plane z, called for z = 0, 1, ... in turn. Memory: as above, without the
/// grid.
std::vector<PyramidLevel> writeOmeZarrPyramid(
    glm::ivec3 dimensions, VoxelType type, glm::dvec3 spacing, const VolumeGeometry& geometry,
    const std::function<void(int, std::vector<double>&)>& plane, const std::string& folder,
    const PyramidOptions& options = {}, const std::function<void(double)>& progress = {});

} // namespace volsg
