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

/// Per cell, the (min, max) over the voxels a trilinear sample in it reads: its own 8^3 and
/// the layer of one voxel around it, i.e. voxels [8c - 1, 8c + 9) clamped, along every axis.
/// A box range is separable: rows along x first (per row, per cell), then those along y, then
/// along z, so each voxel is read once; non-finite voxels count as `lowest` / `highest`.
template <class T>
void measureRanges(const glm::ivec3& d, const glm::ivec3& cells, const T* voxels, double lowest,
                   double highest, std::vector<double>& minOut, std::vector<double>& maxOut) {
    constexpr int n = EmptyCells::kCellSize;
    const auto lowOf = [](int c) { return std::max(c * n - 1, 0); };
    const auto highOf = [](int c, int size) { return std::min((c + 1) * n + 1, size); };
    const double inf = std::numeric_limits<double>::infinity();
    // x: per (cell x, y, z)
    std::vector<double> loX(std::size_t(cells.x) * d.y * d.z, inf), hiX(loX.size(), -inf);
    for (int z = 0; z < d.z; ++z)
        for (int y = 0; y < d.y; ++y) {
            const std::size_t row = std::size_t(d.x) * (std::size_t(y) + std::size_t(d.y) * z);
            for (int c = 0; c < cells.x; ++c) {
                double lo = inf, hi = -inf;
                extendRange(voxels + row + std::size_t(lowOf(c)),
                            std::size_t(highOf(c, d.x) - lowOf(c)), lowest, highest, lo, hi);
                const std::size_t o =
                    std::size_t(c) + std::size_t(cells.x) * (y + std::size_t(d.y) * z);
                loX[o] = lo;
                hiX[o] = hi;
            }
        }
    // y: per (cell x, cell y, z)
    std::vector<double> loY(std::size_t(cells.x) * cells.y * d.z, inf), hiY(loY.size(), -inf);
    for (int z = 0; z < d.z; ++z)
        for (int cy = 0; cy < cells.y; ++cy)
            for (int y = lowOf(cy); y < highOf(cy, d.y); ++y)
                for (int cx = 0; cx < cells.x; ++cx) {
                    const std::size_t from =
                        std::size_t(cx) + std::size_t(cells.x) * (y + std::size_t(d.y) * z);
                    const std::size_t to =
                        std::size_t(cx) + std::size_t(cells.x) * (cy + std::size_t(cells.y) * z);
                    loY[to] = std::min(loY[to], loX[from]);
                    hiY[to] = std::max(hiY[to], hiX[from]);
                }
    // z: per cell
    const std::size_t plane = std::size_t(cells.x) * cells.y;
    for (int cz = 0; cz < cells.z; ++cz)
        for (int z = lowOf(cz); z < highOf(cz, d.z); ++z)
            for (std::size_t i = 0; i < plane; ++i) {
                const std::size_t to = i + plane * std::size_t(cz);
                minOut[to] = std::min(minOut[to], loY[i + plane * std::size_t(z)]);
                maxOut[to] = std::max(maxOut[to], hiY[i + plane * std::size_t(z)]);
            }
}

template <class T>
void measureData(const VolumeGrid& grid, const glm::ivec3& cells, double lowest, double highest,
                 std::vector<double>& minOut, std::vector<double>& maxOut) {
    measureRanges(grid.dimensions(), cells, grid.data<T>().data(), lowest, highest, minOut, maxOut);
}

template <class T>
void measureTags(const VolumeGrid& tags, const glm::ivec3& cells, std::vector<int>& minOut,
                 std::vector<int>& maxOut) {
    std::vector<double> lo(minOut.size(), std::numeric_limits<double>::infinity());
    std::vector<double> hi(maxOut.size(), -std::numeric_limits<double>::infinity());
    measureRanges(tags.dimensions(), cells, tags.data<T>().data(), 0.0, 0.0, lo, hi);
    for (std::size_t i = 0; i < lo.size(); ++i) {
        minOut[i] = int(lo[i]);
        maxOut[i] = int(hi[i]);
    }
}

} // namespace

void EmptyCells::measure(const VolumeGrid& data, const VolumeGrid* tags, double lowest,
                         double highest) {
    cells_ = (data.dimensions() + (kCellSize - 1)) / kCellSize;
    const std::size_t count = std::size_t(cells_.x) * std::size_t(cells_.y) * std::size_t(cells_.z);
    dataMin_.assign(count, std::numeric_limits<double>::infinity());
    dataMax_.assign(count, -std::numeric_limits<double>::infinity());
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

void EmptyCells::classify(const TransferTable& table, bool tagged, bool maximum, double padV) {
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
            may = table.mayEmit(dataMin_[i], dataMax_[i], tagged, tagMin_[i], tagMax_[i], padV);
        }
        flags_[i] = may ? 1 : 0;
        empty += flags_[i] == 0;
    }
    emptyFraction_ = flags_.empty() ? 0.0 : double(empty) / double(flags_.size());
}

std::pair<double, double> EmptyCells::overallRange() const {
    if (dataMin_.empty()) return {0.0, 0.0};
    return {*std::min_element(dataMin_.begin(), dataMin_.end()),
            *std::max_element(dataMax_.begin(), dataMax_.end())};
}

} // namespace volsg
