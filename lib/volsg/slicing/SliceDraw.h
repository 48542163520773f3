#pragma once
// The Volume slicer's GL work of a frame: program, uniforms, textures, brick draws, composite.

#include <span>

#include <volsg/render/FrameContext.h>
#include <volsg/slicing/SlicePlan.h>
#include <volsg/slicing/SliceShared.h>
#include <volsg/slicing/SlicingStats.h>
#include <volsg/slicing/VolumeSlicer.h>
#include <volsg/slicing/VolumeTextures.h>

namespace volsg::slicing {

/// Draws the slices and faces cutBricks left in v.vertices (not empty) as `plan` says: the
/// bricks back to front, each made resident just before its draws (so a budget smaller than
/// the visible bricks streams them), into the frame's target, or for MIP, MINIP and AVERAGE
/// into the projection target composited after. Throws Error beyond kMaxLights lights.
void drawSlices(FrameContext& frame, SliceShared& shared, VolumeTextures& v,
                const RayCastVolume& volume, std::span<const SceneLight> lights,
                const SlicingSettings& settings, const SlicePlan& plan, SlicingStats& drawn);

} // namespace volsg::slicing
