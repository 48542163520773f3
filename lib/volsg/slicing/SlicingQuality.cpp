// The slicer's settings from an error target (see SlicingQuality.h).
#include <volsg/slicing/SlicingQuality.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace volsg {

namespace {

/// Samples per plane tried for automatic settings (powers of two), and the fewest planes an
/// automatic layout has across the view's depth (one: a single slab of many samples, which
/// the model predicts like any other). Up to the shader's 256: the chest CT's default DVR
/// frame went from 12 planes x 64 to 7 x 128, 123-134 -> 99-105 ms at 0.26/255, and its MIP
/// from 0.45/255 to 0.26/255 at 76 ms, not 80 (README, session 12).
constexpr int kMaxAutoSamples = 256;
constexpr double kMinAutoPlanes = 1.0;
/// Samples per L0 searched: 2^(j/2) for j in [kLowestStep, kHighestStep].
constexpr int kLowestStep = -16; // 1/256
constexpr int kHighestStep = 10; // 32

/// A target below the model's floor (the least error any candidate reaches: table and data
/// quantisation, or the model's own resolution, put it there) is met by no candidate, and the
/// search would evaluate every one nearly to its last ray and then again exactly (a 24^3 thin
/// shell beside a Cone: 48 full evaluations' work, 3.5 s). So when the search has done this
/// many full evaluations' work at the top rate, or is about to give up, it measures the floor.
/// Searches that meet their target do at most 0.7 evaluations' work on the examples and the
/// node suite's DVR views; the chest CT's hardest MIP views about 30.
constexpr double kFloorCheckEvaluations = 3.0;
/// Below the floor, the cheapest candidate within this factor of it is drawn.
constexpr double kFloorSlack = 1.2;
/// The floor is sought along the walk of this many samples a plane (or the most below it):
/// denser slabs' parts are no finer at the top rates, and their floor came out higher (the
/// 24^3 thin shell: 0.21/255 along the 256-sample walk, 0.17 along the 64-sample one).
constexpr int kFloorSamples = 64;

/// Spacing rounded to 3 significant digits, so views that differ a little share a cache key.
double roundedSpacing(double s) {
    if (!(s > 0.0)) return s;
    const double e = std::pow(10.0, std::floor(std::log10(s)) - 2.0);
    return std::round(s / e) * e;
}

/// The quadrature of `samplesPerL0` with `samples` per plane for one kind (pre-integrated, or
/// peaks), or with the request's fixed plane count.
SlabQuadrature quadratureFor(double samplesPerL0, int samples, bool preIntegrated, bool peaks,
                             const QualityRequest& r, const QualityView& view) {
    SlabQuadrature q;
    q.preIntegrated = preIntegrated;
    q.peaks = peaks;
    q.refinePeaks = r.refinePeaks;
    if (r.numPlanes) {
        // Not rounded (predictImageRmseUpTo rounds what it evaluates): a spacing rounded below
        // depth / numPlanes would count one plane more than the slicer draws.
        q.planeSpacingL0 = view.depthL0 / std::max(*r.numPlanes, 1) * (1.0 + 1e-9);
        q.samplesPerPlane =
            r.samplesPerPlane
                ? *r.samplesPerPlane
                : std::clamp(int(std::ceil(samplesPerL0 * q.planeSpacingL0 - 1e-9)), samples, 256);
        return q;
    }
    q.samplesPerPlane = samples;
    q.planeSpacingL0 = double(samples) / samplesPerL0;
    return q;
}

} // namespace

ModelDirections modelDirectionsOf(const glm::dvec3& localDirection, double coneTangent,
                                  VolumeRenderMode mode) {
    ModelDirections out;
    const bool extreme = mode == VolumeRenderMode::MIP || mode == VolumeRenderMode::MINIP;
    if (extreme || coneTangent > kWideViewTangent) { // one direction, narrow or wide
        out.dir[0] = SlabErrorModel::nearestDirection(
            localDirection, coneTangent > (extreme ? kWideExtremeTangent : kWideViewTangent));
        out.count = 1;
        return out;
    }
    out.dir = SlabErrorModel::nearestDirections(localDirection);
    out.count = SlabErrorModel::kNearDirections;
    return out;
}

ModelDirections directionsOf(const QualityView& view, VolumeRenderMode mode) {
    return view.directions.count > 0
               ? view.directions
               : modelDirectionsOf(view.localDirection, view.coneTangent, mode);
}

