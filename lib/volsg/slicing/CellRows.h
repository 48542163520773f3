#pragma once
// Empty space left out of the proxy geometry: a brick's part of the volume as rows of empty-
// space cells (EmptyCells) along one axis, each row cut down to the stretch of cells that may
// emit. Slicing only these boxes means the planes make no fragments over the air around a
// body, which on a software rasteriser is what empty space costs (per-sample skipping inside a
// fragment saves little there: its SIMD lanes run both sides of a branch).

#include <vector>

#include <glm/glm.hpp>

#include <volsg/slicing/BrickLayout.h>

namespace volsg {

class EmptyCells;

/// One row's box, in the volume's local coordinates.
struct CellRow {
    glm::dvec3 boxMin{0.0}, boxMax{0.0};
};

class CellRows {
public:
    /// The axis rows run along for a view direction (local coordinates): the one most nearly
    /// perpendicular to it, so that each plane meets as few rows as possible.
    static int axisFor(const glm::dvec3& viewDirection);

    /// Prepares the flags rows are trimmed by: a cell counts when a cell within `reachCells`
    /// of it (along every axis) may emit, so samples taken up to that far from a fragment's
    /// point (a thick slab's parts, MIP's voxel-centre crossings) still find every emitting
    /// cell. 0: the cells' own flags (one sample per fragment, at its point).
    void dilate(const EmptyCells& cells, int reachCells);

    /// The rows of brick `b` along `axis`, trimmed, in back-to-front order for a viewer at
    /// `eyeOrDirection` (local point, perspective; or the viewing direction, orthographic).
    /// `spacing` and `halfExtent` are the grid's (voxel u sits at local u * spacing -
    /// halfExtent). A row is `group` x `group` cells across (fewer, larger rows: less plane
    /// cutting and fewer draws, less air left out). Rows with no cell that counts are left
    /// out; when every cell counts, the one row is the brick's box. `out` is cleared first.
    void rowsOf(const Brick& b, int axis, const glm::dvec3& spacing, const glm::dvec3& halfExtent,
                const glm::dvec3& eyeOrDirection, bool orthographic, int group,
                std::vector<CellRow>& out) const;

private:
    glm::ivec3 cells_{0};
    std::vector<unsigned char> counts_; ///< dilated flags, x fastest
    bool counts(int x, int y, int z) const {
        return counts_[std::size_t(x) +
                       std::size_t(cells_.x) *
                           (std::size_t(y) + std::size_t(cells_.y) * std::size_t(z))] != 0;
    }
    struct Ordered {
        int distance;
        CellRow row;
    };
    mutable std::vector<Ordered> scratch_;
};

} // namespace volsg
