// The k-d split of a volume into sort-last parts, their visibility order, and the "over"
// operator that composites the parts (no MPI, no GL).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/sortlast/KdVolumeSplit.h>
#include <volsg/sortlast/PremultipliedOver.h>

using namespace volsg;

namespace {

const glm::dvec3 kSpacing(1.0, 0.8, 1.3);

/// The parts whose box holds p (local coordinates; half-open boxes).
int partsAt(const KdVolumeSplit& split, const glm::dvec3& p, int& last) {
    int count = 0;
    for (int k = 0; k < split.parts(); ++k) {
        const KdVolumeSplit::Part& part = split.part(k);
        if (!part.empty && glm::all(glm::greaterThanEqual(p, part.boxMin)) &&
            glm::all(glm::lessThan(p, part.boxMax))) {
            ++count;
            last = k;
        }
    }
    return count;
}

/// Walks rays from `eye` (or along `direction`) through the volume and checks that the parts
/// met along each ray come in front-to-back order: what compositing in that order needs.
/// Returns the rays that broke the order.
int raysOutOfOrder(const KdVolumeSplit& split, const glm::dvec3& half, bool orthographic,
                   const glm::dvec3& eyeOrDirection, std::mt19937& random) {
    const std::vector<int> order = split.frontToBack(eyeOrDirection, orthographic);
    std::vector<int> positionOf(order.size());
    for (std::size_t k = 0; k < order.size(); ++k)
        positionOf[std::size_t(order[k])] = int(k);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int broken = 0;
    for (int r = 0; r < 40; ++r) {
        const glm::dvec3 target(unit(random) * half.x, unit(random) * half.y,
                                unit(random) * half.z);
        const glm::dvec3 direction =
            orthographic ? eyeOrDirection : glm::normalize(target - eyeOrDirection);
        const glm::dvec3 start =
            orthographic ? target - 4.0 * glm::length(half) * direction : eyeOrDirection;
        int last = -1;
        bool ok = true;
        for (double t = 0.0; t < 8.0 * glm::length(half) + 20.0; t += 0.1) {
            int part = -1;
            if (partsAt(split, start + t * direction, part) != 1) continue;
            const int position = positionOf[std::size_t(part)];
            if (position < last) ok = false;
            last = std::max(last, position);
        }
        if (!ok) ++broken;
    }
    return broken;
}

} // namespace

TEST_CASE("the parts tile the volume box: every point in exactly one part") {
    std::mt19937 random(3);
    for (const int parts : {1, 2, 3, 4, 7}) {
        const glm::ivec3 dims(40, 33, 27);
        const KdVolumeSplit split(dims, kSpacing, parts);
        const glm::dvec3 half = 0.5 * glm::dvec3(dims) * kSpacing;
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        int wrong = 0;
        for (int k = 0; k < 5000; ++k) {
            const glm::dvec3 p(unit(random) * half.x, unit(random) * half.y, unit(random) * half.z);
            int part = -1;
            if (partsAt(split, p, part) != 1) ++wrong;
        }
        CAPTURE(parts);
        CHECK(wrong == 0);
        // Balanced: the voxel spans of the parts within a factor of two.
        double fewest = 1e30, most = 0.0;
        for (int k = 0; k < parts; ++k) {
            const KdVolumeSplit::Part& part = split.part(k);
            REQUIRE(!part.empty);
            const glm::dvec3 size = part.boxMax - part.boxMin;
            fewest = std::min(fewest, size.x * size.y * size.z);
            most = std::max(most, size.x * size.y * size.z);
        }
        CHECK(most <= 2.0 * fewest);
    }
}

TEST_CASE("neighbouring parts share one voxel layer, and the ghost reaches beyond it") {
    const KdVolumeSplit split({64, 10, 10}, glm::dvec3(1.0), 2);
    const KdVolumeSplit::Part& low = split.part(0);
    const KdVolumeSplit::Part& high = split.part(1);
    CHECK(low.lastVoxel.x == high.firstVoxel.x); // interpolation across the cut sees both
    CHECK(low.boxMax.x == high.boxMin.x);
    glm::ivec3 first, count;
    split.voxelsWithGhost(1, 2, first, count);
    CHECK(first == glm::ivec3(high.firstVoxel.x - 2, 0, 0));
    CHECK(count == glm::ivec3(64 - first.x, 10, 10));
}

TEST_CASE("a volume with fewer cells than parts leaves the last parts empty") {
    const KdVolumeSplit split({2, 2, 2}, glm::dvec3(1.0), 4);
    CHECK(!split.part(0).empty);
    CHECK(split.part(1).empty);
    CHECK(split.part(3).empty);
    const std::vector<int> order = split.frontToBack({0.0, 0.0, 5.0}, false);
    REQUIRE(order.size() == 4);
    CHECK(order[0] == 0);
    glm::ivec3 first, count;
    split.voxelsWithGhost(2, 1, first, count);
    CHECK(count == glm::ivec3(0));
}

TEST_CASE("the parts' front-to-back order holds along every ray, from inside and outside") {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (const int parts : {2, 3, 4, 7}) {
        const glm::ivec3 dims(33, 29, 21);
        const KdVolumeSplit split(dims, kSpacing, parts);
        const glm::dvec3 half = 0.5 * glm::dvec3(dims) * kSpacing;
        CAPTURE(parts);
        for (int view = 0; view < 9; ++view) {
            // Eyes inside the box, beside it along some axes, and outside it.
            const double reach = view < 3 ? 0.8 : view < 6 ? 1.6 : 3.0;
            const glm::dvec3 eye(unit(random) * half.x * reach, unit(random) * half.y * reach,
                                 unit(random) * half.z * reach);
            CHECK(raysOutOfOrder(split, half, false, eye, random) == 0);
            const glm::dvec3 direction = glm::normalize(
                glm::dvec3(unit(random), unit(random), unit(random)) + glm::dvec3(1e-3));
            CHECK(raysOutOfOrder(split, half, true, direction, random) == 0);
        }
    }
}

TEST_CASE("over composites premultiplied colour as the slicer's blend, in any grouping") {
    // Three premultiplied pixels front (a) to back (c), and an opaque background.
    const float a[4] = {0.2f, 0.1f, 0.05f, 0.3f};
    const float b[4] = {0.1f, 0.4f, 0.2f, 0.5f};
    const float c[4] = {0.3f, 0.3f, 0.6f, 0.9f};
    // The slicer's blend, back to front onto an opaque background (ONE, ONE_MINUS_SRC_ALPHA).
    float blended[4] = {0.5f, 0.5f, 0.5f, 1.0f};
    for (const float* s : {c, b, a})
        for (int i = 0; i < 4; ++i)
            blended[i] = s[i] + (1.0f - s[3]) * blended[i];
    // (a over b) over (c over background)
    float ab[4] = {b[0], b[1], b[2], b[3]};
    compositeOver(a, ab, 1);
    float rest[4] = {0.5f, 0.5f, 0.5f, 1.0f};
    compositeOver(c, rest, 1);
    compositeOver(ab, rest, 1);
    for (int i = 0; i < 4; ++i)
        CHECK(rest[i] == doctest::Approx(blended[i]).epsilon(1e-6));
    // Not commutative: b over a differs.
    float ba[4] = {a[0], a[1], a[2], a[3]};
    compositeOver(b, ba, 1);
    CHECK(std::abs(ba[0] - ab[0]) > 0.01f);
}