ModelDirections castDirectionsNear(const SlabErrorModel& model, const QualityView& view,
                                   double maxDegrees) {
    const ModelDirections own = directionsOf(view, model.mode());
    ModelDirections cast;
    for (int i = 0; i < own.count; ++i)
        if (model.hasDirection(own.dir[std::size_t(i)]))
            cast.dir[std::size_t(cast.count++)] = own.dir[std::size_t(i)];
    if (cast.count > 0) return cast;
    const bool wide = own.dir[0] >= SlabErrorModel::kDirections;
    const int near = model.castDirectionNear(view.localDirection, wide, maxDegrees);
    if (near < 0) return own;
    cast.dir[0] = near;
    cast.count = 1;
    return cast;
}

double preClassifiedRmseAlong(SlabErrorModel& model, const ModelDirections& directions,
                              int sliceStep) {
    double sum = 0.0;
    for (int i = 0; i < directions.count; ++i) {
        const double e = model.preClassifiedRmse(directions.dir[std::size_t(i)], sliceStep);
        sum += e * e;
    }
    return std::sqrt(sum / double(std::max(directions.count, 1)));
}

bool directionsCast(const SlabErrorModel& model, const ModelDirections& directions) {
    for (int i = 0; i < directions.count; ++i)
        if (!model.hasDirection(directions.dir[std::size_t(i)])) return false;
    return true;
}

double qualityTargetMargin(VolumeRenderMode mode) {
    return mode == VolumeRenderMode::MIP || mode == VolumeRenderMode::MINIP ? 0.7 : 1.0;
}

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
            const double c = std::max(-eyeDir.z, 0.05);
            stretch += 1.0 / c;
            q.coneTangent = std::max(q.coneTangent, std::sqrt(std::max(0.0, 1.0 - c * c)) / c);
        }
    q.coverage = double(hits) / (n * n);
    q.slabStretch = hits > 0 ? stretch / hits : 1.0;
    return q;
}

double quadratureCost(const SlabQuadrature& q, double depthL0, VolumeRenderMode mode, bool tagged) {
    // Fitted to llvmpipe's times, in units of one lean sample of the same mode (README, "Error
    // targets": the fixed grids of the chest CT and Marschner-Lobb 256^3 at 512 x 512 and of
    // the 64^3 sweep cases at 128 x 128). DVR: a plane's fragments cost about 8.7 lean
    // samples (rasterisation, slab set-up, the float blend); a pre-integrated sample 3.2 (two
    // data fetches and a 2D table, the general loop); a general-loop sample 1.5; a tagged
    // sample 4.5. MIP/MINIP: a lean sample is a fetch and a compare, so the rest weighs more:
    // a plane 22, a general-loop sample 6, a voxel-centre crossing 3 (in the lean loop 1, as
    // a sample: they are a row of evenly spaced fetches per axis).
    const double planes = std::max(1.0, std::ceil(depthL0 / q.planeSpacingL0 - 1e-9));
    const int k = std::max(q.samplesPerPlane, 1);
    if (mode == VolumeRenderMode::DVR) {
        const bool lean = k > 1 && !tagged && !q.preIntegrated;
        // Tagged: the tag-cell split dominates either way (measured on the labelled 64^3 sweep
        // case, a pre-integrated sample cost what a post-classified one did).
        const double perSample = tagged ? 4.5 : q.preIntegrated ? 3.2 : lean ? 1.0 : 1.5;
        return planes * (8.7 + k * perSample);
    }
    // The lean loop with peaks sets up each slab's cell walks and crossing rows: a plane costs
    // about 80 there (chest CT, 0.5 middles per L0 and every crossing: 13.5 planes 86 ms,
    // 7 79, 4 71, 2 47, 1 46).
    const bool lean = k > 1 && !tagged;
    double perPlane = (lean && q.peaks ? 80.0 : 22.0) + k * (lean ? 1.0 : 6.0);
    if (q.peaks) // the crossings
        perPlane += k == 1 ? 3.0 * 3.0 : (lean ? 1.0 : 3.0) * 1.7 * q.planeSpacingL0;
    return planes * perPlane;
}

double predictImageRmse(SlabErrorModel& model, const QualityView& view, const SlabQuadrature& q) {
    return predictImageRmseUpTo(model, view, q, std::numeric_limits<double>::infinity());
}

