#include <volsg/slicing/CellRows.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <volsg/slicing/EmptyCells.h>

namespace volsg {

int CellRows::axisFor(const glm::dvec3& d) {
    int axis = 0;
    for (int a = 1; a < 3; ++a)
        if (std::abs(d[a]) < std::abs(d[axis])) axis = a;
    return axis;
}

void CellRows::dilate(const EmptyCells& cells, int reachCells) {
    cells_ = cells.cells();
    counts_.assign(cells.flags().begin(), cells.flags().end());
    if (reachCells <= 0) return;
    // A separable maximum filter of radius reachCells along x, then y, then z.
    std::vector<unsigned char> line;
    const glm::ivec3 n = cells_;
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, w = (axis + 2) % 3;
        line.resize(std::size_t(n[axis]));
        for (int j = 0; j < n[w]; ++j)
            for (int i = 0; i < n[u]; ++i) {
                glm::ivec3 c(0);
                c[u] = i;
                c[w] = j;
                auto at = [&](int k) -> unsigned char& {
                    c[axis] = k;
                    return counts_[std::size_t(c.x) +
                                   std::size_t(n.x) *
                                       (std::size_t(c.y) + std::size_t(n.y) * std::size_t(c.z))];
                };
                for (int k = 0; k < n[axis]; ++k)
                    line[std::size_t(k)] = at(k);
                for (int k = 0; k < n[axis]; ++k) {
                    unsigned char any = 0;
                    for (int d = std::max(0, k - reachCells);
                         d <= std::min(n[axis] - 1, k + reachCells) && !any; ++d)
                        any = line[std::size_t(d)];
                    at(k) = any;
                }
            }
    }
}

void CellRows::rowsOf(const Brick& b, int axis, const glm::dvec3& spacing,
                      const glm::dvec3& halfExtent, const glm::dvec3& eyeOrDirection,
                      bool orthographic, int group, std::vector<CellRow>& out) const {
    out.clear();
    if (counts_.empty()) return;
    group = std::max(group, 1);
    constexpr int C = EmptyCells::kCellSize;
    const glm::dvec3 uLo = (b.boxMin + halfExtent) / spacing;
    const glm::dvec3 uHi = (b.boxMax + halfExtent) / spacing;
    glm::ivec3 first(0), last(0), eye(0);
    for (int a = 0; a < 3; ++a) {
        first[a] = std::clamp(int(std::floor(uLo[a] / C)), 0, cells_[a] - 1);
        last[a] = std::clamp(int(std::ceil(uHi[a] / C)) - 1, first[a], cells_[a] - 1);
        if (!orthographic) {
            const double u = (eyeOrDirection[a] + halfExtent[a]) / spacing[a];
            eye[a] = int(std::clamp(std::floor(u / C), double(first[a]), double(last[a])));
        }
    }
    const int s = (axis + 1) % 3, t = (axis + 2) % 3;
    // Along s and t the rows are a grid of boxes (of group x group cells); ordering it as
    // bricks are ordered (the sum of per-axis distances from the viewer's row,
    // BrickLayout::backToFront) is a visibility order, and cutting rows short along `axis`
    // keeps it one.
    auto groupOf = [&](int a, int cell) { return (cell - first[a]) / group; };
    auto distanceAlong = [&](int a, int k) {
        if (!orthographic) return std::abs(k - groupOf(a, eye[a]));
        if (eyeOrDirection[a] > 0.0) return k;
        if (eyeOrDirection[a] < 0.0) return groupOf(a, last[a]) - k;
        return 0;
    };
    scratch_.clear();
    bool whole = true; // every row full: the brick's own box says the same with one box
    glm::ivec3 c(0);
    for (int gt = 0; gt <= groupOf(t, last[t]); ++gt)
        for (int gs = 0; gs <= groupOf(s, last[s]); ++gs) {
            const int s0 = first[s] + gs * group, s1 = std::min(s0 + group - 1, last[s]);
            const int t0 = first[t] + gt * group, t1 = std::min(t0 + group - 1, last[t]);
            int from = -1, to = -1;
            for (c[t] = t0; c[t] <= t1; ++c[t])
                for (c[s] = s0; c[s] <= s1; ++c[s])
                    for (int k = first[axis]; k <= last[axis]; ++k) {
                        c[axis] = k;
                        if (!counts(c.x, c.y, c.z)) {
                            whole = false;
                            continue;
                        }
                        if (from < 0 || k < from) from = k;
                        to = std::max(to, k);
                    }
            if (from < 0) continue;
            glm::dvec3 lo(0.0), hi(0.0);
            lo[s] = std::max(double(s0 * C), uLo[s]);
            hi[s] = std::min(double((s1 + 1) * C), uHi[s]);
            lo[t] = std::max(double(t0 * C), uLo[t]);
            hi[t] = std::min(double((t1 + 1) * C), uHi[t]);
            lo[axis] = std::max(double(from * C), uLo[axis]);
            hi[axis] = std::min(double((to + 1) * C), uHi[axis]);
            if (!(hi[s] > lo[s] && hi[t] > lo[t] && hi[axis] > lo[axis])) continue;
            CellRow row;
            row.boxMin = lo * spacing - halfExtent;
            row.boxMax = hi * spacing - halfExtent;
            scratch_.push_back({distanceAlong(s, gs) + distanceAlong(t, gt), row});
        }
    if (whole) {
        CellRow row;
        row.boxMin = b.boxMin;
        row.boxMax = b.boxMax;
        out.push_back(row);
        return;
    }
    // Farthest first; rows at the same distance do not overlap along any ray between them.
    std::stable_sort(scratch_.begin(), scratch_.end(),
                     [](const Ordered& a, const Ordered& b) { return a.distance > b.distance; });
    for (const Ordered& o : scratch_)
        out.push_back(o.row);
}

} // namespace volsg
