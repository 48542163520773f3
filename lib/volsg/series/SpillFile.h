#pragma once
// One extracted voxel object in a file of the series' disk cache: the extracted arrays
// (VoxelObject::Arrays) as they are in memory, so reading gives the object back bit for bit.
#include <string>

#include <volsg/core/Object.h>

namespace volsg {

class VoxelObject;

/// Writes `path.tmp` and renames it to `path`, so a file under `path` is always whole. No
/// fsync: the disk cache lives only as long as the process. Throws Error naming the file.
/// Returns the bytes written.
std::size_t writeSpillFile(const std::string& path, const VoxelObject& object);

/// Throws Error naming the file when it is missing, truncated, or not a spill file.
ref_ptr<VoxelObject> readSpillFile(const std::string& path);

} // namespace volsg
