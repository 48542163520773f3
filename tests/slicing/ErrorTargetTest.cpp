// Error targets: the slicer's error model predicts the measured error, the Volume node chooses
// settings that meet its target, explicit fields override the choice, and pre-integration
// works for tagged volumes (lib/volsg/slicing/README.md, "Error targets").
#include "SlicingTestSupport.h"

#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/Volume.h>
#include <volsg/slicing/SlabErrorModel.h>
#include <volsg/slicing/SlicingQuality.h>

using namespace volsg;
using namespace volsg::test;

namespace {

/// The model's prediction is checked against the measurement within this factor either way.
constexpr double kPredictionFactor = 3.0;

/// All of the quality fixed (so the node draws exactly this) with a target, so that the error
/// of exactly this setting is predicted.
SlicingSettings fixed(int planes, int samples, bool preIntegrated) {
    SlicingSettings s;
    s.numPlanes = planes;
    s.samplesPerPlane = samples;
    s.preIntegrated = preIntegrated;
    s.fixedSamplesPerPlane = s.fixedPreIntegrated = s.fixedMipPeaks = true;
    s.errorTarget = s.interactiveErrorTarget = 0.5 * k8Bit;
    return s;
}

SlicingSettings automatic(double targetIn255) {
    SlicingSettings s;
    s.errorTarget = targetIn255 * k8Bit;
    s.interactiveErrorTarget = 4.0 * targetIn255 * k8Bit;
    return s;
}

/// The issue's volume: 37 x 23 x 19 USHORT, spacing 1 x 1.5 x 2.5, a smooth blob, under one
/// narrow spike of opacity (0 -> 0.9 -> 0 over 10% of the range).
RayCastVolume anisotropicSpike() {
    auto grid = makeGrid({37, 23, 19}, VoxelType::UShort, {1.0, 1.5, 2.5},
                         [](const glm::dvec3& p) { return std::exp(-glm::dot(p, p) / 0.25); });
    return volumeOf(grid, transferFunction(spike(0.45, 0.5, 0.55, 0.9), {{0, 1}, {1, 1}},
                                           {{0, 0.7}, {1, 0.7}}, {{0, 0.3}, {1, 0.3}}));
}

void checkPrediction(const Comparison& c, const std::string& what) {
    const double predicted = c.stats.predictedRmse;
    const double measured = c.difference.rmse;
    MESSAGE(what << ": predicted " << predicted / k8Bit << "/255, measured " << measured / k8Bit
                 << "/255");
    REQUIRE(predicted >= 0.0);
    // Errors below 0.02/255 are at the level of float arithmetic and table steps, which the
    // model does not try to predict: only an upper bound is checked there.
    if (measured < 0.02 * k8Bit) {
        CHECK(predicted < 0.1 * k8Bit);
        return;
    }
    CHECK(predicted < kPredictionFactor * measured);
    CHECK(predicted > measured / kPredictionFactor);
}

} // namespace

TEST_CASE_FIXTURE(GlFixture, "the error model predicts the measured error of fixed settings") {
    const RayCastVolume ml = marschnerLobbVolume();
    auto camera = framing(*ml.data, {0.3f, 0.5f, 1.0f});
    checkPrediction(compareGrid(renderer, ml, fixed(12, 1, false), *camera, 48), "ML 12 x 1");
    checkPrediction(compareGrid(renderer, ml, fixed(6, 4, false), *camera, 48), "ML 6 x 4");
    checkPrediction(compareGrid(renderer, ml, fixed(12, 1, true), *camera, 48), "ML 12 x 1 pre");
    const RayCastVolume sp = anisotropicSpike();
    auto spikeCamera = framing(*sp.data, {0.6f, 0.4f, 1.0f});
    checkPrediction(compareGrid(renderer, sp, fixed(40, 1, false), *spikeCamera, 48),
                    "spike 40 x 1");
    checkPrediction(compareGrid(renderer, sp, fixed(10, 8, false), *spikeCamera, 48),
                    "spike 10 x 8");
    checkPrediction(compareGrid(renderer, sp, fixed(20, 1, true), *spikeCamera, 48),
                    "spike 20 x 1 pre");
}