double predictImageRmseUpTo(SlabErrorModel& model, const QualityView& view, const SlabQuadrature& q,
                            double limit) {
    const double scale = std::sqrt(std::clamp(view.coverage, 0.0, 1.0));
    if (!(scale > 0.0)) return 0.0;
    const ModelDirections dirs = directionsOf(view, model.mode());
    // The slicer lays ceil(depth / spacing) planes over the view's depth. A model direction
    // (up to 15 degrees off) sees the box deeper or shallower: it lays as many planes over its
    // own depth, or a layout of one or two planes would be predicted with two or three.
    const double planes = std::max(1.0, std::ceil(view.depthL0 / q.planeSpacingL0 - 1e-9));
    const double topRate = std::pow(2.0, 0.5 * kHighestStep);
    // The mean square over the directions is over limit^2 once their sum is over n limit^2:
    // each direction is evaluated up to what the sum has left.
    const double limitSum = double(dirs.count) * (limit / scale) * (limit / scale);
    double sum = 0.0;
    for (int i = 0; i < dirs.count; ++i) {
        const int dir = dirs.dir[std::size_t(i)];
        SlabQuadrature stretched = q;
        // (Rounding spacings to 3 digits moves them by at most 0.5%: 0.6% more keeps the count.)
        stretched.planeSpacingL0 = model.depthL0(dir) / planes * 1.006;
        // A narrow ray set stretches its slabs as the view's rays do on average; a wide set's
        // rays spread and stretch as such a view's.
        if (dir < SlabErrorModel::kDirections) stretched.planeSpacingL0 *= view.slabStretch;
        stretched.planeSpacingL0 = roundedSpacing(stretched.planeSpacingL0);
        // Denser than the search's top rate (numPlanes 100000, samplesPerPlane 256): predicted
        // at that rate, an upper bound, so the model's work stays bounded.
        if (stretched.samplesPerL0() > topRate)
            stretched.planeSpacingL0 = roundedSpacing(stretched.samplesPerPlane / topRate);
        const double left = limitSum - sum;
        const double e = model.rayRmseUpTo(dir, stretched, std::sqrt(std::max(left, 0.0)));
        sum += e * e;
        if (sum > limitSum) break; // proven over the limit
    }
    return scale * std::sqrt(sum / double(std::max(dirs.count, 1)));
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
        kinds = {true, false}; // pre-integrated (peaks) first: it wins ties
    // Samples per plane to try: the request's, or (planes automatic) powers of two; with a
    // fixed plane count the samples follow the rate.
    std::vector<int> sampleCounts;
    if (request.samplesPerPlane)
        sampleCounts.push_back(*request.samplesPerPlane);
    else if (request.numPlanes)
        sampleCounts.push_back(1);
    else
        for (int k = 1; k <= kMaxAutoSamples; k *= 2)
            sampleCounts.push_back(k);

    // One walk per (kind, sample count) up the sampling rates. The candidates of all walks are
    // evaluated cheapest first (a walk's cost rises with its rate), and the first that meets
    // the target is the answer: the cheapest of the walks' first candidates to meet it, found
    // with no candidate dearer than it evaluated (proving a candidate meets the target reads
    // every ray; proving a miss usually reads a few).
    struct Walk {
        bool pre = false, peaks = false;
        int samples = 1;
        int step = kLowestStep;
        SlabQuadrature q;
        double cost = 0.0;
    };
    const bool single = request.numPlanes && request.samplesPerPlane;
    const double startWork = model.samplesEvaluated();
    // Moves walk w to its next candidate at or after its step; false when it has none.
    const auto settle = [&](Walk& w) {
        for (; w.step <= kHighestStep; ++w.step) {
            w.q = quadratureFor(std::pow(2.0, 0.5 * w.step), w.samples, w.pre, w.peaks, request,
                                view);
            // Spacings beyond the view's depth all draw one plane: only the densest of them
            // (within a rate step, sqrt 2, of the depth) is worth evaluating.
            if (!request.numPlanes &&
                view.depthL0 / w.q.planeSpacingL0 < kMinAutoPlanes / std::sqrt(2.0) &&
                w.step < kHighestStep)
                continue;
            w.cost = quadratureCost(w.q, view.depthL0, mode, model.tagged());
            return true;
        }
        return false;
    };
    std::vector<Walk> walks;
    for (const bool kind : kinds)
        for (const int samples : sampleCounts) {
            // Refinement takes the neighbours of a slab's top: it needs two samples a plane.
            if (extreme && !kind && request.refinePeaks && samples < 2 && !request.samplesPerPlane)
                continue;
            Walk w;
            w.pre = !extreme && kind;
            w.peaks = extreme && kind;
            w.samples = samples;
            if (settle(w)) walks.push_back(w);
        }

    QualityChoice best;
    bool found = false;
    const double topRate = std::pow(2.0, 0.5 * kHighestStep);
    const ModelDirections dirs = directionsOf(view, model.mode());
    bool floorChecked = single || request.numPlanes.has_value();
    double floorCheckWork = 0.0;
    if (!floorChecked)
        for (int i = 0; i < dirs.count; ++i)
            floorCheckWork += kFloorCheckEvaluations *
                              model.samplesOfFullEvaluation(dirs.dir[std::size_t(i)], topRate);
    // Candidates that missed the target, with their error or a lower bound of it (an
    // evaluation stops once it proves the target missed): the least error among them is
    // found exactly only when nothing meets the target.
    std::vector<std::pair<double, SlabQuadrature>> missed;
    const double targetWanted = request.errorTarget * qualityTargetMargin(mode);
    double wanted = targetWanted;
    std::vector<bool> ended(walks.size(), false);
    const auto openWalk = [&] { // the cheapest open walk (ties: the earlier), or walks.size()
        std::size_t next = walks.size();
        for (std::size_t i = 0; i < walks.size(); ++i)
            if (!ended[i] && (next == walks.size() || walks[i].cost < walks[next].cost)) next = i;
        return next;
    };
    // The model's floor, from exact errors of each kind's dearest candidates; it stops at one
    // within `enough` (then the search goes on as it was).
    const auto floorOf = [&](double enough) {
        double floor = std::numeric_limits<double>::infinity();
        for (const bool kind : kinds) {
            if (floor <= enough) break;
            const Walk* densest = nullptr;
            for (const Walk& w : walks)
                if ((extreme ? w.peaks : w.pre) == kind && w.samples <= kFloorSamples &&
                    (!densest || w.samples > densest->samples))
                    densest = &w;
            if (!densest) continue;
            // The error is not monotone in the rate near the floor (pre-integration's table
            // adds a little per segment): the least of the top five rates, and at that rate
            // every sample count of the kind.
            const auto at = [&](const Walk& w, int step) {
                return predictImageRmse(model, view,
                                        quadratureFor(std::pow(2.0, 0.5 * step), w.samples, w.pre,
                                                      w.peaks, request, view));
            };
            int bestStep = kHighestStep;
            double least = std::numeric_limits<double>::infinity();
            for (int step = kHighestStep; step > kHighestStep - 5 && !(least <= enough); --step)
                if (const double e = at(*densest, step); e < least) {
                    least = e;
                    bestStep = step;
                }
            for (const Walk& w : walks)
                if (&w != densest && (extreme ? w.peaks : w.pre) == kind && !(least <= enough))
                    least = std::min(least, at(w, bestStep));
            floor = std::min(floor, least);
        }
        return floor;
    };
    while (!found) {
        // When the search has worked long, or is about to give up, it checks the floor.
        if (!floorChecked &&
            (model.samplesEvaluated() - startWork > floorCheckWork || openWalk() == walks.size())) {
            floorChecked = true;
            const double floor = floorOf(wanted);
            if (floor > wanted && std::isfinite(floor)) {
                // Out of reach: search again, from the cheapest, for a candidate near the floor.
                wanted = kFloorSlack * floor;
                missed.clear();
                for (std::size_t i = 0; i < walks.size(); ++i) {
                    walks[i].step = kLowestStep;
                    ended[i] = !settle(walks[i]);
                }
                continue;
            }
        }
        const std::size_t next = openWalk();
        if (next == walks.size()) break;
        Walk& w = walks[next];
        const double error = predictImageRmseUpTo(model, view, w.q, wanted);
        if (error <= wanted) {
            best.quadrature = w.q;
            best.predictedRmse = error;
            best.meetsTarget = error <= targetWanted;
            found = true;
            break;
        }
        missed.emplace_back(error, w.q);
        ++w.step;
        if (single || !settle(w)) ended[next] = true;
    }
    if (!found) {
        // The least error: exact values in the order of their bounds, until no bound is lower.
        std::sort(missed.begin(), missed.end(),
                  [](const auto& a, const auto& b) { return a.first < b.first; });
        best.predictedRmse = std::numeric_limits<double>::infinity();
        for (const auto& [bound, q] : missed) {
            if (!(bound < best.predictedRmse)) break;
            const double error = predictImageRmse(model, view, q);
            if (error < best.predictedRmse) {
                best.quadrature = q;
                best.predictedRmse = error;
            }
        }
        best.meetsTarget = false;
    }
    best.direction = dirs.dir[0];
    return best;
}

} // namespace volsg
