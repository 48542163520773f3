// Brick layout: budgets, shared voxel layers at seams, and the back-to-front order.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <volsg/slicing/BrickLayout.h>

using namespace volsg;

namespace {

/// Whether the bricks' drawn regions tile the volume box exactly (no gap, no overlap).
double drawnVolume(const BrickLayout& layout) {
    double sum = 0.0;
    for (const Brick& b : layout.bricks()) {
        const glm::dvec3 size = b.boxMax - b.boxMin;
        sum += size.x * size.y * size.z;
    }
    return sum;
}

} // namespace

TEST_CASE("a volume within the budget is one brick holding every voxel") {
    const BrickLayout layout({37, 23, 19}, glm::dvec3(1.0, 1.5, 2.5), {0, 2048, 2, 0});
    REQUIRE(layout.bricks().size() == 1);
    const Brick& b = layout.bricks()[0];
    CHECK(b.firstVoxel == glm::ivec3(0));
    CHECK(b.voxelCount == glm::ivec3(37, 23, 19));
    CHECK(b.boxMin.x == doctest::Approx(-18.5));
    CHECK(b.boxMax.z == doctest::Approx(0.5 * 19 * 2.5));
    CHECK(layout.fitsBudget());
}

TEST_CASE("bricks fit the budget and tile the volume box exactly") {
    const glm::ivec3 dims(64, 40, 33);
    const glm::dvec3 spacing(1.0, 0.5, 2.0);
    for (const std::uint64_t budget : {100000u, 20000u, 3000u}) {
        const BrickLayout layout(dims, spacing, {budget, 2048, 2, 0});
        CHECK(layout.bricks().size() > 1);
        for (const Brick& b : layout.bricks())
            CHECK(layout.bytes(b) <= budget);
        CHECK(drawnVolume(layout) ==
              doctest::Approx(64.0 * 1.0 * 40.0 * 0.5 * 33.0 * 2.0).epsilon(1e-12));
        CHECK(int(layout.bricks().size()) == layout.grid().x * layout.grid().y * layout.grid().z);
    }
}

TEST_CASE("neighbouring bricks share the voxel layer at their seam") {
    const BrickLayout layout({30, 9, 9}, glm::dvec3(1.0), {2 * 10 * 10 * 10, 2048, 2, 0});
    REQUIRE(layout.grid().x >= 3);
    for (const Brick& b : layout.bricks()) {
        // Every trilinear lookup inside the drawn region [uMin, uMax) needs the voxels from
        // floor(u - 0.5) to floor(u - 0.5) + 1 (clamped): they are in the texture.
        const int first = b.firstVoxel.x, last = b.firstVoxel.x + b.voxelCount.x - 1;
        const double uMin = b.boxMin.x + 15.0, uMax = b.boxMax.x + 15.0; // voxel coordinates
        CHECK(std::max(int(std::floor(uMin - 0.5)), 0) >= first);
        CHECK(std::min(int(std::floor(uMax - 1e-9 - 0.5)) + 1, 29) <= last);
    }
    // Brick k's last voxel is brick k+1's first.
    const Brick& b0 = layout.bricks()[0];
    const Brick& b1 = layout.bricks()[1];
    CHECK(b0.firstVoxel.x + b0.voxelCount.x - 1 == b1.firstVoxel.x);
    CHECK(b0.boxMax.x == doctest::Approx(b1.boxMin.x));
}

TEST_CASE("a guard voxel keeps central differences inside each brick") {
    const BrickLayout plain({40, 8, 8}, glm::dvec3(1.0), {2 * 12 * 8 * 8, 2048, 2, 0});
    const BrickLayout guarded({40, 8, 8}, glm::dvec3(1.0), {2 * 14 * 8 * 8, 2048, 2, 1});
    REQUIRE(guarded.grid().x > 1);
    for (const Brick& b : guarded.bricks()) {
        const int first = b.firstVoxel.x, last = b.firstVoxel.x + b.voxelCount.x - 1;
        const double uMin = b.boxMin.x + 20.0, uMax = b.boxMax.x + 20.0;
        // A difference one voxel either side of any point needs floor(u -+ 1 - 0.5) (+1).
        CHECK(std::max(int(std::floor(uMin - 1.5)), 0) >= first);
        CHECK(std::min(int(std::floor(uMax - 1e-9 + 0.5)) + 1, 39) <= last);
    }
    CHECK(plain.grid().x > 1);
}