TEST_CASE_FIXTURE(GlFixture, "the default meets its target on the anisotropic 16-bit spike") {
    // The issue's default (2 samples per voxel, one per plane) gave 12.6/255 on its volume; on
    // this blob it misses the default target too.
    const RayCastVolume sp = anisotropicSpike();
    auto camera = framing(*sp.data, {0.6f, 0.4f, 1.0f});
    for (const double target : {0.5, 2.0}) {
        const Comparison c = compareGrid(renderer, sp, automatic(target), *camera, 64);
        MESSAGE("target " << target << "/255: " << c.stats.planes << " planes x "
                          << c.stats.samplesPerPlane
                          << std::string(c.stats.preIntegrated ? " pre-int" : "") << ", predicted "
                          << c.stats.predictedRmse / k8Bit << "/255, measured "
                          << c.difference.rmse / k8Bit << "/255");
        CHECK(c.stats.meetsTarget);
        CHECK(c.difference.rmse <= target * k8Bit);
    }
    // Without a target: the old fixed rule, far off on this transfer function.
    const Comparison old = compareGrid(renderer, sp, SlicingSettings{}, *camera, 64);
    MESSAGE("no target: " << old.stats.planes << " planes, " << old.difference.rmse / k8Bit
                          << "/255");
    CHECK(old.stats.predictedRmse < 0.0);
    CHECK(old.difference.rmse > 0.5 * k8Bit);
}

TEST_CASE_FIXTURE(GlFixture, "the default meets its target from inside the volume") {
    // Rays that begin at the near plane inside the data are not the model's rays through the
    // whole box: the search asks for half the target there, as with clip planes. Three spikes
    // on Marschner-Lobb 33^3, a wide view from inside (without the halving: 0.54/255 at 0.5).
    const RayCastVolume v = volumeOf(makeMarschnerLobb(33, VoxelType::UShort),
                                     transferFunction({{0, 0},
                                                       {0.2, 0},
                                                       {0.22, 0.4},
                                                       {0.24, 0},
                                                       {0.5, 0},
                                                       {0.52, 0.4},
                                                       {0.54, 0},
                                                       {0.8, 0},
                                                       {0.82, 0.4},
                                                       {0.84, 0},
                                                       {1, 0}},
                                                      {{0, 0.1}, {1, 1}}, {{0, 0.8}, {1, 0.3}}));
    auto camera = perspectiveAt({0.15f, -0.1f, 0.3f}, 1.4f, 0.02f, 10.0f);
    for (const double target : {0.5, 2.0}) {
        const Comparison c = compareGrid(renderer, v, automatic(target), *camera, 64);
        MESSAGE("inside, target " << target << "/255: " << c.stats.planes << " planes x "
                                  << c.stats.samplesPerPlane << ", predicted "
                                  << c.stats.predictedRmse / k8Bit << "/255, measured "
                                  << c.difference.rmse / k8Bit << "/255");
        CHECK(c.difference.rmse <= target * k8Bit);
    }
}

