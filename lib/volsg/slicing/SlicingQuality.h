#pragma once
// From an error target to the slicer's settings: the cheapest slab quadrature whose predicted
// error (SlabErrorModel) meets the target in this view, the explicit settings kept as given.

#include <array>
#include <optional>

#include <glm/glm.hpp>

#include <volsg/slicing/SlabErrorModel.h>

namespace volsg {

/// What a frame asks: the target and which settings are fixed (unset = automatic).
struct QualityRequest {
    double errorTarget = 0.5 / 255.0; ///< RMSE per channel of the image, 0..1 units
    std::optional<int> numPlanes;     ///< a plane count over the view's depth
    std::optional<int> samplesPerPlane;
    std::optional<bool> preIntegrated;
    std::optional<bool> peaks; ///< MIP, MINIP: mipPeaks
    bool refinePeaks = true;
};

/// The error model's directions a view is predicted along: the mean square of their RMSEs.
struct ModelDirections {
    std::array<int, SlabErrorModel::kNearDirections> dir{};
    int count = 0; ///< 0: the view's own (modelDirectionsOf)
};

/// A view's model directions. DVR: the kNearDirections narrow ones nearest its axis (sharing
/// one direction's rays), or for a view whose rays spread wider than kWideViewTangent (a
/// camera in or at the box) the wide ray set nearest it, whose slabs meet the box's faces as
/// such a view's do. MIP/MINIP: the one nearest, wide beyond kWideExtremeTangent, with all of
/// a direction's rays: their error sits on few pixels, and a third of the rays missed them
/// (ErrorTargetTest's thin shell: predicted 0.35/255, measured 0.52).
constexpr double kWideViewTangent = 0.6;
constexpr double kWideExtremeTangent = 0.2;
ModelDirections modelDirectionsOf(const glm::dvec3& localDirection, double coneTangent,
                                  VolumeRenderMode mode);

/// The view as the error depends on it.
struct QualityView {
    glm::dvec3 localDirection{0.0, 0.0, -1.0}; ///< the view axis in the volume's local frame
    double depthL0 = 1.0;     ///< the box's extent along the view axis, in L0 (local units)
    double coverage = 1.0;    ///< share of the image's pixels whose rays cross the box
    double slabStretch = 1.0; ///< mean ray length per unit of view depth (perspective: > 1)
    double coneTangent = 0.0; ///< tangent of the widest angle of a ray on the box to the axis
    /// What it is predicted along when set (an interactive frame's directions the model has
    /// cast, castDirectionsNear); unset: the view's own (modelDirectionsOf).
    ModelDirections directions;
};

/// The directions a view is predicted along in `mode`: view.directions when set, else its own.
ModelDirections directionsOf(const QualityView& view, VolumeRenderMode mode);

/// A view's directions without casting rays for a new one: those of its own the model has
/// cast; when none is, the nearest cast within `maxDegrees` of the view (of the same ray set);
/// when none is, its own (the prediction casts them).
ModelDirections castDirectionsNear(const SlabErrorModel& model, const QualityView& view,
                                   double maxDegrees);

/// The view of a volume box [-halfExtent, halfExtent] under `modelView` (local to eye) and
/// `projection`: its axis, its depth in L0, and over a 24 x 24 grid of pixel rays the share
/// that crosses the box and their mean length per unit of view depth.
QualityView qualityViewOf(const glm::dmat4& modelView, const glm::dmat4& projection,
                          const glm::dvec3& halfExtent, double L0);

struct QualityChoice {
    SlabQuadrature quadrature;  ///< plane spacing (L0, along the view), samples, methods
    double predictedRmse = 0.0; ///< of the image, 0..1 units
    bool meetsTarget = true;
    int direction = 0; ///< SlabErrorModel's direction used (the first of the view's)
};

/// The image RMSE the model predicts for quadrature q in this view: sqrt(coverage) times the
/// RMSE of the rays through the box along the view's directions (the root of their mean
/// square), with slabs stretched as perspective rays stretch them.
double predictImageRmse(SlabErrorModel& model, const QualityView& view, const SlabQuadrature& q);
/// predictImageRmse if it is at most `limit`, else a value above `limit` and at most it (the
/// evaluation stops once the rays seen prove the limit passed).
double predictImageRmseUpTo(SlabErrorModel& model, const QualityView& view, const SlabQuadrature& q,
                            double limit);

/// Shear-warp's RMSE per channel (SlabErrorModel::preClassifiedRmse) along `directions`: the
/// root of their mean square, of the rays through the box (scale by sqrt(coverage) for the
/// image).
double preClassifiedRmseAlong(SlabErrorModel& model, const ModelDirections& directions,
                              int sliceStep);
/// Whether every one of `directions` is cast (a prediction along them is cheap).
bool directionsCast(const SlabErrorModel& model, const ModelDirections& directions);

/// The chooser takes the model's prediction against this share of the target. DVR: 1, the
/// prediction as it is. Over the volumes sweep's fixed settings it came out between 0.54 and 6.8
/// times the measured error (10% below 0.97, median 1.25), so a margin below 1 paid twice for
/// safety: at 0.9 every default frame of the sweep met its target at most 0.95 of it, and 5 of its
/// 30 rows were over 1.5x the fastest fixed setting that met it; at 1, 3 (README, session 15).
/// MIP/MINIP keep 0.7: their error sits on few pixels (the chest CT: 75% of it in 0.1% of them),
/// and at 0.9 Marschner-Lobb 256^3's default MIP measured 0.29/255, over VTK's 0.256 (README,
/// "Error targets", session 13).
double qualityTargetMargin(VolumeRenderMode mode);

/// The cheapest quadrature (by the cost model in SlicingQuality.cpp) whose predicted image RMSE
/// is at most qualityTargetMargin times the target, among those the request leaves free. When the
/// target is below the model's floor (measured on each kind's dearest candidates), the cheapest
/// within 1.2 times that floor (meetsTarget false); the one with the least error found if even that
/// fails.
QualityChoice chooseQuality(SlabErrorModel& model, const QualityView& view,
                            const QualityRequest& request);

/// The relative cost of drawing quadrature q over a view depth of `depthL0` (fragments times
/// their samples; the weights are llvmpipe's, lib/volsg/slicing/README.md).
double quadratureCost(const SlabQuadrature& q, double depthL0, VolumeRenderMode mode, bool tagged);

} // namespace volsg
