// Generated test volumes: the functions they sample, their ranges, determinism.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <set>

#include <volsg/volume/TestVolumes.h>

using namespace volsg;

TEST_CASE("the Marschner-Lobb signal has its known extremes") {
    // z = -1, r = 0: (1 + 1 + 0.25 * 2) / 2.5 = 1; z = +1, r = 0: (0 + 0.5) / 2.5 = 0.2.
    CHECK(marschnerLobb(0.0, 0.0, -1.0) == doctest::Approx(1.0).epsilon(1e-14));
    CHECK(marschnerLobb(0.0, 0.0, 1.0) == doctest::Approx(0.2).epsilon(1e-14));
    // r = 1: rho_r = cos(12 pi cos(pi / 2)) = 1 too; at z = 0 (1 + 0.5) / 2.5 = 0.6.
    CHECK(marschnerLobb(1.0, 0.0, 0.0) == doctest::Approx(0.6).epsilon(1e-12));
}

TEST_CASE("the Marschner-Lobb volume samples the signal at the voxel centres") {
    auto g = makeMarschnerLobb(41, VoxelType::Float);
    CHECK(g->dimensions() == glm::ivec3(41));
    CHECK(g->spacing().x == doctest::Approx(0.05).epsilon(1e-15));
    for (glm::ivec3 v : {glm::ivec3(0, 0, 0), glm::ivec3(20, 20, 0), glm::ivec3(7, 33, 12),
                         glm::ivec3(40, 40, 40)}) {
        const glm::dvec3 c = g->voxelCenter(v.x, v.y, v.z); // local coordinates = signal's
        CHECK(g->value(v.x, v.y, v.z) ==
              doctest::Approx(marschnerLobb(c.x, c.y, c.z)).epsilon(1e-6));
    }
    auto b = makeMarschnerLobb(41, VoxelType::UByte);
    CHECK(b->value(20, 20, 0) == 255.0);
    CHECK(b->value(20, 20, 40) == std::nearbyint(0.2 * 255.0));
    const auto [lo, hi] = b->minMax();
    CHECK(lo >= 0.0);
    CHECK(hi == 255.0);
}

TEST_CASE("generated volumes are deterministic") {
    auto a = makeMarschnerLobb(17, VoxelType::UByte);
    auto b = makeMarschnerLobb(17, VoxelType::UByte);
    CHECK(std::memcmp(a->bytes().data(), b->bytes().data(), a->byteSize()) == 0);
    auto la = makeLabelledVolume(12), lb = makeLabelledVolume(12);
    CHECK(std::memcmp(la.tags->bytes().data(), lb.tags->bytes().data(), la.tags->byteSize()) == 0);
}

TEST_CASE("the 16-bit volume uses the full 0..65535 range") {
    auto g = makeFullRange16(21);
    CHECK(g->type() == VoxelType::UShort);
    CHECK(g->minMax() == std::pair(0.0, 65535.0));
    CHECK(g->value(10, 10, 10) == 65535.0); // the centre of an odd grid
    CHECK(g->value(0, 0, 0) == 0.0);        // a corner is farthest
    CHECK(g->value(10, 10, 0) > g->value(10, 0, 0));
}

TEST_CASE("the soft sphere falls off linearly from its centre") {
    auto g = makeSoftSphere(21, VoxelType::Float);
    CHECK(g->value(10, 10, 10) == 1.0);
    CHECK(g->value(0, 0, 0) == 0.0);
    // r = 5 voxels, R = 0.45 * 21 = 9.45.
    CHECK(g->value(15, 10, 10) == doctest::Approx(1.0 - 5.0 / 9.45).epsilon(1e-6));
}

TEST_CASE("the thin shell is one to two voxels thick") {
    const int n = 32;
    const double radius = 10.3, thickness = 1.5;
    auto g = makeThinShell(n, radius, thickness);
    for (int axis = 0; axis < 3; ++axis) {
        int along = 0;
        for (int i = n / 2; i < n; ++i) {
            glm::ivec3 v(n / 2);
            v[axis] = i;
            if (g->value(v.x, v.y, v.z) > 0) ++along;
        }
        CHECK(along >= 1);
        CHECK(along <= 2);
    }
    std::size_t set = 0;
    for (std::size_t v = 0; v < g->voxelCount(); ++v)
        set += g->value(v) > 0 ? 1 : 0;
    const double expected = 4.0 * std::numbers::pi * radius * radius * thickness;
    CHECK(double(set) == doctest::Approx(expected).epsilon(0.1));
}

TEST_CASE("the labelled volume carries several tags on soft-sphere data") {
    auto l = makeLabelledVolume(16);
    CHECK(l.tags->dimensions() == l.data->dimensions());
    CHECK(l.tags->isLabelType());
    std::set<int> tags;
    for (std::size_t v = 0; v < l.tags->voxelCount(); ++v)
        tags.insert(int(l.tags->value(v)));
    CHECK(tags == std::set<int>{0, 1, 2, 3});
    CHECK(l.tags->value(8, 8, 8) == 1.0);
    CHECK(l.tags->value(0, 0, 0) == 3.0);
    CHECK(l.tags->value(0, 0, 15) == 0.0);
}

TEST_CASE("constant and ramp volumes hold their closed-form values") {
    auto c = makeConstant({3, 2, 2}, VoxelType::Short, -7.0);
    CHECK(c->minMax() == std::pair(-7.0, -7.0));
    auto r = makeRamp({2, 17, 3}, VoxelType::Float, 1, 0.0, 1.0);
    for (int j = 0; j < 17; ++j)
        CHECK(r->value(1, j, 2) == double(j) / 16.0);
    auto one = makeRamp({1, 1, 1}, VoxelType::UByte, 0, 9.0, 200.0);
    CHECK(one->value(0, 0, 0) == 9.0);
}