TEST_CASE_FIXTURE(GlFixture, "a thin shell's MIP meets its target at once") {
    // examples/volumes/thin-shell-mip.iv: a shell 1.5 voxels thick, whose brightest points lie
    // where rays cross voxel centres. The model's own extreme once sampled only every L0 / 8
    // and came out below them, so every candidate looked 0.8/255 off: the search ran through
    // all of them (2.1 s) and drew a setting measured at 0.74/255, "not met".
    TransferFunction1D tf = transferFunction({{0, 0}, {1, 1}}, {{0, 0}, {1, 1}}, {{0, 0}, {1, 0.9}},
                                             {{0, 0}, {1, 0.6}});
    const RayCastVolume shell = volumeOf(makeThinShell(64, 0.35 * 64), tf, VolumeRenderMode::MIP);
    auto camera = framing(*shell.data, {0.3f, 0.45f, 1.0f});
    const Comparison c = compareGrid(renderer, shell, automatic(0.5), *camera, 96);
    MESSAGE("thin shell MIP: " << c.stats.planes << " planes x " << c.stats.samplesPerPlane
                               << ", predicted " << c.stats.predictedRmse / k8Bit
                               << "/255, measured " << c.difference.rmse / k8Bit << "/255, choice "
                               << c.stats.qualityMilliseconds << " ms");
    CHECK(c.stats.meetsTarget);
    CHECK(c.difference.rmse <= 0.5 * k8Bit);
}

TEST_CASE("below the model's floor the search draws near the floor, with bounded work") {
    // A 24^3 thin shell under the default (identity) transfer function: its error does not go
    // below about 0.2/255 at any rate. Asked for 0.1/255, the search once evaluated all 210
    // candidates nearly to their last ray (3.5 s beside a Cone, which halves the target).
    TransferFunction1D identity;
    const RayCastVolume shell = volumeOf(makeThinShell(24, 0.35 * 24), identity);
    SlabErrorModel model(shell);
    QualityView view;
    view.localDirection = glm::normalize(glm::dvec3(0.3, 0.5, -1.0));
    view.depthL0 = model.depthL0(SlabErrorModel::nearestDirection(view.localDirection));
    view.coverage = 0.44;
    const double target = 0.1 / 255.0;
    const QualityChoice c =
        chooseQuality(model, view, QualityRequest{target, {}, {}, {}, {}, true});
    double full = 0.0; // one evaluation of every ray of the view's directions at the top rate
    const ModelDirections dirs = directionsOf(view, model.mode());
    for (int i = 0; i < dirs.count; ++i)
        full += model.samplesOfFullEvaluation(dirs.dir[std::size_t(i)], 32.0);
    const double work = model.samplesEvaluated() / full;
    // The best of a spread of candidates, exactly (after the choice: its cache is warm).
    double best = 1e300;
    for (const bool pre : {false, true})
        for (const int k : {2, 8, 32, 64})
            for (const double rate : {4.0, 8.0, 16.0, 32.0}) {
                SlabQuadrature q;
                q.samplesPerPlane = k;
                q.planeSpacingL0 = k / rate;
                q.preIntegrated = pre;
                best = std::min(best, predictImageRmse(model, view, q));
            }
    MESSAGE("floor case: predicted " << c.predictedRmse * 255.0 << "/255, best of the spread "
                                     << best * 255.0 << "/255, work " << work
                                     << " full evaluations");
    CHECK_FALSE(c.meetsTarget);
    CHECK(best > 0.7 * target); // really below the floor
    CHECK(c.predictedRmse <= 1.25 * best);
    // (18 walks, 1..256 samples a plane, take 20 full evaluations: bounded; it was 48.)
    CHECK(work < 24.0);
}

TEST_CASE_FIXTURE(GlFixture, "a looser target draws fewer samples") {
    const RayCastVolume ml = marschnerLobbVolume();
    auto camera = framing(*ml.data, {0.3f, 0.5f, 1.0f});
    const Comparison tight = compareGrid(renderer, ml, automatic(0.1), *camera, 48);
    const Comparison loose = compareGrid(renderer, ml, automatic(2.0), *camera, 48);
    const auto samples = [](const SlicingStats& s) { return s.samplesPerPlane / s.planeSpacingL0; };
    MESSAGE("0.1/255: " << samples(tight.stats) << " samples per L0, measured "
                        << tight.difference.rmse / k8Bit << "; 2/255: " << samples(loose.stats)
                        << ", measured " << loose.difference.rmse / k8Bit);
    CHECK(samples(loose.stats) < samples(tight.stats));
    CHECK(tight.difference.rmse <= 0.1 * k8Bit);
    CHECK(loose.difference.rmse <= 2.0 * k8Bit);
    // Interactive frames take their own target (4x here).
    const Comparison interactive =
        compareGrid(renderer, ml, automatic(0.1), *camera, 48, glm::vec3(0.0f), true);
    CHECK(samples(interactive.stats) < samples(tight.stats));
    CHECK(interactive.stats.errorTarget == doctest::Approx(0.4 * k8Bit));
}

