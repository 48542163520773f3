#pragma once
// What paging did for one frame of a paged volume: the level-of-detail part of the frame's
// error, residency and I/O. The viewer's panel and volsg-bench print it.

#include <cstdint>
#include <string>

namespace volsg {

struct PagingStats {
    bool paged = false; ///< the volume is drawn from its pyramid (the rest is meaningless else)
    int levels = 0;
    int bricksDrawn = 0;
    int finestLevel = 0, coarsestLevel = 0; ///< of the drawn bricks
    /// The level-of-detail part of the error, reported apart from the quadrature model's
    /// prediction (which is made on the stand-in level): the largest projected voxel of the
    /// drawn bricks, in pixels, against the budget, and how many drawn bricks are coarser than
    /// the budget asks.
    double worstVoxelPixels = 0.0;
    double pixelBudget = 1.0;
    int coarserBricks = 0;
    bool budgetLimited = false;    ///< the texture budget, not I/O, keeps bricks coarse
    int wanted = 0;                ///< finer bricks this frame asked for
    bool converged = false;        ///< nothing wanted: as fine as the budgets allow
    double finestDrawnVoxel = 0.0; ///< smallest voxel edge of the drawn bricks (local units)
    /// The level-of-detail part of the predicted error (lib/volsg/slicing/LevelOfDetailError.h):
    /// the image RMSE, 0..1 units, of drawing the levels coarser than the stand-in where the
    /// frame does instead of it; the whole LOD error when measuredFrom is 0, else without
    /// detail finer than the stand-in. < 0 when not predicted (no error target, tagged volumes).
    double lodRmse = -1.0;
    int measuredFrom = 0; ///< the stand-in level the differences were measured against
    // Memory now.
    std::uint64_t hostBytes = 0, hostBudget = 0;
    std::uint64_t textureBytes = 0, textureBudget = 0;
    int hostBricks = 0, textureBricks = 0, loading = 0, queued = 0;
    // Cumulative.
    std::uint64_t bricksLoaded = 0, bytesLoaded = 0, hostEvictions = 0, loadFailures = 0;
    std::uint64_t textureUploads = 0, textureEvictions = 0;
    double loadMilliseconds = 0.0; ///< summed over the loader threads
    std::string firstError;        ///< of a brick that could not be read
};

} // namespace volsg
