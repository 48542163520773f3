#pragma once
// The data histogram drawn under a transfer-function editor: voxel counts over the normalised
// value v of docs/SCENE-FORMAT.md section 4, on a linear or a log scale.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace volsg {

class VolumeGrid;

struct Histogram {
    std::vector<std::uint64_t> counts; ///< bins over v in [0, 1]; values outside clamp to the ends
    std::uint64_t samples = 0;

    /// Counts v = clamp((d - lo) / (hi - lo), 0, 1) for the voxels of `grid` into `bins` bins.
    /// Grids above `maxSamples` voxels are sampled with a fixed stride (plain loop, no allocation
    /// per voxel).
    static Histogram of(const VolumeGrid& grid, glm::dvec2 dataRange, int bins = 256,
                        std::uint64_t maxSamples = std::uint64_t(1) << 22);

    /// Bar heights in [0, 1]: count / largest count, or log(1 + count) / log(1 + largest).
    std::vector<float> heights(bool logScale) const;
};

} // namespace volsg
