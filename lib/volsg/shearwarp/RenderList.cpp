#include <volsg/shearwarp/RenderList.h>

#include <algorithm>

#include <volsg/shearwarp/PackedVoxel.h>

namespace volsg {

std::size_t RenderList::memoryBytes() const {
    return packed.size() * (sizeof(std::uint32_t) + 2 * sizeof(std::uint16_t) + 1) +
           entries.size() * sizeof(RenderListEntry);
}

glm::ivec3 RenderList::position(const RenderListEntry& entry, std::size_t index) const {
    const std::uint32_t v = packed[index];
    glm::ivec3 p(0);
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    p[a] = int(entry.offset.x) + int(PackedVoxel::a(v));
    p[b] = int(entry.offset.y) + int(PackedVoxel::b(v));
    p[axis] = entry.slice();
    return p;
}

void RenderList::derivePacked(std::uint32_t begin, std::uint32_t end, PackedLayout layout) {
    if (layout == PackedLayout::ValueMagnitude) {
        for (std::uint32_t i = begin; i < end; ++i)
            packed[i] = PackedVoxel::withAttributes(packed[i], value12[i], magnitude8[i] >> 4);
    } else {
        for (std::uint32_t i = begin; i < end; ++i)
            packed[i] = PackedVoxel::withAttributes(packed[i], gradientCode[i], value12[i] >> 8);
    }
}

void RenderList::sortByPosition(std::uint32_t begin, std::uint32_t end) {
    auto position = [&](std::uint32_t i) { return packed[i] & 0xFFFFu; }; // b in the high byte
    bool sorted = true;
    for (std::uint32_t i = begin + 1; i < end && sorted; ++i)
        sorted = position(i - 1) <= position(i);
    if (sorted) return;
    scratchOrder_.resize(end - begin);
    for (std::uint32_t i = begin; i < end; ++i)
        scratchOrder_[i - begin] = i;
    std::stable_sort(scratchOrder_.begin(), scratchOrder_.end(),
                     [&](std::uint32_t x, std::uint32_t y) { return position(x) < position(y); });
    permute(begin, end);
}

template <class T>
void RenderList::permuteArray(std::vector<T>& array, std::uint32_t begin, std::uint32_t end) {
    std::vector<T> moved(end - begin);
    for (std::uint32_t i = 0; i < end - begin; ++i)
        moved[i] = array[scratchOrder_[i]];
    std::copy(moved.begin(), moved.end(), array.begin() + begin);
}

void RenderList::permute(std::uint32_t begin, std::uint32_t end) {
    permuteArray(packed, begin, end);
    permuteArray(value12, begin, end);
    permuteArray(gradientCode, begin, end);
    permuteArray(magnitude8, begin, end);
}

} // namespace volsg
