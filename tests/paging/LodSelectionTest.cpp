// The brick octree and the per-frame selection: children tile their parent, textures hold
// what trilinear sampling reads, refinement follows the pixel budget and what is available,
// and the drawn bricks come back to front along every ray.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include <volsg/paging/LodSelection.h>

using namespace volsg;

namespace {

/// Level 0 of 37 x 20 x 45 voxels (spacing 0.5, 1, 0.75), halving each axis down to 1 brick of 8.
PagedLayout oddLayout() {
    std::vector<PagedLevel> levels{{{37, 20, 45}, {1, 1, 1}}};
    while (glm::any(glm::greaterThan(levels.back().dimensions, glm::ivec3(8)))) {
        PagedLevel next = levels.back();
        for (int a = 0; a < 3; ++a)
            if (next.dimensions[a] > 1) {
                next.dimensions[a] = (next.dimensions[a] + 1) / 2;
                next.scale[a] *= 2;
            }
        levels.push_back(next);
    }
    return PagedLayout(levels, {0.5, 1.0, 0.75}, 8);
}

double volumeOf(const PagedLayout& layout, const BrickKey& key) {
    glm::dvec3 lo, hi;
    layout.box(key, lo, hi);
    return (hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z);
}

LodView viewFrom(glm::dvec3 eye, int height = 200) {
    LodView view;
    view.modelView = glm::lookAt(eye, glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
    view.projection = glm::perspective(glm::radians(45.0), 1.0, 0.1, 1000.0);
    view.viewportHeight = height;
    return view;
}

/// Entry distance of the ray into the box, or -1 when it misses.
double entry(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& lo, const glm::dvec3& hi) {
    double t0 = 0.0, t1 = 1e300;
    for (int a = 0; a < 3; ++a) {
        const double inv = 1.0 / d[a];
        double ta = (lo[a] - o[a]) * inv, tb = (hi[a] - o[a]) * inv;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    return t0 < t1 - 1e-9 ? t0 : -1.0;
}

} // namespace

TEST_CASE("each brick's children tile its region, and each level tiles the volume box") {
    const PagedLayout layout = oddLayout();
    REQUIRE(layout.levelCount() == 4);
    const glm::dvec3 half = layout.halfExtent();
    const double whole = 8.0 * half.x * half.y * half.z;
    for (int l = 0; l < layout.levelCount(); ++l) {
        double sum = 0.0;
        const glm::ivec3 n = layout.bricksOf(l);
        for (int z = 0; z < n.z; ++z)
            for (int y = 0; y < n.y; ++y)
                for (int x = 0; x < n.x; ++x) {
                    const BrickKey key{l, {x, y, z}};
                    sum += volumeOf(layout, key);
                    if (l == 0) continue;
                    double children = 0.0;
                    glm::dvec3 lo, hi;
                    layout.box(key, lo, hi);
                    for (const BrickKey& c : layout.children(key)) {
                        REQUIRE(layout.contains(c));
                        glm::dvec3 clo, chi;
                        layout.box(c, clo, chi);
                        CHECK(glm::all(glm::greaterThanEqual(clo, lo - 1e-12)));
                        CHECK(glm::all(glm::lessThanEqual(chi, hi + 1e-12)));
                        children += volumeOf(layout, c);
                    }
                    CHECK(children == doctest::Approx(volumeOf(layout, key)).epsilon(1e-12));
                }
        CHECK(sum == doctest::Approx(whole).epsilon(1e-12));
    }
}

TEST_CASE("a brick's texture holds the voxels trilinear sampling of its region reads") {
    const PagedLayout layout = oddLayout();
    for (int l = 0; l < layout.levelCount(); ++l) {
        const glm::ivec3 n = layout.bricksOf(l);
        const PagedLevel& level = layout.level(l);
        for (int x = 0; x < n.x; ++x) {
            const BrickKey key{l, {x, 0, 0}};
            glm::dvec3 lo, hi;
            layout.box(key, lo, hi);
            glm::ivec3 first, count;
            layout.texels(key, first, count);
            // The level's voxel coordinate of the region's ends along x.
            const double spacing = layout.spacingOf(l).x;
            const double u0 = (lo.x + layout.halfExtent().x) / spacing;
            const double u1 = (hi.x + layout.halfExtent().x) / spacing;
            const int need0 = std::max(0, int(std::floor(u0 - 0.5)));
            const int need1 = std::min(level.dimensions.x - 1, int(std::floor(u1 - 0.5)) + 1);
            CHECK(first.x <= need0);
            CHECK(first.x + count.x - 1 >= need1);
            CHECK(count.x <= layout.brickCells() + 2); // one guard voxel a side, no more
            CHECK(first.x + count.x <= level.dimensions.x);
        }
    }
}

TEST_CASE("with every brick available the drawn voxels project below the pixel budget") {
    const PagedLayout layout = oddLayout();
    const LodView view = viewFrom({4.0, 3.0, 60.0}, 90);
    LodRequest request;
    request.pixelBudget = 4.5;
    request.available = [](const BrickKey&) { return true; };
    const LodSelection s = selectBricks(layout, view, request);
    CHECK(s.converged());
    CHECK(s.coarser == 0);
    double covered = 0.0;
    std::set<int> levels;
    for (const BrickKey& key : s.drawn) {
        covered += volumeOf(layout, key);
        levels.insert(key.level);
        CHECK((key.level == 0 || projectedVoxelPixels(layout, key, view) <= 4.5));
    }
    const glm::dvec3 half = layout.halfExtent();
    REQUIRE(s.culled == 0);
    CHECK(covered == doctest::Approx(8.0 * half.x * half.y * half.z).epsilon(1e-9));
    CHECK(levels.size() >= 2); // near bricks finer than far ones
}

TEST_CASE("missing children are wanted coarse first, and the resident parent is drawn") {
    const PagedLayout layout = oddLayout();
    const LodView view = viewFrom({3.0, 2.0, 30.0}, 800);
    LodRequest request;
    const int top = layout.levelCount() - 1;
    request.available = [&](const BrickKey& k) { return k.level >= top - 1; };
    const LodSelection s = selectBricks(layout, view, request);
    CHECK_FALSE(s.converged());
    CHECK(s.coarser > 0);
    REQUIRE_FALSE(s.wanted.empty());
    for (std::size_t i = 1; i < s.wanted.size(); ++i)
        CHECK(s.wanted[i - 1].level >= s.wanted[i].level);
    for (const BrickKey& key : s.drawn)
        CHECK(key.level >= top - 1);
}

TEST_CASE("the texture budget bounds the drawn bricks' bytes") {
    const PagedLayout layout = oddLayout();
    const LodView view = viewFrom({3.0, 2.0, 25.0}, 2000);
    LodRequest request;
    request.available = [](const BrickKey&) { return true; };
    request.bytes = [&](const BrickKey& k) {
        glm::ivec3 first, count;
        layout.texels(k, first, count);
        return std::uint64_t(count.x) * count.y * count.z;
    };
    request.textureBudget = 6000;
    const LodSelection s = selectBricks(layout, view, request);
    CHECK(s.bytes <= 6000);
    CHECK(s.budgetLimited);
    CHECK(s.converged()); // nothing is missing: the budget, not I/O, stops it
}

TEST_CASE("drawn bricks come back to front along every ray from the eye") {
    const PagedLayout layout = oddLayout();
    std::mt19937 random(3);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (const glm::dvec3 eye : {glm::dvec3(10, 8, 40), glm::dvec3(-30, -4, 2), glm::dvec3(4, 3, 2),
                                 glm::dvec3(0.5, -20, -15)}) {
        const LodView view = viewFrom(eye, 600);
        LodRequest request;
        request.available = [](const BrickKey& k) { return (k.index.x + k.index.z) % 3 != 1; };
        const LodSelection s = selectBricks(layout, view, request);
        REQUIRE(!s.drawn.empty());
        for (int ray = 0; ray < 300; ++ray) {
            const glm::dvec3 target =
                layout.halfExtent() * glm::dvec3(unit(random), unit(random), unit(random));
            const glm::dvec3 d = glm::normalize(target - eye);
            // Along the ray the bricks it enters, nearest first, must be drawn last.
            std::vector<std::pair<double, int>> hits;
            for (std::size_t i = 0; i < s.drawn.size(); ++i) {
                glm::dvec3 lo, hi;
                layout.box(s.drawn[i], lo, hi);
                const double t = entry(eye, d, lo, hi);
                if (t >= 0.0) hits.push_back({t, int(i)});
            }
            std::sort(hits.begin(), hits.end());
            for (std::size_t h = 1; h < hits.size(); ++h)
                CHECK_MESSAGE(hits[h - 1].second > hits[h].second,
                              "eye " << eye.x << " " << eye.y << " " << eye.z);
        }
    }
}

TEST_CASE("with reach 1 a brick's texture also holds what central differences read") {
    const PagedLayout narrow = oddLayout();
    std::vector<PagedLevel> levels;
    for (int l = 0; l < narrow.levelCount(); ++l)
        levels.push_back(narrow.level(l));
    const PagedLayout wide(levels, narrow.spacing(), narrow.brickCells(), 1);
    CHECK(wide.reach() == 1);
    for (int l = 0; l < wide.levelCount(); ++l) {
        const glm::ivec3 n = wide.bricksOf(l);
        const glm::ivec3 dimensions = wide.level(l).dimensions;
        for (int x = 0; x < n.x; ++x) {
            const BrickKey key{l, {x, n.y / 2, n.z - 1}};
            glm::ivec3 first, count, narrowFirst, narrowCount;
            wide.texels(key, first, count);
            narrow.texels(key, narrowFirst, narrowCount);
            // One voxel more each side (a sample one voxel from the region's end reads it),
            // but never beyond the level, which one texture of it clamps alike.
            for (int a = 0; a < 3; ++a) {
                CHECK(first[a] == std::max(0, narrowFirst[a] - 1));
                CHECK(first[a] + count[a] ==
                      std::min(dimensions[a], narrowFirst[a] + narrowCount[a] + 1));
            }
        }
    }
}
