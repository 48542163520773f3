#pragma once
// One extracted voxel object in a file of the series' disk cache: the extracted arrays
// (VoxelObject::Arrays) and every RenderList built so far, as they are in memory (sorted,
// clipped and optimized as they were), so reading gives the object back bit for bit and
// drawing it costs no sort.
#include <cstdint>
#include <string>

#include <volsg/core/Object.h>

namespace volsg {

class VoxelObject;

/// The format version written; a file of another version is refused.
constexpr std::uint32_t kSpillFileVersion = 2;

/// Writes `path.tmp` and renames it to `path`, so a file under `path` is always whole. No
/// fsync: the disk cache lives only as long as the process. Each RenderList is written under
/// its own mutex (the optimizer may hold it); `withRenderLists` false writes the arrays only
/// (read-backs then sort again). Throws Error naming the file. Returns the bytes written.
std::size_t writeSpillFile(const std::string& path, VoxelObject& object,
                           bool withRenderLists = true);

/// The object with the RenderLists the file holds (adopted, not rebuilt). Throws Error naming
/// the file when it is missing, truncated, of another format version, damaged (checksum) or
/// inconsistent.
ref_ptr<VoxelObject> readSpillFile(const std::string& path);

} // namespace volsg
