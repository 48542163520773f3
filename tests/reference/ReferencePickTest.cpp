// ReferenceRayCaster::firstVisibleDistance: where a ray first meets visible content, checked
// on a linear ramp where the answer is a closed formula.
#include <doctest/doctest.h>

#include <cmath>

#include <volsg/core/Error.h>
#include <volsg/reference/ReferenceRayCaster.h>

using namespace volsg;

namespace {
// An 8^3 Float grid (spacing 1: the box is z in [-4, 4]) with value k in the voxels of slice
// k: trilinear data d = z + 3.5 between the outermost centres, clamped beyond. The default
// transfer function is the identity ramp over the data's range 0..7, so A = d / 7.
RayCastVolume ramp() {
    auto grid = VolumeGrid::create({8, 8, 8}, VoxelType::Float);
    for (int k = 0; k < 8; ++k)
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i)
                grid->setValue(i, j, k, double(k));
    RayCastVolume v;
    v.data = grid;
    return v;
}
const Ray up{{0.25, -0.5, -10.0}, {0.0, 0.0, 2.0}}; // along +z; direction need not be unit
} // namespace

TEST_CASE("the first visible point is where the classified opacity reaches the threshold") {
    const RayCastVolume volume = ramp();
    // A = (z + 3.5) / 7 = 0.02 at z = -3.36: 6.64 along the ray from z = -10.
    const auto hit = ReferenceRayCaster::firstVisibleDistance(volume, up, 0.0, 1e300);
    REQUIRE(hit.has_value());
    CHECK(*hit == doctest::Approx(6.64).epsilon(1e-9));
    // Another threshold: A = 0.5 at z = 0.
    CHECK(*ReferenceRayCaster::firstVisibleDistance(volume, up, 0.0, 1e300, 0.5) ==
          doctest::Approx(10.0).epsilon(1e-9));
    // Starting beyond that point: visible at once, at the near distance.
    CHECK(*ReferenceRayCaster::firstVisibleDistance(volume, up, 8.0, 1e300) ==
          doctest::Approx(8.0).epsilon(1e-12));
    // Ending before it, or running the other way through only the transparent start: none.
    CHECK_FALSE(ReferenceRayCaster::firstVisibleDistance(volume, up, 0.0, 6.5).has_value());
    CHECK_FALSE(ReferenceRayCaster::firstVisibleDistance(
                    volume, Ray{{0.0, 0.0, -3.6}, {0.0, 0.0, -1.0}}, 0.0, 1e300)
                    .has_value());
}

TEST_CASE("a BoxClip opacity multiplier m raises the data needed to 1 - (1 - A)^m = 0.02") {
    RayCastVolume volume = ramp();
    RayCastBoxClip clip; // a box far away: the whole volume is outside, at opacity 0.5
    clip.origin = glm::dvec3(100.0);
    clip.outsideOpacity = 0.5;
    volume.boxClip = clip;
    // A = 1 - 0.98^2 = 0.0396 at z = 7 * 0.0396 - 3.5.
    const double z = 7.0 * (1.0 - 0.98 * 0.98) - 3.5;
    CHECK(*ReferenceRayCaster::firstVisibleDistance(volume, up, 0.0, 1e300) ==
          doctest::Approx(z + 10.0).epsilon(1e-9));
    volume.boxClip->outsideOpacity = 0.0; // removed
    CHECK_FALSE(ReferenceRayCaster::firstVisibleDistance(volume, up, 0.0, 1e300).has_value());
}

TEST_CASE("clip planes and the model matrix move where a volume is first visible") {
    RayCastVolume volume = ramp();
    volume.clipPlanes.push_back({0.0, 0.0, 1.0, 1.0}); // keeps z >= 1
    CHECK(*ReferenceRayCaster::firstVisibleDistance(volume, up, 0.0, 1e300) ==
          doctest::Approx(11.0).epsilon(1e-12));
    RayCastVolume moved = ramp();
    moved.model = glm::dmat4(2.0); // twice the size: A = 0.02 at z = 2 * -3.36
    moved.model[3][3] = 1.0;
    CHECK(*ReferenceRayCaster::firstVisibleDistance(moved, up, 0.0, 1e300) ==
          doctest::Approx(10.0 - 6.72).epsilon(1e-9));
    RayCastVolume none;
    CHECK_THROWS_AS(ReferenceRayCaster::firstVisibleDistance(none, up, 0.0, 1e300), Error);
}
