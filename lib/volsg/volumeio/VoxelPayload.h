#pragma once
// Moving a volume file's voxel bytes into a VolumeGrid: raw or compressed, byte-swapped in place.

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include <volsg/core/Object.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

class InputFile;

/// Where a file's voxel bytes are and how they are stored.
struct VoxelPayload {
    std::uint64_t offset = 0; ///< first stored byte in the file (headers and skips already added)
    bool atEnd = false;       ///< uncompressed only: the voxels are the file's last bytes
    /// Compressed data: "gzip" or "zlib" (both headers are accepted, the name is for messages);
    /// empty for raw bytes.
    std::string compression;
    std::uint64_t decompressedSkip = 0; ///< compressed only: bytes dropped before the voxels
    std::uint64_t compressedSize = 0;   ///< compressed only: stream length, 0 = to the file's end
    bool bigEndian = false;
};

/// The byte size of such a grid, or an Error naming `headerPath` and `headerLine` when it
/// exceeds `byteLimit` or overflows, a dimension is < 1, or a spacing is not finite and > 0.
std::uint64_t checkedGridBytes(const std::string& headerPath, int headerLine, glm::ivec3 dimensions,
                               VoxelType type, glm::dvec3 spacing, std::uint64_t byteLimit);

/// Reads a whole grid of `dimensions` x `type` from `data` as `payload` describes.
/// Everything that can be checked is checked before the grid is allocated: the byte size
/// against `byteLimit` and the spacing (errors name `headerPath` and `headerLine`), then
/// whether the file can hold the data at all (errors name the data file). Uncompressed: the
/// file must hold exactly the grid's bytes from `offset` on ("expected N bytes of data, file
/// has M"). Compressed: the stream is inflated straight into the grid and must decompress to
/// exactly decompressedSkip + the grid's bytes; inflating stops one byte past that (a
/// decompression bomb costs nothing), and a stream that ends early, is cut off or is corrupt is
/// an Error. Concatenated gzip members are read as one stream, as gzip does. Multi-byte voxels
/// are byte-swapped in place when the file's order is not the host's.
ref_ptr<VolumeGrid> readVoxelGrid(const std::string& headerPath, int headerLine,
                                  glm::ivec3 dimensions, VoxelType type, glm::dvec3 spacing,
                                  std::uint64_t byteLimit, InputFile& data,
                                  const VoxelPayload& payload);

/// Reverses the byte order of each `elementSize`-byte element of `bytes`, in place.
void swapElementBytes(std::byte* bytes, std::size_t byteCount, std::size_t elementSize);

} // namespace volsg
