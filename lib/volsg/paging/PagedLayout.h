#pragma once
// The brick octree over the levels of a pyramid: which level-0 region each brick draws and
// which voxels of its level its texture holds.

#include <vector>

#include <glm/glm.hpp>

#include <volsg/paging/BrickKey.h>

namespace volsg {

/// One level of the pyramid as the brick octree needs it.
struct PagedLevel {
    glm::ivec3 dimensions{1};
    /// Level-0 voxels per voxel of this level along x, y, z (PyramidSourceLevel::scale).
    glm::ivec3 scale{1};
};

/// The bricks of every level of a pyramid, nested as an octree.
///
/// Brick k of level l (along an axis with level-0 length N and scale S) draws level-0 voxel
/// coordinates u in [k n S, (k + 1) n S] (u = 0 and u = N the box faces; the last brick ends at
/// N), n = `brickCells`. Since every level halves each axis or keeps it, brick k's children
/// on level l - 1 are bricks k f .. k f + f - 1 (f = 2 where the axis halves, else 1; the last
/// brick takes the rest of the finer level), whose regions tile its region exactly. Its
/// texture holds the level's voxels that trilinear sampling of its region reads: the voxel
/// centres around it, one guard voxel beyond each inner face, so neighbouring bricks of a level
/// sample the same voxels at their seam; and `reach` voxels more on each side, for drawing
/// that samples around its points (lighting's central differences, one voxel either side).
///
/// A level-l voxel's centre is at u = (i + 0.5) S: the halving writers put a coarse voxel at
/// the mean of the centres of the finer voxels it reduces.
class PagedLayout {
public:
    PagedLayout() = default;
    /// `levels[0]` the finest; `spacing` level 0's voxel size (local units); `reach` the
    /// voxels a texture holds beyond those trilinear sampling of its region reads, each side.
    PagedLayout(std::vector<PagedLevel> levels, glm::dvec3 spacing, int brickCells, int reach = 0);

    int levelCount() const { return int(levels_.size()); }
    const PagedLevel& level(int l) const { return levels_[std::size_t(l)]; }
    int brickCells() const { return cells_; }
    int reach() const { return reach_; }
    glm::dvec3 spacing() const { return spacing_; } ///< level 0's
    glm::dvec3 halfExtent() const {
        return 0.5 * glm::dvec3(levels_.front().dimensions) * spacing_;
    }
    /// A level's voxel size in local units (level 0's times its scale).
    glm::dvec3 spacingOf(int level) const {
        return spacing_ * glm::dvec3(this->level(level).scale);
    }

    glm::ivec3 bricksOf(int level) const; ///< the level's brick grid
    bool contains(const BrickKey& key) const;
    std::vector<BrickKey> roots() const; ///< the bricks of the coarsest level

    /// The region brick `key` draws, in local coordinates (the box [-halfExtent, halfExtent]).
    void box(const BrickKey& key, glm::dvec3& boxMin, glm::dvec3& boxMax) const;
    /// The voxels of its level its texture holds: first index and count.
    void texels(const BrickKey& key, glm::ivec3& first, glm::ivec3& count) const;
    /// Its children on the finer level (none on level 0).
    std::vector<BrickKey> children(const BrickKey& key) const;

    /// Orders `keys` (a grid of bricks of one level, such as a brick's children or the roots)
    /// back to front for a viewer at `eyeOrDirection` (local; the viewing direction when
    /// orthographic): each brick-grid index moves away from the viewer's slab along a ray, so
    /// the sum of those distances is a visibility order (BrickLayout::backToFront).
    void backToFront(std::vector<BrickKey>& keys, const glm::dvec3& eyeOrDirection,
                     bool orthographic) const;

private:
    /// Level-0 voxel coordinates of brick k's region along axis a of level l.
    glm::dvec2 span(int level, int a, int k) const;

    std::vector<PagedLevel> levels_;
    glm::dvec3 spacing_{1.0};
    int cells_ = 64;
    int reach_ = 0;
};

} // namespace volsg
