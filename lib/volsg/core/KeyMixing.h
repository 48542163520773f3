#pragma once
// Cache keys built from field values: a node's GPU or voxel data is rebuilt only when the key
// of what it depends on changes.

#include <cstdint>
#include <cstring>

namespace volsg {

/// FNV-1a style mixing of a value into a running key.
inline std::uint64_t mixKey(std::uint64_t key, std::uint64_t value) {
    return (key ^ value) * 0x100000001b3ULL;
}

/// The bits of a double, to mix it into a key exactly.
inline std::uint64_t bitsOf(double v) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    return bits;
}

} // namespace volsg
