#pragma once
// The level-of-detail part of a paged frame's predicted error: what drawing coarse levels of
// the pyramid instead of finer ones changes in the image, folded with the quadrature's
// prediction into the frame's (lib/volsg/paging/README.md, "The error of a paged frame").
//
// It is measured where the pyramid is held whole: the error model's rays (the view's
// direction) are integrated through the stand-in level s, and again through the frame's cut
// (SlabErrorModel::cutDifference): each sample from the level the frame draws at its point,
// for the levels above the stand-in, and from the stand-in elsewhere. A coarse brick's error
// thus counts as far as rays cross it, and behind what lies in front of it. Where s is level
// 0 (the volume fits the stand-in's bytes) this is the whole level-of-detail error; otherwise
// detail finer than the stand-in is not seen, and the figure is the part of the error the
// levels above the stand-in make. Carrying the coarse levels' differences on to the finer
// levels was tried and rejected: on the chest CT the finer levels differ more than the coarse
// ones (under-predicted 2-5x), and sheets thinner than a stand-in voxel leave nothing to carry
// (the README has the measurements).

#include <vector>

#include <volsg/paging/BrickKey.h>
#include <volsg/slicing/SlabErrorModel.h>
#include <volsg/slicing/SlicingQuality.h>

namespace volsg {

class PagedVolume;

struct LevelOfDetailError {
    double rmse = -1.0;   ///< image RMSE, 0..1 units; < 0: not predicted (tagged volumes)
    int measuredFrom = 0; ///< the stand-in level: 0 means the figure is the whole LOD error
};

/// The LOD error of a frame drawing bricks `drawn` of `paged`, for `view`, on `model` (the
/// error model made on the stand-in).
LevelOfDetailError predictLevelOfDetailError(SlabErrorModel& model, const QualityView& view,
                                             const PagedVolume& paged,
                                             const std::vector<BrickKey>& drawn);

/// The cut of `drawn` over the bricks of level 0 (GridCut's cells): each cell names the grid
/// of the level drawn there when that level is coarser than the stand-in and held whole, and
/// the stand-in (index 0) elsewhere.
GridCut gridCutOf(const PagedVolume& paged, const std::vector<BrickKey>& drawn);

} // namespace volsg
