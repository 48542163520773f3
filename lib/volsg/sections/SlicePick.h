#pragma once
// Picking on planar sections.

#include <volsg/sections/SlicePlane.h>
#include <volsg/sections/SliceSampler.h>
#include <volsg/sections/SliceVolume.h>

namespace volsg {

class PickAction;

/// Hits the slice where the action's ray crosses its polygon inside the volume box and the
/// slice is drawn there (not discarded by its alpha use), reporting the voxel and data value
/// (PickedVoxel) with the plane's normal. ClipPlanes, near and far are the action's.
void pickSlice(PickAction& action, const SliceVolume& volume, const SlicePlane& plane,
               const SliceStyle& style);

} // namespace volsg
