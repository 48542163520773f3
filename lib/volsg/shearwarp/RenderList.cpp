#include <volsg/shearwarp/RenderList.h>

#include <algorithm>
#include <string>

#include <volsg/core/Error.h>

#include <volsg/shearwarp/PackedVoxel.h>

namespace volsg {

std::size_t RenderList::memoryBytes() const {
    return packed.size() * (sizeof(std::uint32_t) + 2 * sizeof(std::uint16_t) + 1) +
           entries.size() * sizeof(RenderListEntry);
}

bool RenderList::sameContent(const RenderList& other) const {
    return axis == other.axis && packed == other.packed && value12 == other.value12 &&
           gradientCode == other.gradientCode && magnitude8 == other.magnitude8 &&
           entries == other.entries && clipKey == other.clipKey && tableKey == other.tableKey &&
           unclippedLayout == other.unclippedLayout && clippedLayout == other.clippedLayout &&
           contributesUnclipped == other.contributesUnclipped &&
           contributesClipped == other.contributesClipped;
}

void RenderList::checkConsistent(std::size_t voxelCount, const glm::ivec3& dimensions) const {
    auto fail = [](const std::string& what) { throw Error("RenderList: " + what); };
    if (axis < 0 || axis > 2) fail("axis must be 0, 1 or 2");
    if (packed.size() != voxelCount || value12.size() != voxelCount ||
        gradientCode.size() != voxelCount || magnitude8.size() != voxelCount)
        fail("arrays differ from the object's " + std::to_string(voxelCount) + " voxels");
    const std::size_t maskSize = std::size_t(1) << 16;
    for (const auto* mask : {&contributesUnclipped, &contributesClipped})
        if (!mask->empty() && mask->size() != maskSize) fail("contribution mask of wrong size");
    for (const PackedLayout layout : {unclippedLayout, clippedLayout})
        if (layout != PackedLayout::ValueMagnitude && layout != PackedLayout::GradientValue)
            fail("unknown packed layout");
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    std::uint32_t next = 0;
    int lastSlice = -1;
    for (const RenderListEntry& e : entries) {
        if (e.first != next || e.first > e.last || e.last > e.firstClipped ||
            e.firstClipped > e.lastClipped || e.lastClipped > e.lastInSlice)
            fail("entry ranges out of order");
        if (e.slice() < lastSlice || e.slice() >= dimensions[axis] || e.offset.x >= dimensions[a] ||
            e.offset.y >= dimensions[b] || (e.offset.x & 0xFF) != 0 || (e.offset.y & 0xFF) != 0 ||
            (e.offset.z & 0xFF) != 0)
            fail("entry outside the object's dimensions");
        if (e.lastInSlice > voxelCount) fail("entries do not cover the voxels");
        const unsigned spanA = unsigned(dimensions[a] - e.offset.x);
        const unsigned spanB = unsigned(dimensions[b] - e.offset.y);
        for (std::uint32_t i = e.first; i < e.lastInSlice; ++i)
            if (PackedVoxel::a(packed[i]) >= spanA || PackedVoxel::b(packed[i]) >= spanB)
                fail("voxel outside the object's dimensions");
        lastSlice = e.slice();
        next = e.lastInSlice;
    }
    if (next != voxelCount) fail("entries do not cover the voxels");
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