TEST_CASE_FIXTURE(GlFixture, "an interactive frame reuses a near direction the model has cast") {
    // Casting a new direction costs more than an interactive frame: a view within 30 degrees of
    // one cast is predicted along that one. Still frames and far views cast their own.
    const RayCastVolume ml = marschnerLobbVolume();
    auto root = Separator::create();
    auto node = GridVolume::create();
    node->description = ml;
    node->settings = automatic(0.5);
    root->addChild(node);
    RenderOptions options;
    options.width = options.height = 48;
    const auto frameFrom = [&](const glm::vec3& direction, bool interactive) {
        const ref_ptr<PerspectiveCamera> camera = framing(*ml.data, direction);
        options.camera = camera;
        options.interactive = interactive;
        Comparison c;
        c.gl = renderer.render(*root, options);
        c.stats = node->stats;
        c.reference = referenceImage(rayCamera(*camera, 48, 48), {ml}, glm::dvec3(0.0));
        c.difference = difference(c.gl, c.reference);
        return c;
    };
    const Comparison still = frameFrom({0.3f, 0.5f, 1.0f}, false);
    const int cast = still.stats.modelDirections;
    CHECK(cast >= 1);
    // 13 degrees away, nearest to another of the model's directions, interactive: no direction
    // cast, the interactive target still met.
    const glm::dvec3 first(0.3, 0.5, 1.0), second(0.6, 0.5, 1.0);
    REQUIRE(SlabErrorModel::nearestDirection(first) != SlabErrorModel::nearestDirection(second));
    const Comparison near = frameFrom(glm::vec3(second), true);
    CHECK(near.stats.modelDirections == cast);
    CHECK(near.stats.errorTarget == doctest::Approx(2.0 * k8Bit)); // 4x the still target
    CHECK(near.difference.rmse <= near.stats.errorTarget);
    // The same view still: its own direction.
    const Comparison nearStill = frameFrom(glm::vec3(second), false);
    CHECK(nearStill.stats.modelDirections > cast);
    // Far from any cast direction, interactive: cast.
    const int before = nearStill.stats.modelDirections;
    const Comparison far = frameFrom({1.0f, -0.2f, 0.1f}, true);
    CHECK(far.stats.modelDirections > before);
    CHECK(far.difference.rmse <= far.stats.errorTarget);
}

