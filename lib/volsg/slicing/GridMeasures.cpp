#include <volsg/slicing/GridMeasures.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <tuple>

#include <volsg/slicing/BrickTexels.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

namespace {

template <class T>
void dataRangeOf(const VolumeGrid& grid, const Brick& b, double lowest, double highest,
                 BrickRange& out) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    const auto voxels = grid.data<T>();
    for (int k = 0; k < b.voxelCount.z; ++k)
        for (int j = 0; j < b.voxelCount.y; ++j)
            extendRange(voxels.data() + brickRowStart(grid, b, j, k), std::size_t(b.voxelCount.x),
                        lowest, highest, lo, hi);
    out.dataMin = lo;
    out.dataMax = hi;
}

template <class T> void tagRangeOf(const VolumeGrid& grid, const Brick& b, BrickRange& out) {
    int lo = std::numeric_limits<int>::max(), hi = std::numeric_limits<int>::min();
    forEachBrickVoxel<T>(grid, b, [&](T x) {
        lo = std::min(lo, int(x));
        hi = std::max(hi, int(x));
    });
    out.tagMin = lo;
    out.tagMax = hi;
}

} // namespace

std::vector<BrickRange> measureBrickRanges(const VolumeGrid& data, const VolumeGrid* tags,
                                           const BrickLayout& layout, double lowest,
                                           double highest) {
    const std::vector<Brick>& bricks = layout.bricks();
    if (!tags && bricks.size() == 1 && bricks[0].firstVoxel == glm::ivec3(0) &&
        bricks[0].voxelCount == data.dimensions())
        return {BrickRange{lowest, highest, 0, 0}}; // non-finite voxels count as the extremes
    std::vector<BrickRange> out(bricks.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        const Brick& b = bricks[i];
        switch (data.type()) {
        case VoxelType::UByte:
            dataRangeOf<std::uint8_t>(data, b, lowest, highest, out[i]);
            break;
        case VoxelType::UShort:
            dataRangeOf<std::uint16_t>(data, b, lowest, highest, out[i]);
            break;
        case VoxelType::Short:
            dataRangeOf<std::int16_t>(data, b, lowest, highest, out[i]);
            break;
        case VoxelType::Float:
            dataRangeOf<float>(data, b, lowest, highest, out[i]);
            break;
        }
        if (tags) {
            if (tags->type() == VoxelType::UByte)
                tagRangeOf<std::uint8_t>(*tags, b, out[i]);
            else
                tagRangeOf<std::uint16_t>(*tags, b, out[i]);
        }
    }
    return out;
}

GridMeasures GridMeasures::of(const VolumeGrid& data, const VolumeGrid* tags,
                              const BrickLayout& layout) {
    GridMeasures m;
    m.bricks = layout.bricks();
    if (data.type() != VoxelType::Float) {
        // Integer voxels are all finite: the cells' ranges give the grid's in the same pass.
        m.cells.measure(data, tags, 0.0, 0.0);
        std::tie(m.finiteMin, m.finiteMax) = m.cells.overallRange();
    } else {
        std::tie(m.finiteMin, m.finiteMax) = data.minMax(); // finite values only
        m.cells.measure(data, tags, m.finiteMin, m.finiteMax);
    }
    m.ranges = measureBrickRanges(data, tags, layout, m.finiteMin, m.finiteMax);
    return m;
}

bool GridMeasures::sameBricks(const BrickLayout& layout) const {
    const std::vector<Brick>& other = layout.bricks();
    if (other.size() != bricks.size()) return false;
    for (std::size_t i = 0; i < bricks.size(); ++i)
        if (other[i].firstVoxel != bricks[i].firstVoxel ||
            other[i].voxelCount != bricks[i].voxelCount)
            return false;
    return true;
}

} // namespace volsg
