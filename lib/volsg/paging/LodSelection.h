#pragma once
// Which bricks of a pyramid a frame draws: refined by screen-space error where their finer
// bricks are at hand, in an order that composites correctly (issue 26, part 2).

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/paging/PagedLayout.h>

namespace volsg {

/// The camera as the selection sees it.
struct LodView {
    glm::dmat4 modelView{1.0}; ///< local to eye
    glm::dmat4 projection{1.0};
    int viewportHeight = 512; ///< pixels
    bool orthographic = false;
};

/// What the selection may use and must respect.
struct LodRequest {
    /// A brick is fine enough when one of its voxels projects to at most this many pixels.
    double pixelBudget = 1.0;
    /// Bytes the drawn bricks' textures may take together (0: no limit).
    std::uint64_t textureBudget = 0;
    /// Whether the brick's voxels can be drawn this frame (uploaded, or held in host memory).
    std::function<bool(const BrickKey&)> available;
    /// The texture bytes of a brick.
    std::function<std::uint64_t(const BrickKey&)> bytes;
    /// Only bricks meeting this local box can show anything (a BoxClip that removes the rest);
    /// the others are left out as if outside the view. Empty (min > max): the whole volume.
    glm::dvec3 regionMin{1.0}, regionMax{-1.0};
};

/// One frame's choice.
struct LodSelection {
    std::vector<BrickKey> drawn;  ///< back to front
    std::vector<BrickKey> wanted; ///< missing finer bricks, coarse levels first, then nearest
    /// The bricks replaced by their children: the fallback should a child go, so a cache keeps
    /// them as it keeps the drawn ones.
    std::vector<BrickKey> refined;
    /// Drawn bricks coarser than the pixel budget asks (level > 0 and voxels above it).
    int coarser = 0;
    double worstPixels = 0.0;   ///< the largest projected voxel of the drawn bricks (pixels)
    bool budgetLimited = false; ///< the texture budget stopped a refinement
    std::uint64_t bytes = 0;    ///< texture bytes of the drawn bricks
    int culled = 0;             ///< bricks left out as outside the view
    /// Nothing more to load: the image is as fine as the pixel and texture budgets allow.
    bool converged() const { return wanted.empty(); }
};

/// The projected size in pixels of one voxel of brick `key` seen from `view`, where its region
/// is nearest the eye (infinite when the eye is inside it: refine as far as there are levels).
double projectedVoxelPixels(const PagedLayout& layout, const BrickKey& key, const LodView& view);

/// Refines from the coarsest level, largest projected voxels first: a brick above the pixel
/// budget is replaced by its children (those inside the view frustum) when all of them are
/// available and their textures fit the budget beside those of the bricks drawn and refined
/// (kept as fallbacks); its missing children are wanted. The coarsest
/// level's bricks are drawn when available and wanted otherwise.
LodSelection selectBricks(const PagedLayout& layout, const LodView& view,
                          const LodRequest& request);

} // namespace volsg
