#pragma once
// The renderable form of one voxel in a RenderListEntry: 32 bits (RTVR section 3.1).

#include <cstdint>

namespace volsg {

/// Bits 0-7: a (position along the slice's first axis, within its 256^3 piece), bits 8-15: b
/// (second axis), bits 16-27: the 12-bit main attribute, bits 28-31: the 4-bit second
/// attribute. The slice coordinate and the piece offset are stored once per RenderListEntry.
struct PackedVoxel {
    static constexpr std::uint32_t pack(unsigned a, unsigned b, unsigned main12, unsigned second4) {
        return (a & 0xFFu) | ((b & 0xFFu) << 8) | ((main12 & 0xFFFu) << 16) |
               ((second4 & 0xFu) << 28);
    }
    static constexpr unsigned a(std::uint32_t v) { return v & 0xFFu; }
    static constexpr unsigned b(std::uint32_t v) { return (v >> 8) & 0xFFu; }
    static constexpr unsigned main12(std::uint32_t v) { return (v >> 16) & 0xFFFu; }
    static constexpr unsigned second4(std::uint32_t v) { return v >> 28; }
    /// The 16 attribute bits as one table index: second4 * 4096 + main12 (the top half).
    static constexpr unsigned attributes16(std::uint32_t v) { return v >> 16; }
    /// Replaces the 16 attribute bits, keeping the position.
    static constexpr std::uint32_t withAttributes(std::uint32_t v, unsigned main12,
                                                  unsigned second4) {
        return (v & 0xFFFFu) | ((main12 & 0xFFFu) << 16) | ((second4 & 0xFu) << 28);
    }
};

} // namespace volsg
