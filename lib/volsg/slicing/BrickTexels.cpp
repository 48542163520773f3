#include <volsg/slicing/BrickTexels.h>

#include <cstdint>
#include <cstring>

namespace volsg {

namespace {

template <class T, class U, class F>
void writeConverted(const VolumeGrid& grid, const Brick& b, void* out, F&& convert) {
    U* to = static_cast<U*>(out);
    std::size_t n = 0;
    forEachBrickVoxel<T>(grid, b, [&](T x) { to[n++] = convert(x); });
}

bool isWhole(const VolumeGrid& grid, const Brick& b) {
    return b.firstVoxel == glm::ivec3(0) && b.voxelCount == grid.dimensions();
}

/// Unconverted texels: row by row (the whole grid at once when the brick is the grid).
template <class T> void copyRows(const VolumeGrid& grid, const Brick& b, void* out) {
    const T* src = grid.data<T>().data();
    auto* to = static_cast<std::uint8_t*>(out);
    if (isWhole(grid, b)) {
        std::memcpy(to, src, b.texels() * sizeof(T));
        return;
    }
    const std::size_t rowBytes = std::size_t(b.voxelCount.x) * sizeof(T);
    for (int k = 0; k < b.voxelCount.z; ++k)
        for (int j = 0; j < b.voxelCount.y; ++j) {
            std::memcpy(to, src + brickRowStart(grid, b, j, k), rowBytes);
            to += rowBytes;
        }
}

} // namespace

std::size_t uploadTexelBytes(VoxelType type) {
    switch (type) {
    case VoxelType::UByte:
        return 1;
    case VoxelType::UShort:
    case VoxelType::Short:
        return 2;
    case VoxelType::Float:
        return 4;
    }
    return 1;
}

const void* directBrickTexels(const VolumeGrid& grid, const Brick& b) {
    if (!isWhole(grid, b)) return nullptr;
    if (grid.type() == VoxelType::UByte) return grid.data<std::uint8_t>().data();
    if (grid.type() == VoxelType::UShort) return grid.data<std::uint16_t>().data();
    return nullptr;
}

void writeBrickTexels(const VolumeGrid& grid, const Brick& b, double finiteMin, double finiteMax,
                      void* out) {
    switch (grid.type()) {
    case VoxelType::UByte:
        copyRows<std::uint8_t>(grid, b, out);
        break;
    case VoxelType::UShort:
        copyRows<std::uint16_t>(grid, b, out);
        break;
    case VoxelType::Short:
        writeConverted<std::int16_t, std::uint16_t>(
            grid, b, out, [](std::int16_t x) { return std::uint16_t(int(x) + 32768); });
        break;
    case VoxelType::Float:
        writeConverted<float, float>(grid, b, out, [finiteMin, finiteMax](float x) {
            return float(replacedValue(x, finiteMin, finiteMax));
        });
        break;
    }
}

const void* directBrickLabels(const VolumeGrid& tags, const Brick& b) {
    if (!isWhole(tags, b)) return nullptr;
    if (tags.type() == VoxelType::UShort) return tags.data<std::uint16_t>().data();
    return tags.data<std::uint8_t>().data();
}

void writeBrickLabels(const VolumeGrid& tags, const Brick& b, void* out) {
    if (tags.type() == VoxelType::UShort)
        copyRows<std::uint16_t>(tags, b, out);
    else
        copyRows<std::uint8_t>(tags, b, out);
}

} // namespace volsg
