#include <volsg/slicing/LevelOfDetailError.h>

#include <algorithm>
#include <cmath>

#include <volsg/paging/PagedVolume.h>

namespace volsg {

GridCut gridCutOf(const PagedVolume& paged, const std::vector<BrickKey>& drawn) {
    const PagedLayout& layout = paged.layout();
    const int s = paged.standInLevel();
    GridCut cut;
    cut.cells = layout.bricksOf(0);
    cut.cellSize = glm::dvec3(layout.brickCells()) * layout.spacing();
    cut.boxMin = -layout.halfExtent();
    cut.cellGrid.assign(
        std::size_t(cut.cells.x) * std::size_t(cut.cells.y) * std::size_t(cut.cells.z), 0);
    cut.grids.push_back(nullptr); // the stand-in
    std::vector<int> gridOfLevel(std::size_t(layout.levelCount()), 0);
    for (int level = s + 1; level < layout.levelCount(); ++level)
        if (const VolumeGrid* grid = paged.keptWhole(level)) {
            gridOfLevel[std::size_t(level)] = int(cut.grids.size());
            cut.grids.push_back(grid);
        }
    std::uint64_t key = 0xcbf29ce484222325ULL;
    for (const BrickKey& brick : drawn) {
        key = (key ^ std::uint64_t(brick.level)) * 0x100000001b3ULL;
        for (int a = 0; a < 3; ++a)
            key = (key ^ std::uint64_t(std::uint32_t(brick.index[a]))) * 0x100000001b3ULL;
        const int grid = gridOfLevel[std::size_t(brick.level)];
        if (grid == 0) continue;
        // The level-0 bricks whose centres lie in this brick's region.
        glm::dvec3 lo, hi;
        layout.box(brick, lo, hi);
        const glm::ivec3 first =
            glm::clamp(glm::ivec3(glm::ceil((lo - cut.boxMin) / cut.cellSize - 0.5)), glm::ivec3(0),
                       cut.cells);
        const glm::ivec3 last =
            glm::clamp(glm::ivec3(glm::ceil((hi - cut.boxMin) / cut.cellSize - 0.5)), glm::ivec3(0),
                       cut.cells);
        for (int z = first.z; z < last.z; ++z)
            for (int y = first.y; y < last.y; ++y)
                for (int x = first.x; x < last.x; ++x)
                    cut.cellGrid[cut.indexOf({x, y, z})] = std::uint8_t(grid);
    }
    cut.key = key;
    return cut;
}

LevelOfDetailError predictLevelOfDetailError(SlabErrorModel& model, const QualityView& view,
                                             const PagedVolume& paged,
                                             const std::vector<BrickKey>& drawn) {
    LevelOfDetailError out;
    out.measuredFrom = paged.standInLevel();
    if (model.tagged()) return out;
    // A converged frame usually draws nothing coarser than the stand-in: no cut to make.
    const bool coarse = std::any_of(drawn.begin(), drawn.end(), [&](const BrickKey& b) {
        return b.level > out.measuredFrom && paged.keptWhole(b.level);
    });
    out.rmse = 0.0;
    if (!coarse) return out;
    const int dir = directionsOf(view, model.mode()).dir[0];
    out.rmse = std::sqrt(std::clamp(view.coverage, 0.0, 1.0)) *
               model.cutDifference(dir, gridCutOf(paged, drawn));
    return out;
}

} // namespace volsg
