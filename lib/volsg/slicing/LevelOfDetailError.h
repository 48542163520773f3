#pragma once
// The level-of-detail part of a paged frame's predicted error: what drawing coarse levels of
// the pyramid instead of finer ones changes in the image, folded with the quadrature's
// prediction into the frame's (lib/volsg/paging/README.md, "The error of a paged frame").
//
// It is measured where the pyramid is held whole: the error model's rays (the view's
// direction, SlabErrorModel::levelDifference) integrated through the stand-in level s and
// through each coarser level the frame draws. For a level L >= s that is the error of drawing
// L instead of s, quadrature aside; the frame's figure is the root of those squared errors
// weighted by each level's share of the drawn region. Where s is level 0 (the volume fits the
// stand-in's bytes) it is the whole level-of-detail error. Otherwise detail finer than the
// stand-in is not seen: bricks finer than s count 0, and the figure is the part of the error
// that the levels from s up make. Carrying the coarse levels' differences on to the finer
// levels was tried and rejected: on the chest CT the finer levels differ more than the coarse
// ones (under-predicted 2-5x), and sheets thinner than a stand-in voxel leave nothing to carry
// (the README has the measurements).

#include <vector>

#include <volsg/slicing/SlabErrorModel.h>
#include <volsg/slicing/SlicingQuality.h>

namespace volsg {

class PagedVolume;

struct LevelOfDetailError {
    double rmse = -1.0;   ///< image RMSE, 0..1 units; < 0: not predicted (tagged volumes)
    int measuredFrom = 0; ///< the stand-in level: 0 means the figure is the whole LOD error
};

/// The LOD error of a frame drawing `levelShares` (per level, share of the drawn region) of
/// `paged`, for `view`, on `model` (the error model made on the stand-in).
LevelOfDetailError predictLevelOfDetailError(SlabErrorModel& model, const QualityView& view,
                                             const PagedVolume& paged,
                                             const std::vector<double>& levelShares);

} // namespace volsg
