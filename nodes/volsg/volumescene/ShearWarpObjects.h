#pragma once
// What a ShearWarpVolume draws, from the volume in scope and the state nodes among its
// children: the objects as the shear-warp engine takes them, and the reference's description.

#include <optional>
#include <vector>

#include <volsg/shearwarp/ShearWarpScene.h>
#include <volsg/volume/VolumeModel.h>

namespace volsg {

class ShearWarpVolume;
class State;
class VolumeObject;

/// The node's objects as the engine takes them, from the state at the node (VolumeData,
/// TransferFunctions, BoxClip, ClipPlanes above it: gatherVolumeInScope) and the state nodes
/// among its children (each VolumeObject takes the state before it). Extracts (or reuses)
/// voxel lists. `sources` receives the VolumeObject of each. Empty without VolumeData in scope
/// (and without a voxelFile). Throws Error for an invalid TransferFunction. `grid`, when
/// given, replaces the VolumeData's grid (a paged volume's level read whole: the same box).
std::vector<ShearWarpObject> gatherShearWarpObjects(ShearWarpVolume& node, const State& state,
                                                    std::vector<VolumeObject*>* sources = nullptr,
                                                    ref_ptr<const VolumeGrid> grid = nullptr);

/// The reference ray caster's description of the node (ReferenceScene's bridge): one volume
/// with a transfer function per object's tag (WHOLE objects: the default), MIP when every
/// object is MIP, clip planes and the nearest BoxClip (clippedOpacity of the first object as
/// outside opacity). THRESHOLD sources and non-TF render modes have no counterpart there; the
/// description is exact for TF-mode DVR/MIP objects. Throws Error without VolumeData in scope.
RayCastVolume describeShearWarpVolume(ShearWarpVolume& node, const State& state);

} // namespace volsg
