#pragma once
// How a volume is split into 3D textures (bricks) that fit a texture budget, and the order in
// which they are drawn back to front.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace volsg {

/// One brick: the voxels its texture holds and the part of the volume box it draws.
struct Brick {
    glm::ivec3 index{0};      ///< position in the brick grid
    glm::ivec3 firstVoxel{0}; ///< voxel index of the texture's texel (0, 0, 0)
    glm::ivec3 voxelCount{1}; ///< texture size in texels
    glm::dvec3 boxMin{0.0};   ///< the region it draws, in the volume's local coordinates
    glm::dvec3 boxMax{0.0};
    /// A paged volume's brick (PagedBricks.h): its level's voxel size and dimensions, which
    /// map the volume box to that level's voxels; 0: the volume's own.
    glm::dvec3 levelSpacing{0.0};
    glm::ivec3 levelDimensions{0};
    std::size_t texels() const {
        return std::size_t(voxelCount.x) * std::size_t(voxelCount.y) * std::size_t(voxelCount.z);
    }
};

/// Splits a volume of `dimensions` voxels into bricks.
///
/// Voxel i's centre is at voxel coordinate u = i + 0.5 (u = 0 and u = N are the box faces).
/// Along an axis with bricks of n cells, brick k draws u in [k n + 0.5, (k+1) n + 0.5] (from the
/// face u = 0 for the first brick and to u = N for the last) and its texture holds voxels
/// k n .. (k+1) n: neighbouring bricks share one voxel layer, so trilinear interpolation sees
/// the same eight voxels on both sides of a seam and bricked images equal unbricked ones.
/// `guard` extra voxels on each inner side (1 with lighting) keep central differences exact
/// across seams too. A volume that fits whole is one brick holding every voxel.
///
/// The volume is bricked when its texture would exceed `budgetBytes` (0: no limit) or
/// `maxTextureSize` along an axis. Bricks are halved along their longest texture axis until
/// one fits; a budget smaller than the smallest brick (1 cell a side, or 1/16 of the axis,
/// whichever is larger) gives that brick, and `fitsBudget()` is false.
class BrickLayout {
public:
    struct Limits {
        std::uint64_t budgetBytes = 0; ///< bytes one brick's textures may take; 0 = no limit
        int maxTextureSize = 2048;     ///< GL_MAX_3D_TEXTURE_SIZE
        std::size_t bytesPerVoxel = 1; ///< data texel plus tag texel
        int guard = 0;                 ///< extra voxels beyond each inner seam
    };

    BrickLayout() = default;
    BrickLayout(glm::ivec3 dimensions, glm::dvec3 spacing, const Limits& limits);
    /// Bricks chosen elsewhere (a paged volume's, PagedBricks.h), drawn in the order the
    /// chooser gives (explicitBricks()): backToFront() is not theirs to decide.
    static BrickLayout fromBricks(std::vector<Brick> bricks, glm::ivec3 dimensions,
                                  glm::dvec3 spacing, std::size_t bytesPerVoxel);
    bool explicitBricks() const { return explicit_; }

    const std::vector<Brick>& bricks() const { return bricks_; }
    glm::ivec3 grid() const { return grid_; }              ///< bricks along x, y, z
    glm::ivec3 cellsPerBrick() const { return cells_; }    ///< n along x, y, z
    glm::ivec3 largestTexture() const { return largest_; } ///< texels of the largest brick
    std::size_t bytesPerVoxel() const { return bytesPerVoxel_; }
    /// Bytes of a brick's textures.
    std::size_t bytes(const Brick& b) const { return b.texels() * bytesPerVoxel_; }
    /// Whether the largest brick fits the budget (false only for an impossibly small one).
    bool fitsBudget() const { return fitsBudget_; }

    /// Brick indices in back-to-front order for a viewer at `eye` (perspective) or looking
    /// along `direction` (orthographic), both in the volume's local coordinates. Along a ray
    /// from the viewer, each brick-grid index moves monotonically away from the viewer's brick
    /// slab, so the sum of those distances grows brick by brick: sorting by it, largest first,
    /// is a visibility order for any view. Fills `order` (reused).
    void backToFront(const glm::dvec3& eyeOrDirection, bool orthographic,
                     std::vector<int>& order) const;

private:
    glm::ivec3 dims_{1};
    glm::dvec3 spacing_{1.0};
    glm::ivec3 grid_{1};
    glm::ivec3 cells_{1};
    glm::ivec3 largest_{1};
    std::size_t bytesPerVoxel_ = 1;
    bool fitsBudget_ = true;
    bool explicit_ = false;
    std::vector<Brick> bricks_;
    mutable std::vector<std::pair<int, int>> sortScratch_;
};

} // namespace volsg
