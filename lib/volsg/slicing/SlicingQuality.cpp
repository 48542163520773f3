// The slicer's settings from an error target (see SlicingQuality.h).
#include <volsg/slicing/SlicingQuality.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace volsg {

namespace {

/// The model's prediction is taken against this share of the target: it samples 144 rays
/// per direction and the nearest of 13 directions, so it is a few tens of percent off either
/// way (README, "Error targets").
constexpr double kTargetMargin = 0.7;
/// Automatic planes: samples per plane grow (powers of two up to kMaxAutoSamples) until about
/// this many planes cross the view's depth. On llvmpipe a fragment costs several samples'
/// worth (rasterisation, slab set-up, the float blend), so thick slabs of many samples are
/// cheapest; a few planes keep the silhouette slivers and the empty-cell rows working.
constexpr double kPlanesWanted = 8.0;
constexpr int kMaxAutoSamples = 64;
/// Samples per L0 searched: 2^(j/2) for j in [kLowestStep, kHighestStep].
constexpr int kLowestStep = -16; // 1/256
constexpr int kHighestStep = 4;  // 4

/// Spacing rounded to 3 significant digits, so views that differ a little share a cache key.
double roundedSpacing(double s) {
    if (!(s > 0.0)) return s;
    const double e = std::pow(10.0, std::floor(std::log10(s)) - 2.0);
    return std::round(s / e) * e;
}

int largestPowerOfTwoAtMost(double x, int cap) {
    int k = 1;
    while (k * 2 <= cap && double(k * 2) <= x)
        k *= 2;
    return k;
}

/// The quadrature of `samplesPerL0` for one kind (pre-integrated, or peaks), honouring the
/// request's fixed plane count or samples per plane.
SlabQuadrature quadratureFor(double samplesPerL0, bool preIntegrated, bool peaks,
                             const QualityRequest& r, const QualityView& view, bool extreme) {
    SlabQuadrature q;
    q.preIntegrated = preIntegrated;
    q.peaks = peaks;
    q.refinePeaks = r.refinePeaks;
    const int minimumSamples = extreme && !peaks && r.refinePeaks ? 2 : 1; // refinement needs 2
    if (r.numPlanes) {
        q.planeSpacingL0 = roundedSpacing(view.depthL0 / std::max(*r.numPlanes, 1));
        q.samplesPerPlane =
            r.samplesPerPlane
                ? *r.samplesPerPlane
                : std::clamp(int(std::ceil(samplesPerL0 * q.planeSpacingL0)), minimumSamples, 256);
        return q;
    }
    q.samplesPerPlane =
        r.samplesPerPlane
            ? *r.samplesPerPlane
            : std::max(minimumSamples,
                       largestPowerOfTwoAtMost(samplesPerL0 * view.depthL0 / kPlanesWanted,
                                               kMaxAutoSamples));
    q.planeSpacingL0 = double(q.samplesPerPlane) / samplesPerL0;
    return q;
}

} // namespace

QualityView qualityViewOf(const glm::dmat4& modelView, const glm::dmat4& projection,
                          const glm::dvec3& halfExtent, double L0) {
    QualityView q;
    const glm::dmat4 eyeToLocal = glm::inverse(modelView);
    const glm::dmat3 eyeToLocal3(eyeToLocal);
    const glm::dvec3 axis = eyeToLocal3 * glm::dvec3(0.0, 0.0, -1.0);
    q.localDirection = glm::normalize(axis);
    // The box's extent along the view axis: its corners' eye depths, in local units.
    double lo = 1e300, hi = -1e300;
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 p((c & 1) ? halfExtent.x : -halfExtent.x,
                           (c & 2) ? halfExtent.y : -halfExtent.y,
                           (c & 4) ? halfExtent.z : -halfExtent.z);
        const double depth = -(modelView * glm::dvec4(p, 1.0)).z;
        lo = std::min(lo, depth);
        hi = std::max(hi, depth);
    }
    q.depthL0 = (hi - lo) * glm::length(axis) / L0;
    const glm::dmat4 unproject = glm::inverse(projection);
    constexpr int n = 24;
    int hits = 0;
    double stretch = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x = -1.0 + (i + 0.5) * 2.0 / n, y = -1.0 + (j + 0.5) * 2.0 / n;
            const glm::dvec4 nearPoint = unproject * glm::dvec4(x, y, -1.0, 1.0);
            const glm::dvec4 farPoint = unproject * glm::dvec4(x, y, 1.0, 1.0);
            const glm::dvec3 a = glm::dvec3(nearPoint) / nearPoint.w;
            const glm::dvec3 eyeDir = glm::normalize(glm::dvec3(farPoint) / farPoint.w - a);
            const glm::dvec3 o = glm::dvec3(eyeToLocal * glm::dvec4(a, 1.0));
            const glm::dvec3 d = eyeToLocal3 * eyeDir;
            double t0 = 0.0, t1 = 1e300;
            for (int k = 0; k < 3; ++k) {
                if (std::abs(d[k]) < 1e-300) {
                    if (std::abs(o[k]) > halfExtent[k]) t1 = -1.0;
                    continue;
                }
                double ta = (-halfExtent[k] - o[k]) / d[k];
                double tb = (halfExtent[k] - o[k]) / d[k];
                if (ta > tb) std::swap(ta, tb);
                t0 = std::max(t0, ta);
                t1 = std::min(t1, tb);
            }
            if (!(t1 > t0)) continue;
            ++hits;
            stretch += 1.0 / std::max(-eyeDir.z, 0.05);
        }
    q.coverage = double(hits) / (n * n);
    q.slabStretch = hits > 0 ? stretch / hits : 1.0;
    return q;
}

