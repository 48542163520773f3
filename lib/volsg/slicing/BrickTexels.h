#pragma once
// A brick's voxels as its 3D textures take them: one definition for the direct upload and the
// staged (pixel unpack buffer) upload of the Volume slicer, so both send the same bytes.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

#include <volsg/slicing/BrickLayout.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

/// As the reference: NaN and -Inf become the smallest finite value, +Inf the largest.
template <class T> double replacedValue(T x, double lowest, double highest) {
    if constexpr (std::is_same_v<T, float>) {
        if (std::isnan(x) || x == -std::numeric_limits<float>::infinity()) return lowest;
        if (x == std::numeric_limits<float>::infinity()) return highest;
    }
    (void)lowest;
    (void)highest;
    return double(x);
}

/// Widens [lo, hi] by the n voxels at `row`, non-finite ones replaced as replacedValue does.
/// Integer voxels are compared in their own type (the loop vectorises), floats one by one.
template <class T>
void extendRange(const T* row, std::size_t n, double lowest, double highest, double& lo,
                 double& hi) {
    if (n == 0) return;
    if constexpr (std::is_integral_v<T>) {
        T a = row[0], b = row[0];
        for (std::size_t i = 1; i < n; ++i) {
            a = row[i] < a ? row[i] : a;
            b = row[i] > b ? row[i] : b;
        }
        lo = std::min(lo, double(a));
        hi = std::max(hi, double(b));
    } else {
        for (std::size_t i = 0; i < n; ++i) {
            const double d = replacedValue(row[i], lowest, highest);
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
    }
}

/// The grid index of the first voxel of the brick's texel row (j, k).
inline std::size_t brickRowStart(const VolumeGrid& grid, const Brick& b, int j, int k) {
    const glm::ivec3 d = grid.dimensions();
    return std::size_t(b.firstVoxel.x) +
           std::size_t(d.x) * (std::size_t(b.firstVoxel.y + j) +
                               std::size_t(d.y) * std::size_t(b.firstVoxel.z + k));
}

/// Calls f(value) for every voxel of the brick's texture, x fastest.
template <class T, class F> void forEachBrickVoxel(const VolumeGrid& grid, const Brick& b, F&& f) {
    const auto src = grid.data<T>();
    for (int k = 0; k < b.voxelCount.z; ++k)
        for (int j = 0; j < b.voxelCount.y; ++j) {
            const std::size_t row = brickRowStart(grid, b, j, k);
            for (int i = 0; i < b.voxelCount.x; ++i)
                f(src[row + std::size_t(i)]);
        }
}

/// Bytes of one texel as uploaded (DataFormat::type of the grid's voxel type): 1, 2 or 4.
std::size_t uploadTexelBytes(VoxelType type);

/// The brick's data texels in upload order when the grid's own memory is them (the brick is
/// the whole grid and UByte or UShort), else null: then writeBrickTexels converts.
const void* directBrickTexels(const VolumeGrid& grid, const Brick& b);
/// Writes the brick's data texels (b.texels() * uploadTexelBytes): UByte and UShort as they
/// are, Short shifted by 32768, Float with non-finite values replaced by finiteMin/finiteMax.
void writeBrickTexels(const VolumeGrid& grid, const Brick& b, double finiteMin, double finiteMax,
                      void* out);

/// As directBrickTexels and writeBrickTexels for a label grid (UByte or UShort, unconverted).
const void* directBrickLabels(const VolumeGrid& tags, const Brick& b);
void writeBrickLabels(const VolumeGrid& tags, const Brick& b, void* out);

} // namespace volsg
