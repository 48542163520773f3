#pragma once
// Empty-space skipping inside a brick: the volume in cells of kCellSize^3 voxels, each with the
// range of the data (and tags) that a trilinear sample inside it can read, and per transfer
// table one flag per cell: may it emit? (DVR: their optical depth is zero; MIP: their value is
// below every value the table shows.) The slicer leaves rows of cells that cannot out of its
// geometry (CellRows), and a fragment that takes one sample discards itself in such a cell. So a
// volume that fits one texture skips its air as a bricked one skips its empty bricks, at the
// cost of one small integer texture. (Fragments with several samples do not test each one: on
// llvmpipe that cost more than the masked samples saved; the lean slab loop only steps over
// the empty cells at a slab's two ends, a cell per fetch; lib/volsg/slicing/README.md.)

#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace volsg {

class TransferTable;
class VolumeGrid;

class EmptyCells {
public:
    static constexpr int kCellSize = 8; ///< voxels per cell along each axis

    /// Measures the cells of a grid (once per grid): per cell the data range (NaN and -Inf
    /// counted as `lowest`, +Inf as `highest`, as the textures hold them) and the tag range of
    /// its voxels and of the one voxel layer around it, which trilinear samples in the cell
    /// also read.
    void measure(const VolumeGrid& data, const VolumeGrid* tags, double lowest, double highest);
    bool measured() const { return !dataMin_.empty(); }

    /// One byte per cell, x fastest. DVR (`maximum` false): 1 where the table may give the
    /// cell's data some opacity. MIP (`maximum` true, untagged): 1 unless the table is
    /// transparent from the lowest value up to the cell's largest, so that a skipped sample is
    /// below every sample the table shows and cannot be the maximum that matters. `padV`
    /// (DVR): each cell's v interval widened by this much each way (TransferTable::mayEmit),
    /// for a table whose filtered lookups read entries beyond a value.
    void classify(const TransferTable& table, bool tagged, bool maximum = false, double padV = 0.0);
    const std::vector<std::uint8_t>& flags() const { return flags_; }
    glm::ivec3 cells() const { return cells_; }
    /// Cell i's (min, max) data as measured (x fastest).
    glm::dvec2 dataRange(std::size_t cell) const { return {dataMin_[cell], dataMax_[cell]}; }
    /// The smallest and largest of all cells (0, 0 for an empty grid): the grid's range.
    std::pair<double, double> overallRange() const;
    /// The share of cells that cannot emit under the last classify().
    double emptyFraction() const { return emptyFraction_; }

private:
    glm::ivec3 cells_{0};
    std::vector<double> dataMin_, dataMax_;
    std::vector<int> tagMin_, tagMax_;
    std::vector<std::uint8_t> flags_;
    double emptyFraction_ = 0.0;
};

} // namespace volsg
