// Cameras at the edges of what the slicing path must handle: a volume wholly behind the eye,
// a very wide perspective (120 degrees), and that wide view from inside the volume.
#include "SlicingTestSupport.h"

#include <cmath>

using namespace volsg;
using namespace volsg::test;

namespace {

constexpr float kDegrees120 = 2.0f * 3.14159265f / 3.0f;

/// A smooth blob with some structure so that wrong plane geometry shows up as error.
double lumpyBlob(const glm::dvec3& p) {
    const double r2 = glm::dot(p, p);
    return std::clamp(
        std::exp(-1.2 * r2) * (0.75 + 0.25 * std::sin(4.0 * p.x) * std::cos(3.0 * p.y)), 0.0, 1.0);
}

RayCastVolume lumpyVolume() {
    return volumeOf(makeGrid({28, 24, 20}, VoxelType::UByte, glm::dvec3(1.0), lumpyBlob),
                    transferFunction({{0, 0.0}, {0.2, 0.02}, {1, 0.35}}, {{0, 0.1}, {1, 1}},
                                     {{0, 0.6}, {1, 0.5}}, {{0, 1}, {1, 0.2}}));
}

/// A perspective camera at `eye` looking along `forward` (not at the origin).
ref_ptr<PerspectiveCamera> lookingAlong(const glm::vec3& eye, const glm::vec3& forward,
                                        float heightAngle, float nearDistance, float farDistance) {
    auto camera = perspectiveAt(-glm::normalize(forward), heightAngle, nearDistance, farDistance);
    camera->position = eye;
    return camera;
}

} // namespace

TEST_CASE_FIXTURE(GlFixture, "a volume wholly behind the camera leaves the background untouched") {
    const RayCastVolume v = lumpyVolume();
    const glm::vec3 background(0.2f, 0.3f, 0.4f);
    // The eye is 40 units in front of the volume, looking away from it: the whole box is
    // behind the eye, inside the frustum's mirror image, where a wrong w sign would draw it.
    for (const float heightAngle : {0.8f, kDegrees120}) {
        auto camera = lookingAlong({0, 0, 40}, {0, 0, 1}, heightAngle, 0.5f, 200.0f);
        const Comparison c = compareGrid(renderer, v, {}, *camera, 48, background);
        MESSAGE("heightAngle " << heightAngle << ": " << c.stats.planes << " planes, max "
                               << c.difference.max * 255 << "/255");
        CHECK(allFinite(c.gl));
        CHECK(c.stats.sliceTriangles == 0);
        double largest = 0.0; // exact: nothing may be blended over the background
        for (const glm::vec4& p : c.gl.pixels)
            largest = std::max(largest, double(glm::length(glm::vec3(p) - background)));
        CHECK(largest < 1e-6);
        CHECK(c.difference.max < 1e-6);
    }
}

TEST_CASE_FIXTURE(GlFixture, "a volume half behind the camera shows only its part in front") {
    const RayCastVolume v = lumpyVolume();
    // The eye at the box centre looks out through the +x face: the -x half is behind it.
    auto camera = lookingAlong({0, 0, 0}, {1, 0.15f, 0.1f}, 1.4f, 0.25f, 100.0f);
    const Comparison c = compareGrid(renderer, v, {}, *camera, 64);
    keepImages(c, "half-behind");
    checkSliced(c, 0.25, 1.0);
}

TEST_CASE_FIXTURE(GlFixture, "perspective at a 120 degree field of view matches the reference") {
    const RayCastVolume v = lumpyVolume();
    // Close enough that the box fills most of the 120 degree frustum: rays at the image
    // corners cross the planes at over 60 degrees, where the plane spacing along the ray is
    // twice the spacing along the view axis and opacity correction must follow it.
    for (const glm::vec3 eye : {glm::vec3(0, 0, 12), glm::vec3(10, 8, 13)}) {
        auto camera = perspectiveAt(eye, kDegrees120, 0.5f, 100.0f);
        const Comparison c = compareGrid(renderer, v, {}, *camera, 64);
        keepImages(c, "fov120-" + std::to_string(int(eye.x)));
        checkSliced(c, 0.2, 1.0, "eye " + text(eye) + ": ");
    }
}

TEST_CASE_FIXTURE(GlFixture, "a 120 degree view from inside the volume matches the reference") {
    const RayCastVolume v = lumpyVolume();
    auto camera = perspectiveAt({2, -1, 4}, kDegrees120, 0.3f, 100.0f);
    const Comparison c = compareGrid(renderer, v, {}, *camera, 64);
    keepImages(c, "fov120-inside");
    checkSliced(c, 0.4, 1.5);
}

TEST_CASE_FIXTURE(GlFixture,
                  "from inside the volume, a ray that leaves it before any plane is drawn") {
    // One or two thick slabs: most rays of a wide view from inside leave the box through a
    // side before they meet a plane, and only the near plane's cut through the box gives them
    // a fragment (without it, regions of the image stayed empty: 42/255 on ErrorTargetTest's
    // three spikes).
    const RayCastVolume v = lumpyVolume();
    auto camera = perspectiveAt({2, -1, 4}, kDegrees120, 0.3f, 100.0f);
    for (const int planes : {1, 2})
        for (const bool preIntegrated : {false, true}) {
            SlicingSettings s;
            s.numPlanes = planes;
            s.samplesPerPlane = 256;
            s.preIntegrated = preIntegrated;
            s.fixedSamplesPerPlane = s.fixedPreIntegrated = true;
            const Comparison c = compareGrid(renderer, v, s, *camera, 64);
            checkSliced(c, 0.4, 1.5, preIntegrated ? "pre-integrated, " : "");
        }
}
