#include <volsg/editors/RegionHistogram.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <volsg/volume/VolumeGrid.h>

namespace volsg {

std::optional<RegionHistogram> RegionHistogram::of(const VolumeGrid& grid, glm::ivec3 voxel, int k,
                                                   glm::dvec2 dataRange, int bins) {
    if (k < 1 || !grid.contains(voxel.x, voxel.y, voxel.z)) return std::nullopt;
    RegionHistogram r;
    r.center = voxel;
    r.size = k;
    r.dataRange = dataRange;
    r.value = grid.value(voxel.x, voxel.y, voxel.z);
    r.first = glm::max(voxel - glm::ivec3(k / 2), glm::ivec3(0));
    r.last = glm::min(voxel + glm::ivec3((k - 1) / 2), grid.dimensions() - 1);
    r.counts.assign(std::size_t(std::max(bins, 1)), 0);

    const double width = dataRange.y - dataRange.x;
    const double scale = width != 0.0 ? 1.0 / width : 0.0;
    const double lastBin = double(r.counts.size() - 1);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, sum = 0.0;
    for (int z = r.first.z; z <= r.last.z; ++z)
        for (int y = r.first.y; y <= r.last.y; ++y)
            for (int x = r.first.x; x <= r.last.x; ++x) {
                const double d = grid.value(x, y, z);
                if (!std::isfinite(d)) continue;
                const double v = width != 0.0 ? std::clamp((d - dataRange.x) * scale, 0.0, 1.0)
                                              : (d >= dataRange.x ? 1.0 : 0.0);
                ++r.counts[std::size_t(std::lround(v * lastBin))];
                ++r.samples;
                lo = std::min(lo, d);
                hi = std::max(hi, d);
                sum += d;
            }
    if (r.samples > 0) {
        r.minimum = lo;
        r.maximum = hi;
        r.mean = sum / double(r.samples);
    }
    return r;
}

std::optional<glm::ivec3> RegionHistogram::voxelAt(const VolumeGrid& grid,
                                                   const glm::dvec3& localPoint) {
    const glm::dvec3 cell = (localPoint + 0.5 * grid.extent()) / grid.spacing();
    const glm::ivec3 voxel(glm::floor(cell));
    // The far faces of the box belong to the last voxel.
    const glm::dvec3 dims(grid.dimensions());
    for (int a = 0; a < 3; ++a)
        if (!(cell[a] >= 0.0 && cell[a] <= dims[a])) return std::nullopt;
    return glm::min(voxel, grid.dimensions() - 1);
}

} // namespace volsg
