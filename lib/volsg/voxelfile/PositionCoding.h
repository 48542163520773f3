#pragma once
// Run coding of voxel positions per scanline: how the .vsgv file stores where an object's
// voxels are (lib/volsg/voxelfile/README.md).

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace volsg {

/// Codes positions sorted in (k, j, i) order, as extraction produces them: for each scanline
/// (k, j) in turn, the number of runs of consecutive i, then per run the gap from the end of
/// the previous run (or from i = 0) and the run length minus one; all as LEB128 varints.
/// Throws Error when the positions are not strictly increasing in that order or lie outside
/// `dimensions`.
std::string encodePositions(const glm::ivec3& dimensions, const std::vector<std::uint16_t>& i,
                            const std::vector<std::uint16_t>& j,
                            const std::vector<std::uint16_t>& k);

/// Decodes `count` positions. Throws Error (with `where` in the message) when the code is
/// malformed: runs past the scanline, a count other than `count`, bytes left over or missing.
/// Allocates only `count` entries per axis, which the caller has checked.
void decodePositions(const std::uint8_t* code, std::size_t size, const glm::ivec3& dimensions,
                     std::size_t count, std::vector<std::uint16_t>& i,
                     std::vector<std::uint16_t>& j, std::vector<std::uint16_t>& k,
                     const std::string& where);

} // namespace volsg
