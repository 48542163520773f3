#include <volsg/paging/PagedLayout.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <volsg/core/Error.h>

namespace volsg {

PagedLayout::PagedLayout(std::vector<PagedLevel> levels, glm::dvec3 spacing, int brickCells,
                         int reach)
    : levels_(std::move(levels)), spacing_(spacing), cells_(brickCells), reach_(reach) {
    if (levels_.empty() || cells_ < 1 || reach_ < 0)
        throw Error("a paged volume needs levels and bricks");
}

glm::ivec3 PagedLayout::bricksOf(int l) const {
    const glm::ivec3 n = level(l).dimensions;
    return (n + cells_ - 1) / cells_;
}

bool PagedLayout::contains(const BrickKey& key) const {
    return key.level >= 0 && key.level < levelCount() &&
           glm::all(glm::greaterThanEqual(key.index, glm::ivec3(0))) &&
           glm::all(glm::lessThan(key.index, bricksOf(key.level)));
}

std::vector<BrickKey> PagedLayout::roots() const {
    const int top = levelCount() - 1;
    const glm::ivec3 n = bricksOf(top);
    std::vector<BrickKey> out;
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x)
                out.push_back({top, {x, y, z}});
    return out;
}

glm::dvec2 PagedLayout::span(int l, int a, int k) const {
    const double n0 = levels_.front().dimensions[a];
    const double step = double(cells_) * level(l).scale[a];
    const double lo = k == 0 ? 0.0 : std::min(k * step, n0);
    const double hi = k == bricksOf(l)[a] - 1 ? n0 : std::min((k + 1) * step, n0);
    return {lo, hi};
}

void PagedLayout::box(const BrickKey& key, glm::dvec3& boxMin, glm::dvec3& boxMax) const {
    const glm::dvec3 half = halfExtent();
    for (int a = 0; a < 3; ++a) {
        const glm::dvec2 s = span(key.level, a, key.index[a]);
        boxMin[a] = s.x * spacing_[a] - half[a];
        boxMax[a] = s.y * spacing_[a] - half[a];
    }
}

void PagedLayout::texels(const BrickKey& key, glm::ivec3& first, glm::ivec3& count) const {
    const PagedLevel& lv = level(key.level);
    for (int a = 0; a < 3; ++a) {
        const glm::dvec2 s = span(key.level, a, key.index[a]) / double(lv.scale[a]);
        // Trilinear sampling at u reads the voxels whose centres i + 0.5 lie around it; a
        // sample at u +- reach those `reach` further out. Clamped at the level's faces, as one
        // texture of the level clamps.
        const int lo = std::max(0, int(std::floor(s.x - 0.5)) - reach_);
        const int hi = std::min(lv.dimensions[a] - 1, int(std::floor(s.y - 0.5)) + 1 + reach_);
        first[a] = lo;
        count[a] = std::max(1, hi - lo + 1);
    }
}

std::vector<BrickKey> PagedLayout::children(const BrickKey& key) const {
    std::vector<BrickKey> out;
    if (key.level == 0) return out;
    const int finer = key.level - 1;
    const glm::ivec3 grid = bricksOf(finer);
    glm::ivec3 from, to;
    for (int a = 0; a < 3; ++a) {
        const int f = level(key.level).scale[a] / level(finer).scale[a];
        from[a] = key.index[a] * f;
        to[a] = key.index[a] == bricksOf(key.level)[a] - 1 ? grid[a] - 1
                                                           : std::min(from[a] + f - 1, grid[a] - 1);
    }
    for (int z = from.z; z <= to.z; ++z)
        for (int y = from.y; y <= to.y; ++y)
            for (int x = from.x; x <= to.x; ++x)
                out.push_back({finer, {x, y, z}});
    return out;
}

void PagedLayout::backToFront(std::vector<BrickKey>& keys, const glm::dvec3& eyeOrDirection,
                              bool orthographic) const {
    if (keys.size() < 2) return;
    glm::ivec3 low = keys.front().index, high = low;
    for (const BrickKey& k : keys) {
        low = glm::min(low, k.index);
        high = glm::max(high, k.index);
    }
    const int l = keys.front().level;
    glm::ivec3 viewer(0);
    if (!orthographic) {
        const glm::dvec3 u = (eyeOrDirection + halfExtent()) / spacing_; // level-0 voxels
        for (int a = 0; a < 3; ++a) {
            viewer[a] = low[a];
            for (int k = low[a]; k <= high[a]; ++k)
                if (u[a] >= span(l, a, k).x) viewer[a] = k;
        }
    }
    auto distance = [&](const BrickKey& key) {
        int d = 0;
        for (int a = 0; a < 3; ++a) {
            if (!orthographic)
                d += std::abs(key.index[a] - viewer[a]);
            else if (eyeOrDirection[a] > 0.0)
                d += key.index[a] - low[a];
            else if (eyeOrDirection[a] < 0.0)
                d += high[a] - key.index[a];
        }
        return d;
    };
    std::stable_sort(keys.begin(), keys.end(), [&](const BrickKey& a, const BrickKey& b) {
        return distance(a) > distance(b);
    });
}

} // namespace volsg
