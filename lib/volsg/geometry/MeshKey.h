#pragma once
// Combines the versions and addresses a mesh depends on into one cache key.

#include <cstdint>

namespace volsg {

/// Order-dependent mix (splitmix64's finalizer on each step): different inputs collide with
/// probability ~2^-64, so a changed Coordinate3 version or a different node in scope gives a
/// different key.
constexpr std::uint64_t combineMeshKey(std::uint64_t key, std::uint64_t value) {
    std::uint64_t z = key ^ (value + 0x9e3779b97f4a7c15ULL + (key << 6) + (key >> 2));
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

} // namespace volsg
