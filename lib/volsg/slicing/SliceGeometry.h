#pragma once
// The Volume slicer's geometry of a frame: view, plane layout, clip planes, brick slices.

#include <vector>

#include <glm/glm.hpp>

#include <volsg/render/FrameContext.h>
#include <volsg/slicing/SlicePlan.h>
#include <volsg/slicing/SlicingQuality.h>
#include <volsg/slicing/SlicingStats.h>
#include <volsg/slicing/VolumeSlicer.h>
#include <volsg/slicing/VolumeTextures.h>

namespace volsg::slicing {

/// The view of `frame` in the local coordinates of a volume with this model matrix and grid.
LocalView localView(const RenderView& view, const glm::dmat4& model, const VolumeGrid& grid);

/// The view as the error model sees it: the view axis and the box's depth along it in L0, the
/// share of pixels whose rays cross the box (a 24 x 24 grid of pixel rays) and how much longer
/// than the view depth they run through a slab (perspective).
QualityView qualityView(const LocalView& local, const RenderView& view);

/// The planes over the volume box's depth range: numPlanes, or settings.planeSpacingL0 (chosen
/// from an error target), or 2 per voxel along the view axis (fewer with several samples per
/// plane); while interacting interactivePlanes, or the spacing chosen for the interactive
/// target, or a quarter; scaled by the viewer.
PlaneLayout planeLayout(const LocalView& local, const SlicingSettings& settings, int slabSamples,
                        const FrameContext& frame);

/// The volume's clip planes in its local coordinates; throws Error beyond kMaxClipPlanes.
std::vector<glm::dvec4> localClipPlanes(const RayCastVolume& volume);

/// The rows of empty-space cells the bricks are cut into (none when cells are not skipped, a
/// fragment takes more than kMaxRowSamples samples, or a slab reaches too far), with the cell
/// flags dilated for them.
RowPlan planRows(VolumeTextures& v, const SlicePlan& plan, const SlicingSettings& settings);

/// Orders the bricks back to front and cuts those that can contribute into v.vertices: their
/// slices (whole, or row by row), then the faces that bound the visible part (front faces on
/// the volume box, entered clip planes). Fills each BrickState's ranges of vertices.
void cutBricks(VolumeTextures& v, const VolumeGrid& grid, const SlicePlan& plan,
               SlicingStats& drawn);

} // namespace volsg::slicing
