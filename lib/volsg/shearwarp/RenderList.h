#pragma once
// The voxels of one object sorted for one principal viewing axis: one RenderListEntry per
// slice (and 256^3 piece), packed 32-bit voxels and their attribute arrays (RTVR section 3.1).

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

#include <glm/glm.hpp>

namespace volsg {

/// The voxels of one slice of one 256^3 piece. Ranges index the RenderList's arrays:
/// [first, firstClipped) is the unclipped part, [firstClipped, lastInSlice) the clipped part;
/// only [first, last) and [firstClipped, lastClipped) are drawn: the optimizer moved the
/// voxels that cannot contribute under the current tables behind `last` / `lastClipped`.
struct RenderListEntry {
    std::uint8_t z = 0;     ///< slice within the piece
    glm::u16vec3 offset{0}; ///< piece offset (multiples of 256) in (a, b, c) order
    std::uint32_t first = 0, firstClipped = 0, last = 0, lastClipped = 0, lastInSlice = 0;
    bool optimized = false; ///< the optimizer has classified it under the current tables
    int slice() const { return int(offset.z) + int(z); }
    bool operator==(const RenderListEntry&) const = default;
};

/// Which voxel attributes fill the 16 attribute bits of the packed words (RTVR figure 5):
/// the data value in the 12-bit channel and the gradient magnitude in the 4-bit one, or the
/// gradient direction code in the 12-bit channel and the value's top 4 bits in the 4-bit one.
enum class PackedLayout { ValueMagnitude, GradientValue };

/// One object's voxels for principal axis `axis` (c): slices are planes of constant c, a voxel's
/// in-slice position is (a, b) with a = (c + 1) % 3 and b = (c + 2) % 3. Entries are sorted by
/// slice, then piece; the voxels of each drawn range are sorted by b then a (clipping and
/// optimizing partition stably), which lets threads take bands of rows.
///
/// Attribute arrays are reordered together with the packed array. Lock `mutex` to read or
/// change the list while another thread (the optimizer) may use it.
class RenderList {
public:
    int axis = 2;
    std::vector<std::uint32_t> packed;
    std::vector<std::uint16_t> value12;      ///< normalised value v * 4095
    std::vector<std::uint16_t> gradientCode; ///< GradientCode of the surface normal (-gradient)
    std::vector<std::uint8_t> magnitude8;    ///< gradient magnitude, log-remapped to 8 bits
    std::vector<RenderListEntry> entries;
    mutable std::mutex mutex;

    // What the arrays are arranged for (set by ShearWarpRenderer::prepare, read by the optimizer).
    std::uint64_t clipKey = 0;  ///< clip state the entries are split by (0: none applied yet)
    std::uint64_t tableKey = 0; ///< tables the contribution masks below were made from
    PackedLayout unclippedLayout = PackedLayout::ValueMagnitude;
    PackedLayout clippedLayout = PackedLayout::ValueMagnitude;
    /// Per 16-bit attribute value: can a voxel with it change the image under the current
    /// tables (view-independent part only)? Empty: every voxel can.
    std::vector<std::uint8_t> contributesUnclipped, contributesClipped;

    std::size_t voxelCount() const { return packed.size(); }
    std::size_t memoryBytes() const;

    /// Same voxels, attributes, entries, keys, layouts and masks: everything but the mutex and
    /// scratch space (a list read back from the series' disk cache is this to the one written).
    bool sameContent(const RenderList& other) const;
    /// Throws Error unless every array holds `voxelCount` voxels, the entries tile them in
    /// slice order with ordered ranges inside `dimensions`, and the masks are empty or full:
    /// what a list read from outside the process must satisfy before it is drawn.
    void checkConsistent(std::size_t voxelCount, const glm::ivec3& dimensions) const;

    /// Index-space position (i, j, k) of the voxel at `index` of `entry`.
    glm::ivec3 position(const RenderListEntry& entry, std::size_t index) const;

    /// Rewrites the attribute bits of the packed words in [begin, end) for `layout`.
    void derivePacked(std::uint32_t begin, std::uint32_t end, PackedLayout layout);

    /// Restores the (b, a) order of [begin, end) that clipping and optimizing rely on (after a
    /// reset joins parts that were partitioned before).
    void sortByPosition(std::uint32_t begin, std::uint32_t end);

    /// Stable partition of [begin, end): voxels with keep(index) true first, all arrays moved
    /// together. Returns the index of the first voxel with keep false. `keep` sees indices of
    /// the current order.
    template <class Keep>
    std::uint32_t partition(std::uint32_t begin, std::uint32_t end, Keep keep) {
        scratchOrder_.clear();
        for (std::uint32_t i = begin; i < end; ++i)
            if (keep(i)) scratchOrder_.push_back(i);
        const auto split = std::uint32_t(begin + scratchOrder_.size());
        if (split == end || split == begin) return split;
        for (std::uint32_t i = begin; i < end; ++i)
            if (!keep(i)) scratchOrder_.push_back(i);
        permute(begin, end);
        return split;
    }

private:
    std::vector<std::uint32_t> scratchOrder_;
    void permute(std::uint32_t begin, std::uint32_t end);
    template <class T>
    void permuteArray(std::vector<T>& array, std::uint32_t begin, std::uint32_t end);
};

} // namespace volsg
