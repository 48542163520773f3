#pragma once
// The one gatherer of "the volume in scope" at a node, for every volume path.

#include <cstdint>
#include <optional>

#include <volsg/volume/VolumeModel.h>

namespace volsg {

class State;

class TransferFunction;

/// The volume in scope at the current node of a traversal (VolumeInScope says what each
/// member means), read from the state: the nearest VolumeData, the nearest TransferFunction
/// of each tag, the nearest BoxClip, every ClipPlane that is on, the model matrix. Nothing
/// without a VolumeData in scope, or when it has no grid. Loads the data
/// (VolumeData::grid() throws Error naming the file on failure); throws Error for a
/// TransferFunction tag below -1 or an invalid function.
std::optional<VolumeInScope> gatherVolumeInScope(const State& state);

/// As gatherVolumeInScope(), but without loading the data: `data` and `tags` stay empty
/// (`dataOwner` is the VolumeData in scope, if any), for paths that read voxels elsewhere
/// (ShearWarpVolume's voxel files and series).
VolumeInScope gatherScopeWithoutData(const State& state);

/// The key of one TransferFunction node's content (VolumeInScope::transferKeys).
std::uint64_t transferFunctionKey(const TransferFunction& node);

} // namespace volsg