TEST_CASE_FIXTURE(GlFixture, "the node's explicit fields override the choice") {
    const std::string head =
        "#Inventor V2.1 ascii\nSeparator {\n"
        "  PerspectiveCamera { position 0 0 3 heightAngle 0.9 }\n"
        "  VolumeData { generator MARSCHNER_LOBB dimensions 24 24 24 }\n"
        "  TransferFunction { alpha [ 0 0, 0.475 0, 0.5 0.6, 0.525 0, 1 0 ] }\n";
    auto render = [&](const std::string& fields) {
        ref_ptr<Node> root =
            readSceneFromString(head + "  DEF V Volume { " + fields + " }\n}\n", "override.iv");
        RenderOptions options;
        options.width = options.height = 32;
        renderer.render(*root, options);
        Volume* v = nullptr;
        for (const auto& child : *root->children())
            if (child->isA<Volume>()) v = static_cast<Volume*>(child.get());
        REQUIRE(v);
        return v->slicingStats();
    };
    const SlicingStats chosen = render("");
    MESSAGE("automatic: " << chosen.planes << " x " << chosen.samplesPerPlane
                          << std::string(chosen.preIntegrated ? " pre-int" : ""));
    CHECK(chosen.predictedRmse >= 0.0);
    const SlicingStats all = render("numPlanes 40 samplesPerPlane 3 preIntegrated TRUE");
    CHECK(all.planes == 40);
    CHECK(all.samplesPerPlane == 3);
    CHECK(all.preIntegrated);
    CHECK(all.predictedRmse >= 0.0); // still predicted and reported
    // Written at their default values they are still explicit.
    const SlicingStats defaults = render("samplesPerPlane 1 preIntegrated FALSE");
    CHECK(defaults.samplesPerPlane == 1);
    CHECK_FALSE(defaults.preIntegrated);
    // No target: the fixed rules (2 samples per voxel along the view, no prediction).
    const SlicingStats none = render("errorTarget 0");
    CHECK(none.predictedRmse < 0.0);
    CHECK(none.samplesPerPlane == 1);
    CHECK(none.planeSpacingL0 == doctest::Approx(0.5).epsilon(0.05));
    CHECK(render("errorTarget -1").predictedRmse < 0.0);
}

TEST_CASE_FIXTURE(GlFixture, "pre-integration works for tagged volumes") {
    const RayCastVolume v =
        labelledVolume(20, {{-1, transferFunction(spike(0.3, 0.35, 0.4, 0.5))},
                            {1, transferFunction(spike(0.6, 0.65, 0.7, 0.9), {{0, 1}, {1, 1}},
                                                 {{0, 0.2}, {1, 0.2}}, {{0, 0}, {1, 0}})},
                            {2, transferFunction(spike(0.2, 0.3, 0.4, 0.7), {{0, 0}, {1, 0}},
                                                 {{0, 1}, {1, 1}}, {{0, 0.3}, {1, 0.3}})}});
    auto camera = framing(*v.data, {0.4f, 0.6f, 1.0f});
    SlicingSettings post;
    post.numPlanes = 16;
    const auto [plain, pre] = compareSettings(renderer, v, post, preIntegrated(post), *camera, 48);
    keepImages(pre, "tagged-pre-integrated");
    MESSAGE("16 planes, tagged: post-classified " << plain.difference.rmse / k8Bit
                                                  << "/255, pre-integrated "
                                                  << pre.difference.rmse / k8Bit << "/255");
    CHECK(pre.stats.preIntegrated);
    CHECK(pre.difference.rmse < 0.5 * plain.difference.rmse);
    checkDifference(pre.difference, 1.5, 30.0, "tagged pre-integrated, 16 planes: ");
    // Many planes: both converge to the reference.
    SlicingSettings many;
    many.numPlanes = 160;
    const Comparison fine = compareGrid(renderer, v, preIntegrated(many), *camera, 48);
    checkDifference(fine.difference, 0.3, 8.0, "tagged pre-integrated, 160 planes: ");
}

