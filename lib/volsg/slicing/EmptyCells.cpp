#include <volsg/slicing/EmptyCells.h>

#include <algorithm>
#include <cstdint>
#include <limits>

#include <volsg/slicing/BrickTexels.h>
#include <volsg/slicing/TransferTable.h>
#include <volsg/volume/TransferFunction1D.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

namespace {

/// The voxels a trilinear sample in cell c reads: the cell's and one layer around it.
Brick cellReach(const glm::ivec3& c, const glm::ivec3& dimensions) {
    Brick b;
    const glm::ivec3 lo = glm::max(c * EmptyCells::kCellSize - 1, glm::ivec3(0));
    const glm::ivec3 hi = glm::min((c + 1) * EmptyCells::kCellSize + 1, dimensions);
    b.firstVoxel = lo;
    b.voxelCount = hi - lo;
    return b;
}

template <class T>
void measureData(const VolumeGrid& grid, const glm::ivec3& cells, double lowest, double highest,
                 std::vector<double>& minOut, std::vector<double>& maxOut) {
    std::size_t n = 0;
    for (int z = 0; z < cells.z; ++z)
        for (int y = 0; y < cells.y; ++y)
            for (int x = 0; x < cells.x; ++x, ++n) {
                double lo = std::numeric_limits<double>::infinity(), hi = -lo;
                forEachBrickVoxel<T>(grid, cellReach({x, y, z}, grid.dimensions()), [&](T v) {
                    const double d = replacedValue(v, lowest, highest);
                    lo = std::min(lo, d);
                    hi = std::max(hi, d);
                });
                minOut[n] = lo;
                maxOut[n] = hi;
            }
}

template <class T>
void measureTags(const VolumeGrid& tags, const glm::ivec3& cells, std::vector<int>& minOut,
                 std::vector<int>& maxOut) {
    std::size_t n = 0;
    for (int z = 0; z < cells.z; ++z)
        for (int y = 0; y < cells.y; ++y)
            for (int x = 0; x < cells.x; ++x, ++n) {
                int lo = std::numeric_limits<int>::max(), hi = std::numeric_limits<int>::min();
                forEachBrickVoxel<T>(tags, cellReach({x, y, z}, tags.dimensions()), [&](T v) {
                    lo = std::min(lo, int(v));
                    hi = std::max(hi, int(v));
                });
                minOut[n] = lo;
                maxOut[n] = hi;
            }
}

} // namespace

void EmptyCells::measure(const VolumeGrid& data, const VolumeGrid* tags, double lowest,
                         double highest) {
    cells_ = (data.dimensions() + (kCellSize - 1)) / kCellSize;
    const std::size_t count = std::size_t(cells_.x) * std::size_t(cells_.y) * std::size_t(cells_.z);
    dataMin_.assign(count, 0.0);
    dataMax_.assign(count, 0.0);
    switch (data.type()) {
    case VoxelType::UByte:
        measureData<std::uint8_t>(data, cells_, lowest, highest, dataMin_, dataMax_);
        break;
    case VoxelType::UShort:
        measureData<std::uint16_t>(data, cells_, lowest, highest, dataMin_, dataMax_);
        break;
    case VoxelType::Short:
        measureData<std::int16_t>(data, cells_, lowest, highest, dataMin_, dataMax_);
        break;
    case VoxelType::Float:
        measureData<float>(data, cells_, lowest, highest, dataMin_, dataMax_);
        break;
    }
    tagMin_.assign(count, 0);
    tagMax_.assign(count, 0);
    if (tags) {
        if (tags->type() == VoxelType::UByte)
            measureTags<std::uint8_t>(*tags, cells_, tagMin_, tagMax_);
        else
            measureTags<std::uint16_t>(*tags, cells_, tagMin_, tagMax_);
    }
    flags_.clear();
}

void EmptyCells::classify(const TransferTable& table, bool tagged, bool maximum) {
    flags_.resize(dataMin_.size());
    std::size_t empty = 0;
    const glm::dvec2 range = table.dataRange(0);
    const auto& alpha = table.function(0).channel(TransferFunction1D::Alpha);
    for (std::size_t i = 0; i < flags_.size(); ++i) {
        bool may = true;
        if (maximum) { // v may run either way with the data (a reversed dataRange)
            const double v = std::max(TransferFunction1D::normalise(dataMin_[i], range.x, range.y),
                                      TransferFunction1D::normalise(dataMax_[i], range.x, range.y));
            may = alpha.maxOver(0.0, v) > 0.0;
        } else {
            may = table.mayEmit(dataMin_[i], dataMax_[i], tagged, tagMin_[i], tagMax_[i]);
        }
        flags_[i] = may ? 1 : 0;
        empty += flags_[i] == 0;
    }
    emptyFraction_ = flags_.empty() ? 0.0 : double(empty) / double(flags_.size());
}

} // namespace volsg
