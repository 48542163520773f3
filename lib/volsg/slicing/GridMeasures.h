#pragma once
// What the slicer measures of a grid before it draws it: the finite data range, each brick's
// data and tag range (empty bricks are neither uploaded nor drawn) and the empty cells. Taken
// on the GL thread when a grid is first drawn, or ahead of time on the staging thread while
// the previous time step is on screen (TextureStaging.h), so a step change does not pay for it.

#include <vector>

#include <volsg/slicing/BrickLayout.h>
#include <volsg/slicing/EmptyCells.h>

namespace volsg {

class VolumeGrid;

/// One brick's voxels: data range (non-finite values replaced as the textures hold them) and
/// tag range (0, 0 without tags).
struct BrickRange {
    double dataMin = 0.0, dataMax = 0.0;
    int tagMin = 0, tagMax = 0;
};

/// The ranges of every brick of `layout`; `lowest`, `highest`: the grid's finite range (so a
/// single brick holding the whole grid without labels has it without a pass over the voxels).
std::vector<BrickRange> measureBrickRanges(const VolumeGrid& data, const VolumeGrid* tags,
                                           const BrickLayout& layout, double lowest,
                                           double highest);

/// All of it for one grid and layout, as the staging thread takes it.
struct GridMeasures {
    double finiteMin = 0.0, finiteMax = 0.0;
    std::vector<Brick> bricks; ///< the layout's bricks the ranges belong to
    std::vector<BrickRange> ranges;
    EmptyCells cells;

    static GridMeasures of(const VolumeGrid& data, const VolumeGrid* tags,
                           const BrickLayout& layout);
    /// Whether the ranges are of exactly these bricks.
    bool sameBricks(const BrickLayout& layout) const;
};

} // namespace volsg