TEST_CASE("the error model's choice is the cheapest that meets the target") {
    const RayCastVolume ml = marschnerLobbVolume();
    SlabErrorModel model(ml);
    QualityView view;
    view.localDirection = {0.0, 0.0, -1.0};
    view.depthL0 = 17.0;
    view.coverage = 0.5;
    const QualityRequest request{2e-3, {}, {}, {}, {}, true};
    const QualityChoice c = chooseQuality(model, view, request);
    CHECK(c.meetsTarget);
    CHECK(c.predictedRmse <= request.errorTarget);
    // No other quadrature of the search grid that the model predicts within the target (with
    // the chooser's margin) is cheaper.
    const double cost = quadratureCost(c.quadrature, view.depthL0, VolumeRenderMode::DVR, false);
    for (const bool pre : {false, true})
        for (int k = 1; k <= 64; k *= 2)
            for (int j = -16; j <= 8; ++j) {
                SlabQuadrature q;
                q.samplesPerPlane = k;
                q.planeSpacingL0 = k / std::pow(2.0, 0.5 * j);
                q.preIntegrated = pre;
                if (view.depthL0 / q.planeSpacingL0 < 1.0) continue; // fewer than one plane
                if (predictImageRmse(model, view, q) >
                    qualityTargetMargin(VolumeRenderMode::DVR) * request.errorTarget)
                    continue;
                CHECK(quadratureCost(q, view.depthL0, VolumeRenderMode::DVR, false) >=
                      0.999 * cost);
            }
    // The prediction falls with the sampling rate.
    SlabQuadrature denser = c.quadrature;
    denser.planeSpacingL0 /= 4.0;
    CHECK(predictImageRmse(model, view, denser) < c.predictedRmse);
}

TEST_CASE("the model lays as many planes as the slicer draws over the view's depth") {
    // The model's direction sees the box deeper than the view (its nearest lattice direction
    // is off the view's): a spacing of the view's depth is one plane for the slicer, and must
    // be one for the model too, not two.
    const RayCastVolume ml = marschnerLobbVolume();
    SlabErrorModel model(ml);
    QualityView view;
    view.localDirection = glm::normalize(glm::dvec3(0.3, 0.5, -1.0));
    const int dir = SlabErrorModel::nearestDirection(view.localDirection);
    view.directions.dir[0] = dir; // predicted along the nearest direction alone
    view.directions.count = 1;
    view.depthL0 = 0.9 * model.depthL0(dir);
    view.coverage = 1.0;
    SlabQuadrature q;
    q.samplesPerPlane = 16;
    q.planeSpacingL0 = view.depthL0;
    SlabQuadrature onePlane = q, twoPlanes = q;
    onePlane.planeSpacingL0 = 2.0 * model.depthL0(dir);
    twoPlanes.planeSpacingL0 = 0.51 * model.depthL0(dir);
    const double predicted = predictImageRmse(model, view, q);
    CHECK(predicted == doctest::Approx(model.rayRmse(dir, onePlane)).epsilon(1e-12));
    CHECK(model.rayRmse(dir, twoPlanes) != doctest::Approx(predicted).epsilon(1e-3));
    // Two planes over the view's depth are two for the model.
    q.planeSpacingL0 = 0.5 * view.depthL0;
    CHECK(predictImageRmse(model, view, q) ==
          doctest::Approx(model.rayRmse(dir, twoPlanes)).epsilon(1e-12));
    // numPlanes 1 is one plane, also where the depth's fourth digit would round its spacing
    // down (53.847 L0 deep: a spacing of 53.8 counts two).
    const double digit = std::pow(10.0, std::floor(std::log10(view.depthL0)) - 2.0);
    view.depthL0 = (std::floor(view.depthL0 / digit) + 0.4) * digit;
    QualityRequest request;
    request.errorTarget = 1.0;
    request.numPlanes = 1;
    request.samplesPerPlane = 16;
    request.preIntegrated = false;
    const QualityChoice c = chooseQuality(model, view, request);
    CHECK(c.predictedRmse == doctest::Approx(model.rayRmse(dir, onePlane)).epsilon(1e-12));
    // The view's own directions: the root of the mean square of each one's prediction.
    QualityView own = view;
    own.directions = {};
    const ModelDirections dirs = directionsOf(own, model.mode());
    REQUIRE(dirs.count == SlabErrorModel::kNearDirections);
    CHECK(dirs.dir[0] == dir);
    double sum = 0.0;
    for (int i = 0; i < dirs.count; ++i) {
        QualityView one = view;
        one.directions.dir[0] = dirs.dir[std::size_t(i)];
        const double e = predictImageRmse(model, one, q);
        sum += e * e;
    }
    CHECK(predictImageRmse(model, own, q) ==
          doctest::Approx(std::sqrt(sum / dirs.count)).epsilon(1e-12));
}