TEST_CASE("volumes larger than the 3D texture limit are split along that axis") {
    const BrickLayout layout({3000, 4, 5}, glm::dvec3(1.0), {0, 2048, 2, 0});
    CHECK(layout.grid() == glm::ivec3(2, 1, 1));
    CHECK(layout.largestTexture().x <= 2048);
    CHECK(layout.bricks()[1].firstVoxel.x + layout.bricks()[1].voxelCount.x == 3000);
}

TEST_CASE("a budget below the smallest brick gives 2-cell bricks and says so") {
    const BrickLayout layout({9, 9, 9}, glm::dvec3(1.0), {10, 2048, 2, 0});
    CHECK_FALSE(layout.fitsBudget());
    CHECK(layout.cellsPerBrick() == glm::ivec3(1));
    CHECK(layout.largestTexture() == glm::ivec3(2));
}

TEST_CASE("1xN and single-voxel axes make one brick along them") {
    const BrickLayout layout({1, 1, 100}, glm::dvec3(12.0, 12.0, 1.0), {2 * 30, 2048, 2, 0});
    CHECK(layout.grid().x == 1);
    CHECK(layout.grid().y == 1);
    CHECK(layout.grid().z > 1);
    for (const Brick& b : layout.bricks()) {
        CHECK(b.voxelCount.x == 1);
        CHECK(b.boxMin.x == doctest::Approx(-6.0));
        CHECK(b.boxMax.x == doctest::Approx(6.0));
    }
}

TEST_CASE("the back-to-front order never puts a brick behind one that hides it") {
    const BrickLayout layout({40, 40, 40}, glm::dvec3(1.0), {2 * 11 * 11 * 11, 2048, 2, 0});
    REQUIRE(layout.grid() == glm::ivec3(4));
    const auto& bricks = layout.bricks();
    std::vector<int> order;
    // Rays from several eyes (outside, inside, on a seam plane) and orthographic directions:
    // along each ray, the bricks it passes must appear in the order in reverse.
    struct View {
        glm::dvec3 eye;
        bool orthographic;
    };
    for (const View view :
         {View{{70, 50, 90}, false}, View{{3, -7, 12}, false}, View{{0.5, 0.5, -80}, false},
          View{{-0.3, 0.7, -1}, true}, View{{0, 0, 1}, true}}) {
        layout.backToFront(view.eye, view.orthographic, order);
        REQUIRE(order.size() == bricks.size());
        std::vector<int> position(order.size());
        for (std::size_t i = 0; i < order.size(); ++i)
            position[std::size_t(order[i])] = int(i);
        int checked = 0;
        for (int r = 0; r < 200; ++r) {
            // A deterministic spread of rays through the box.
            const glm::dvec3 target(-19.0 + (r * 7 % 38), -19.0 + (r * 13 % 38),
                                    -19.0 + (r * 29 % 38));
            const glm::dvec3 origin = view.orthographic ? target - 100.0 * view.eye : view.eye;
            const glm::dvec3 dir = glm::normalize(target - origin);
            int previous = -1;
            for (double t = 0.0; t < 400.0; t += 0.05) {
                const glm::dvec3 p = origin + t * dir;
                if (glm::any(glm::lessThan(p, glm::dvec3(-20))) ||
                    glm::any(glm::greaterThan(p, glm::dvec3(20))))
                    continue;
                for (std::size_t i = 0; i < bricks.size(); ++i)
                    if (glm::all(glm::greaterThan(p, bricks[i].boxMin)) &&
                        glm::all(glm::lessThan(p, bricks[i].boxMax)) && int(i) != previous) {
                        if (previous >= 0) {
                            // Front to back along the ray: drawn later.
                            CHECK(position[i] < position[std::size_t(previous)]);
                            ++checked;
                        }
                        previous = int(i);
                    }
            }
        }
        CHECK(checked > 100);
    }
}
