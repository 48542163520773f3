#pragma once
// 12-bit codes for unit vectors: the index of the 4096-entry shading tables.

#include <cstdint>

#include <glm/glm.hpp>

namespace volsg {

/// Octahedral mapping of the unit sphere onto a 64 x 64 grid (6 + 6 bits): every code covers
/// about the same solid angle, unlike a latitude/longitude split, so shading is equally fine
/// in every direction. The largest angle between a vector and its code's centre is about 3.5
/// degrees (measured over 2000 directions). A zero vector encodes as +z.
struct GradientCode {
    static constexpr int side = 64;
    static constexpr int count = side * side; ///< 4096
    static std::uint16_t encode(const glm::vec3& direction);
    static glm::vec3 decode(std::uint16_t code); ///< unit vector at the code's cell centre
};

} // namespace volsg