TEST_CASE("the error model predicts the same on one thread and on several") {
    // Each ray is integrated by one thread, so the predictions are equal bit for bit: DVR
    // (tagged, so several segment tables are built before the threads read them) and MIP.
    RayCastVolume tagged = labelledVolume(20, {{-1, transferFunction(spike(0.3, 0.35, 0.4, 0.5))},
                                               {1, transferFunction(spike(0.6, 0.65, 0.7, 0.9))},
                                               {2, transferFunction(spike(0.2, 0.3, 0.4, 0.7))}});
    RayCastVolume mip = marschnerLobbVolume();
    mip.mode = VolumeRenderMode::MIP;
    for (const RayCastVolume* v : {&tagged, &mip}) {
        SlabErrorModel one(*v), several(*v);
        one.setThreads(1);
        several.setThreads(4);
        for (const int dir : {3, 50, SlabErrorModel::kDirections + 20})
            for (const double spacing : {0.5, 2.0, 8.0}) {
                SlabQuadrature q;
                q.planeSpacingL0 = spacing;
                q.samplesPerPlane = spacing > 1.0 ? 4 : 1;
                const double a = one.rayRmse(dir, q), b = several.rayRmse(dir, q);
                CHECK(a > 0.0);
                CHECK(a == b);
            }
    }
}

TEST_CASE_FIXTURE(GlFixture, "ShearWarpVolume predicts its error and picks the interactive step") {
    const std::string scene = R"(#Inventor V2.1 ascii
Separator {
  OrthographicCamera { position 0 1.2 4 orientation 1 0 0 -0.2914567944778671 height 3.4843
                       nearDistance 2 farDistance 6.5 focalDistance 4.18 }
  VolumeData { generator MARSCHNER_LOBB dimensions 32 32 32 }
  DEF SW ShearWarpVolume {
    TransferFunction { red [ 0 0.1, 1 1 ] green [ 0 0.3, 1 0.9 ] blue [ 0 1, 1 0.1 ]
                       alpha [ 0 0, 1 0.12 ] }
    VolumeObject { }
  }
}
)";
    ref_ptr<Node> root = readSceneFromString(scene, "sw.iv");
    auto* sw = static_cast<ShearWarpVolume*>(root->children()->back().get());
    REQUIRE(sw->isA<ShearWarpVolume>());
    RenderOptions options;
    options.width = options.height = 64;
    const Image reference = renderReference(*root, options);
    const Image still = renderer.render(*root, options);
    const ShearWarpVolume::Quality floor = sw->lastQuality();
    const double measured = difference(still, reference).rmse;
    MESSAGE("still: predicted " << floor.predictedRmse / k8Bit << "/255, measured "
                                << measured / k8Bit << "/255");
    REQUIRE(floor.predicted);
    CHECK(floor.sliceStep == 1);
    CHECK(floor.predictedRmse == doctest::Approx(floor.floorRmse));
    CHECK(floor.predictedRmse < kPredictionFactor * measured);
    CHECK(floor.predictedRmse > measured / kPredictionFactor);
    // Interactive: the largest step predicted within interactiveErrorTarget.
    for (const float target : {2.0f, 8.0f}) {
        sw->interactiveErrorTarget = target;
        options.interactive = true;
        const Image moving = renderer.render(*root, options);
        const ShearWarpVolume::Quality q = sw->lastQuality();
        MESSAGE("interactive target " << target << "/255: step " << q.sliceStep << ", predicted "
                                      << q.predictedRmse / k8Bit << "/255, measured "
                                      << difference(moving, reference).rmse / k8Bit << "/255");
        CHECK(q.predictedRmse <= target * k8Bit + 1e-12);
        if (target == 8.0f) CHECK(q.sliceStep > 1);
    }
    // Set in the scene, the step is kept.
    sw->interactiveSliceStep = 3;
    renderer.render(*root, options);
    CHECK(sw->lastQuality().sliceStep == 3);
}

