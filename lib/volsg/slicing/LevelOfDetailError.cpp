#include <volsg/slicing/LevelOfDetailError.h>

#include <algorithm>
#include <cmath>

#include <volsg/paging/PagedVolume.h>

namespace volsg {

LevelOfDetailError predictLevelOfDetailError(SlabErrorModel& model, const QualityView& view,
                                             const PagedVolume& paged,
                                             const std::vector<double>& levelShares) {
    LevelOfDetailError out;
    const int s = paged.standInLevel();
    out.measuredFrom = s;
    if (model.tagged()) return out;
    const int dir = SlabErrorModel::nearestDirection(view.localDirection, view.coneTangent > 0.2);
    double sum = 0.0;
    for (int level = s + 1; level < int(levelShares.size()); ++level) {
        const double share = levelShares[std::size_t(level)];
        const VolumeGrid* grid = paged.keptWhole(level);
        if (!(share > 0.0) || !grid) continue;
        const double error = model.levelDifference(dir, s, nullptr, level, grid);
        sum += share * error * error;
    }
    out.rmse = std::sqrt(std::clamp(view.coverage, 0.0, 1.0)) * std::sqrt(sum);
    return out;
}

} // namespace volsg
