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
                      bool orthographic, std::vector<CellRow>& out) const {
    out.clear();
    if (counts_.empty()) return;
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
    // Along s and t the rows are a grid of boxes; ordering it as bricks are ordered (the sum
    // of per-axis distances from the viewer's row, BrickLayout::backToFront) is a visibility
    // order, and cutting rows short along `axis` keeps it one.
    auto distanceAlong = [&](int a, int k) {
        if (!orthographic) return std::abs(k - eye[a]);
        if (eyeOrDirection[a] > 0.0) return k - first[a];
        if (eyeOrDirection[a] < 0.0) return last[a] - k;
        return 0;
    };
    scratch_.clear();
    glm::ivec3 c(0);
    for (int ct = first[t]; ct <= last[t]; ++ct)
        for (int cs = first[s]; cs <= last[s]; ++cs) {
            c[s] = cs;
            c[t] = ct;
            int from = -1, to = -1;
            for (int k = first[axis]; k <= last[axis]; ++k) {
                c[axis] = k;
                if (!counts(c.x, c.y, c.z)) continue;
                if (from < 0) from = k;
                to = k;
            }
            if (from < 0) continue;
            glm::dvec3 lo(0.0), hi(0.0);
            lo[s] = std::max(double(cs * C), uLo[s]);
            hi[s] = std::min(double((cs + 1) * C), uHi[s]);
            lo[t] = std::max(double(ct * C), uLo[t]);
            hi[t] = std::min(double((ct + 1) * C), uHi[t]);
            lo[axis] = std::max(double(from * C), uLo[axis]);
            hi[axis] = std::min(double((to + 1) * C), uHi[axis]);
            if (!(hi[s] > lo[s] && hi[t] > lo[t] && hi[axis] > lo[axis])) continue;
            CellRow row;
            row.boxMin = lo * spacing - halfExtent;
            row.boxMax = hi * spacing - halfExtent;
            scratch_.push_back({distanceAlong(s, cs) + distanceAlong(t, ct), row});
        }
    // Farthest first; rows at the same distance do not overlap along any ray between them.
    std::stable_sort(scratch_.begin(), scratch_.end(),
                     [](const Ordered& a, const Ordered& b) { return a.distance > b.distance; });
    for (const Ordered& o : scratch_)
        out.push_back(o.row);
}

} // namespace volsg