double quadratureCost(const SlabQuadrature& q, double depthL0, VolumeRenderMode mode, bool tagged) {
    const double planes = std::max(1.0, std::ceil(depthL0 / q.planeSpacingL0));
    const int k = std::max(q.samplesPerPlane, 1);
    constexpr double fragment = 6.0; // a fragment's fixed cost, in lean samples
    double perSample = 1.0;
    double samples = k;
    if (mode == VolumeRenderMode::DVR) {
        const bool lean = k > 1 && !tagged && !q.preIntegrated;
        perSample = lean ? 1.0 : 1.5;
        if (q.preIntegrated) perSample *= 2.5; // two data fetches and a 2D table
        if (tagged) perSample *= 3.0;          // tag cell pieces
    } else {
        const bool lean = k > 1 && !tagged && !q.peaks;
        perSample = lean ? 1.0 : 1.5;
        if (q.peaks) samples += k == 1 ? 3.0 : 1.7 * q.planeSpacingL0; // voxel-centre crossings
    }
    return planes * (fragment + samples * perSample);
}

double predictImageRmse(SlabErrorModel& model, const QualityView& view, const SlabQuadrature& q) {
    SlabQuadrature stretched = q;
    stretched.planeSpacingL0 = roundedSpacing(q.planeSpacingL0 * view.slabStretch);
    const int dir = SlabErrorModel::nearestDirection(view.localDirection);
    return std::sqrt(std::clamp(view.coverage, 0.0, 1.0)) * model.rayRmse(dir, stretched);
}

QualityChoice chooseQuality(SlabErrorModel& model, const QualityView& view,
                            const QualityRequest& request) {
    const VolumeRenderMode mode = model.mode();
    const bool extreme = mode == VolumeRenderMode::MIP || mode == VolumeRenderMode::MINIP;
    // The kinds to try: DVR post-classified or pre-integrated; MIP/MINIP with or without the
    // voxel-centre crossings (unless the request fixes it).
    std::vector<bool> kinds;
    const std::optional<bool>& fixedKind = extreme ? request.peaks : request.preIntegrated;
    if (fixedKind)
        kinds.push_back(*fixedKind);
    else
        kinds = {false, true};

    QualityChoice best;
    double bestCost = std::numeric_limits<double>::infinity();
    QualityChoice leastError;
    leastError.predictedRmse = std::numeric_limits<double>::infinity();
    const double wanted = request.errorTarget * kTargetMargin;
    const bool single = request.numPlanes && request.samplesPerPlane;
    // Start where the signal's needs say the error is still large: a sixty-fourth of the rate
    // that gives the narrowest feature two samples.
    const double needs = model.needs().samplesPerL0;
    int lowest = kLowestStep;
    if (needs > 0.0)
        lowest =
            std::clamp(int(std::floor(2.0 * std::log2(needs / 64.0))), kLowestStep, kHighestStep);
    for (const bool kind : kinds) {
        const bool pre = !extreme && kind, peaks = extreme && kind;
        for (int j = lowest; j <= kHighestStep; ++j) {
            const SlabQuadrature q =
                quadratureFor(std::pow(2.0, 0.5 * j), pre, peaks, request, view, extreme);
            const double cost = quadratureCost(q, view.depthL0, mode, model.tagged());
            if (cost >= bestCost) break; // dearer than a choice that meets the target
            const double error = predictImageRmse(model, view, q);
            if (error < leastError.predictedRmse) {
                leastError.quadrature = q;
                leastError.predictedRmse = error;
            }
            if (error <= wanted) {
                best.quadrature = q;
                best.predictedRmse = error;
                bestCost = cost;
                break;
            }
            if (single) break;
        }
    }
    if (!std::isfinite(bestCost)) {
        best = leastError;
        best.meetsTarget = false;
    }
    best.direction = SlabErrorModel::nearestDirection(view.localDirection);
    return best;
}

} // namespace volsg
