// The error model's rays skip the cells that cannot emit (lib/volsg/slicing/EmptyRuns): a ray's
// runs lie where every trilinear sample is transparent, and skipping changes no prediction.
#include "SlicingTestSupport.h"

#include <cmath>

#include <volsg/slicing/EmptyCells.h>
#include <volsg/slicing/EmptyRuns.h>
#include <volsg/slicing/PreIntegrationTable.h>
#include <volsg/slicing/SlabErrorModel.h>
#include <volsg/slicing/TransferTable.h>

using namespace volsg;
using namespace volsg::test;

namespace {

/// On an anisotropic 16-bit grid whose size is not a multiple of the cell's (partial last
/// cells): air (0) for x below -0.3, else a background just under the spike's foot (0.2985,
/// within one pre-integration entry of it: only the pad keeps its cells from counting as
/// empty), with one voxel in 5000 at the spike's peak scattered through both.
ref_ptr<VolumeGrid> sparsePeaks() {
    return makeGrid({43, 37, 29}, VoxelType::UShort, {1.0, 1.5, 2.0}, [](const glm::dvec3& p) {
        const double h = std::fmod(
            std::abs(std::sin(glm::dot(p, glm::dvec3(127.1, 311.7, 74.7))) * 43758.5453), 1.0);
        if (h < 2e-4) return 0.4;
        return p.x < -0.3 ? 0.0 : 0.2985;
    });
}

/// The spike the data is read under, over the type's whole range: transparent below 0.3 and
/// above 0.5.
TransferFunction1D spikeFunction() {
    TransferFunction1D tf = transferFunction(spike(0.3, 0.4, 0.5));
    tf.setDataRange(0.0, 65535.0);
    return tf;
}

double trilinear(const VolumeGrid& g, const glm::dvec3& p) {
    const glm::ivec3 d = g.dimensions();
    const glm::dvec3 u =
        glm::clamp((p + 0.5 * g.extent()) / g.spacing() - 0.5, glm::dvec3(0.0), glm::dvec3(d - 1));
    const glm::ivec3 i = glm::min(glm::ivec3(u), glm::max(d - 2, glm::ivec3(0)));
    const glm::dvec3 f = u - glm::dvec3(i);
    double out = 0.0;
    for (int c = 0; c < 8; ++c) {
        const glm::ivec3 o((c & 1) ? 1 : 0, (c & 2) ? 1 : 0, (c & 4) ? 1 : 0);
        const glm::ivec3 at = glm::min(i + o, d - 1);
        double w = 1.0;
        for (int a = 0; a < 3; ++a)
            w *= o[a] ? f[a] : 1.0 - f[a];
        out += w * g.value(at.x, at.y, at.z);
    }
    return out;
}

/// A ray from a pseudo-random point on a sphere around the box through a point inside it.
struct TestRay {
    glm::dvec3 origin, dir;
    double t0 = 0.0, t1 = 0.0;
};
TestRay rayThrough(const glm::dvec3& half, int seed) {
    const auto at = [&](int k) {
        return std::fmod(std::sin(12.9898 * (seed * 7 + k)) * 43758.5, 1.0);
    };
    const glm::dvec3 from = 3.0 * glm::length(half) *
                            glm::normalize(glm::dvec3(at(0), at(1), at(2)) + glm::dvec3(1e-3));
    const glm::dvec3 to = half * glm::dvec3(at(3), at(4), at(5));
    TestRay r;
    r.origin = from;
    r.dir = glm::normalize(to - from);
    r.t0 = -1e300;
    r.t1 = 1e300;
    for (int a = 0; a < 3; ++a) {
        double ta = (-half[a] - from[a]) / r.dir[a], tb = (half[a] - from[a]) / r.dir[a];
        if (ta > tb) std::swap(ta, tb);
        r.t0 = std::max(r.t0, ta);
        r.t1 = std::min(r.t1, tb);
    }
    return r;
}

} // namespace

TEST_CASE("a ray's empty runs lie where every sample is transparent") {
    const auto grid = sparsePeaks();
    RayCastVolume volume = volumeOf(grid, spikeFunction());
    TransferTable table;
    table.build(volume.transferFunctions, {0.0, 65535.0});
    EmptyCells cells;
    cells.measure(*grid, nullptr, 0.0, 65535.0);
    const double pad = PreIntegrationTable::kLookupPadV;
    cells.classify(table, false, false, pad);
    const glm::dvec3 half = 0.5 * grid->extent();
    const EmptyCellMap map{half, grid->spacing(), grid->dimensions(), &cells};
    const auto& alpha = volume.transferFunctions[-1].channel(TransferFunction1D::Alpha);
    double inRuns = 0.0, total = 0.0;
    int checked = 0;
    for (int seed = 0; seed < 300; ++seed) {
        const TestRay r = rayThrough(half, seed);
        if (!(r.t1 > r.t0)) continue;
        total += r.t1 - r.t0;
        const auto runs = emptyRunsAlong(map, r.origin, r.dir, r.t0, r.t1);
        double last = r.t0;
        for (const glm::dvec2& run : runs) {
            REQUIRE(run.x >= last);
            REQUIRE(run.y > run.x);
            REQUIRE(run.y <= r.t1);
            last = run.y;
            inRuns += run.y - run.x;
            for (int k = 0; k <= 40; ++k) {
                const double t = run.x + (run.y - run.x) * k / 40.0;
                const double v = trilinear(*grid, r.origin + t * r.dir) / 65535.0;
                // Transparent with the pad the tables' filters need around the value.
                CHECK(alpha.maxOver(v - pad, v + pad) == 0.0);
                ++checked;
            }
        }
    }
    MESSAGE(checked << " samples in runs; runs cover " << inRuns / total << " of the rays");
    CHECK(checked > 1000);
    // About a third of this box is air, some of it near peaks: the runs must find much of it.
    CHECK(inRuns > 0.1 * total);
}

TEST_CASE("skipping empty cells leaves the error model's predictions as they were") {
    // Sparse peaks in air and in a background at the spike's foot (many empty cells, and
    // some that only the pad keeps) and Marschner-Lobb under its rising ramp (dense, few
    // empty cells), plain and pre-integrated, one and many samples per plane, thin and thick
    // slabs, a narrow and a wide ray set.
    RayCastVolume ball = volumeOf(sparsePeaks(), spikeFunction());
    RayCastVolume ml = marschnerLobbVolume();
    for (const RayCastVolume* v : {&ball, &ml}) {
        SlabErrorModel skipping(*v), whole(*v);
        whole.setSkipsEmptyCells(false);
        for (const int dir : {5, SlabErrorModel::kDirections + 12})
            for (const double spacing : {2.0, 40.0})
                for (const int samples : {1, 16})
                    for (const bool pre : {false, true}) {
                        SlabQuadrature q;
                        q.planeSpacingL0 = spacing;
                        q.samplesPerPlane = samples;
                        q.preIntegrated = pre;
                        const double a = skipping.rayRmse(dir, q), b = whole.rayRmse(dir, q);
                        CHECK(a > 0.0);
                        // The truth's skipped segments were transparent up to the rounding of
                        // its cumulative table (1e-9 of a segment's depth); the slicer's
                        // arithmetic is the same bit for bit.
                        CHECK(a == doctest::Approx(b).epsilon(1e-9));
                    }
    }
}
