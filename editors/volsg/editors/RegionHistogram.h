#pragma once
// The data-value readout and the histogram of the region under the viewer's cursor: the value
// of the voxel at the cursor and the histogram of the k x k x k voxels around it, in the bins of
// the transfer-function editor's Histogram (so the two can be drawn over the same axis).

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

namespace volsg {

class VolumeGrid;

struct RegionHistogram {
    glm::ivec3 center{0};         ///< the cursor voxel
    int size = 0;                 ///< k: the region is k^3 voxels (clipped to the grid)
    glm::ivec3 first{0}, last{0}; ///< the region's voxel bounds, inclusive, inside the grid
    double value = 0.0;           ///< the data value at `center`
    double minimum = 0.0, maximum = 0.0, mean = 0.0; ///< over the region's finite values
    glm::dvec2 dataRange{0.0, 1.0};
    /// Bins over v = clamp((d - lo) / (hi - lo), 0, 1), bin round(v * (bins - 1)), as
    /// Histogram::of counts them; non-finite values are not counted.
    std::vector<std::uint64_t> counts;
    std::uint64_t samples = 0;

    /// The region of `k` voxels a side around `voxel` (for an even k, one more voxel below the
    /// centre than above: c - k/2 .. c + k/2 - 1), clipped to the grid. `voxel` must lie inside
    /// the grid and k be >= 1, else std::nullopt. Plain loops over the region, nothing
    /// allocated per voxel.
    static std::optional<RegionHistogram> of(const VolumeGrid& grid, glm::ivec3 voxel, int k,
                                             glm::dvec2 dataRange, int bins = 64);

    /// The voxel whose cell holds `localPoint` (the grid's local coordinates: box centred on
    /// the origin, extent dimensions * spacing), or std::nullopt outside the box.
    static std::optional<glm::ivec3> voxelAt(const VolumeGrid& grid, const glm::dvec3& localPoint);
};

} // namespace volsg
