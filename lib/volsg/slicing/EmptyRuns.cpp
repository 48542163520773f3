#include <volsg/slicing/EmptyRuns.h>

#include <algorithm>
#include <cmath>

#include <volsg/slicing/EmptyCells.h>

namespace volsg {

std::vector<glm::dvec2> emptyRunsAlong(const EmptyCellMap& map, const glm::dvec3& origin,
                                       const glm::dvec3& dir, double t0, double t1) {
    std::vector<glm::dvec2> runs;
    if (!map.cells || !(t1 > t0)) return runs;
    constexpr int n = EmptyCells::kCellSize;
    const glm::ivec3 cells = map.cells->cells();
    const std::vector<std::uint8_t>& flags = map.cells->flags();
    if (flags.size() != std::size_t(cells.x) * std::size_t(cells.y) * std::size_t(cells.z))
        return runs;
    const glm::dvec3 u0 = (origin + map.half) / map.spacing - 0.5;
    const glm::dvec3 du = dir / map.spacing;
    // Where u crosses a cell's face (u = n k) inside (t0, t1), per axis.
    std::vector<double> cuts{t0, t1};
    for (int a = 0; a < 3; ++a) {
        if (std::abs(du[a]) < 1e-300) continue;
        for (int k = 1; k < cells[a]; ++k) {
            const double t = (n * k - u0[a]) / du[a];
            if (t > t0 && t < t1) cuts.push_back(t);
        }
    }
    std::sort(cuts.begin(), cuts.end());
    const auto emptyAt = [&](double t) {
        std::size_t index = 0, stride = 1;
        for (int a = 0; a < 3; ++a) {
            const double u = std::clamp(u0[a] + t * du[a], 0.0, double(map.dims[a] - 1));
            const int c = std::clamp(int(u / n), 0, cells[a] - 1);
            index += std::size_t(c) * stride;
            stride *= std::size_t(cells[a]);
        }
        return flags[index] == 0;
    };
    // A hair: far above a sample position's rounding (1e-13 of the box), far below a cell.
    const double hair = 1e-6 * std::min({map.spacing.x, map.spacing.y, map.spacing.z});
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double a = cuts[i], b = cuts[i + 1];
        if (!(b > a) || !emptyAt(0.5 * (a + b))) continue;
        if (!runs.empty() && runs.back().y == a)
            runs.back().y = b;
        else
            runs.push_back({a, b});
    }
    std::erase_if(runs, [&](const glm::dvec2& r) { return r.y - r.x <= 2.0 * hair; });
    for (glm::dvec2& r : runs)
        r += glm::dvec2(hair, -hair);
    return runs;
}

} // namespace volsg