TEST_CASE_FIXTURE(GlFixture, "a ShearWarpVolume frame of a new view direction predicts on read") {
    // Casting the model's rays for a new direction costs more than the frame: the frame leaves
    // it to the first lastQuality(), whose prediction is that of the frame's view.
    const auto sceneAt = [](const char* camera) {
        return std::string("#Inventor V2.1 ascii\nSeparator {\n") + camera + R"(
  VolumeData { generator MARSCHNER_LOBB dimensions 32 32 32 }
  ShearWarpVolume {
    TransferFunction { red [ 0 0.1, 1 1 ] green [ 0 0.3, 1 0.9 ] blue [ 0 1, 1 0.1 ]
                       alpha [ 0 0, 1 0.12 ] }
    VolumeObject { }
  }
}
)";
    };
    ref_ptr<Node> root = readSceneFromString(
        sceneAt("OrthographicCamera { position 0 1.2 4 orientation 1 0 0 -0.2914567944778671 "
                "height 3.4843 nearDistance 2 farDistance 6.5 focalDistance 4.18 }"),
        "sw.iv");
    auto* sw = static_cast<ShearWarpVolume*>(root->children()->back().get());
    REQUIRE(sw->isA<ShearWarpVolume>());
    RenderOptions options;
    options.width = options.height = 64;
    renderer.render(*root, options);
    REQUIRE(sw->lastQuality().predicted);
    const double first = sw->lastQuality().floorRmse;
    // Turned to look at the volume's centre from elsewhere (another principal axis).
    auto* camera = static_cast<OrthographicCamera*>(root->children()->front().get());
    REQUIRE(camera->isA<OrthographicCamera>());
    const auto lookFrom = [&](const Rotation& r) {
        camera->orientation = r;
        camera->position = glm::vec3(r.matrix() * glm::dvec4(0.0, 0.0, 4.18, 1.0));
    };
    lookFrom(Rotation{glm::vec3(0.4f, 1.0f, 0.2f), 1.1f});
    const Image side = renderer.render(*root, options);
    CHECK_FALSE(sw->lastQualityKnown().predicted); // left to the read
    const ShearWarpVolume::Quality q = sw->lastQuality();
    REQUIRE(q.predicted);
    CHECK(sw->lastQualityKnown().predicted);
    CHECK(q.predictedRmse == doctest::Approx(q.floorRmse));
    CHECK(q.floorRmse != doctest::Approx(first)); // this view's, not the first one's
    const double measured = difference(side, renderReference(*root, options)).rmse;
    MESSAGE("side view: predicted " << q.predictedRmse / k8Bit << "/255, measured "
                                    << measured / k8Bit << "/255");
    CHECK(q.predictedRmse < kPredictionFactor * measured);
    CHECK(q.predictedRmse > measured / kPredictionFactor);
    renderer.render(*root, options); // the direction is cast now: predicted in the frame, alike
    CHECK(sw->lastQualityKnown().predicted);
    CHECK(sw->lastQualityKnown().floorRmse == q.floorRmse);
    // An interactive frame of a third direction chooses its step from the directions cast, and
    // predicts its own on read, at that step.
    lookFrom(Rotation{glm::vec3(-0.5f, 1.0f, 0.3f), -0.8f});
    sw->interactiveErrorTarget = 8.0f;
    options.interactive = true;
    renderer.render(*root, options);
    CHECK_FALSE(sw->lastQualityKnown().predicted);
    const ShearWarpVolume::Quality moving = sw->lastQuality();
    REQUIRE(moving.predicted);
    CHECK(moving.sliceStep > 1);
    CHECK(moving.predictedRmse > moving.floorRmse);
}
