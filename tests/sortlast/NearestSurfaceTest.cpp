// The depth composite of sort-last's opaque images (no MPI, no GL): the nearest surface per
// pixel, in any grouping, ties to the lower rank.
#include <doctest/doctest.h>

#include <random>
#include <vector>

#include <volsg/sortlast/NearestSurface.h>

using namespace volsg;

TEST_CASE("the depth composite keeps the nearest surface, in any grouping, ties to the front "
          "operand") {
    std::mt19937 random(7);
    std::uniform_int_distribution<int> level(0, 4); // few depths: many ties
    const std::size_t pixels = 200;
    std::vector<std::vector<SurfacePixel>> images(5, std::vector<SurfacePixel>(pixels));
    for (std::size_t r = 0; r < images.size(); ++r)
        for (SurfacePixel& p : images[r])
            p = {level(random) == 4 ? 1.0f : 0.2f * float(level(random)), float(r), 0.5f, 0.25f,
                 1.0f};
    // Left to right: ((0 1) 2) 3) 4, as a chain.
    std::vector<SurfacePixel> chain = images[4];
    for (int r = 3; r >= 0; --r) {
        std::vector<SurfacePixel> front = images[std::size_t(r)];
        keepNearest(front.data(), chain.data(), pixels); // chain = r op chain
    }
    // Another grouping: (0 1) op ((2 3) 4).
    std::vector<SurfacePixel> left = images[1], right = images[4], middle = images[3];
    keepNearest(images[0].data(), left.data(), pixels);
    keepNearest(images[2].data(), middle.data(), pixels);
    keepNearest(middle.data(), right.data(), pixels);
    keepNearest(left.data(), right.data(), pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        // The expected: the smallest depth, the lowest rank among equals.
        std::size_t best = 0;
        for (std::size_t r = 1; r < images.size(); ++r)
            if (images[r][i].depth < images[best][i].depth) best = r;
        CAPTURE(i);
        CHECK(chain[i].depth == images[best][i].depth);
        CHECK(chain[i].red == float(best));
        CHECK(right[i].red == float(best));
    }
}

TEST_CASE("an opaque image's colour and depth go into surface pixels and back unchanged") {
    const std::vector<glm::vec4> color = {{0.1f, 0.2f, 0.3f, 1.0f}, {0.4f, 0.5f, 0.6f, 1.0f}};
    const std::vector<float> depth = {0.25f, 1.0f};
    std::vector<glm::vec4> colorBack;
    std::vector<float> depthBack;
    splitSurfacePixels(surfacePixels(color, depth), colorBack, depthBack);
    CHECK(colorBack == color);
    CHECK(depthBack == depth);
    CHECK_THROWS(surfacePixels(color, {0.5f}));
}
