// ShearWarpVolume gathers its objects, renders them with its CPU engine and composites the
// frame into the Volume pass (lib/volsg/render/ImageCompositor).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/nodes/VolumeSeries.h>
#include <volsg/paging/PagedVolume.h>
#include <volsg/render/BuiltinRendering.h>
#include <volsg/render/ImageCompositor.h>
#include <volsg/render/RenderAction.h>
#include <volsg/shearwarp/SimdLevel.h>
#include <volsg/slicing/SlicingQuality.h>
#include <volsg/volumescene/ShearWarpObjects.h>
#include <volsg/volumescene/VolumeInScope.h>

namespace volsg {

namespace {

/// The error model's prediction for this frame, and the interactive slice step chosen from the
/// interactive target when interactiveSliceStep is not set. Predicted only where the model
/// describes shear-warp: every object a transfer-function DVR object, DVR between them, the
/// data in scope (not a voxel file). A view direction whose rays the model has not cast yet is
/// left `pending` for ShearWarpVolume::lastQuality(): a still frame draws every slice whatever
/// the prediction, and an interactive one chooses its step from the nearest direction cast so
/// far (the first one is cast in the frame).
ShearWarpVolume::Quality
predictQuality(ShearWarpVolume& node, const State& state,
               const std::vector<ShearWarpObject>& objects, const ShearWarpView& view,
               const FrameContext& frame,
               std::optional<ShearWarpVolume::PendingPrediction>& pending) {
    ShearWarpVolume::Quality q;
    q.sliceStep = node.sliceStepFor(frame.interactive, frame.interactivePlaneScale);
    const float targetField =
        frame.interactive ? node.interactiveErrorTarget() : node.errorTarget();
    if (!(targetField > 0.0f) || !node.voxelFile().empty() ||
        node.interObjectCompositing() != ShearWarpVolume::DVR)
        return q;
    for (const ShearWarpObject& o : objects)
        if (o.compositing != ObjectCompositing::DVR || o.unclipped.mode != VoxelRenderMode::TF)
            return q;
    std::optional<VolumeInScope> scope = gatherVolumeInScope(state);
    if (!scope || !scope->data) return q;
    RayCastVolume volume;
    static_cast<VolumeInScope&>(volume) = std::move(*scope);
    volume.tags = nullptr;
    volume.transferFunctions = {{-1, objects.front().transferFunction}};
    volume.mode = VolumeRenderMode::DVR;
    const std::uint64_t key = std::uint64_t(reinterpret_cast<std::uintptr_t>(volume.data.get())) ^
                              (objects.front().tableKey * 0x9E3779B97F4A7C15ull);
    SlabErrorModel& model = node.errorModel(volume, key);
    QualityView qv =
        qualityViewOf(view.modelView, view.projection, volume.halfExtent(), model.L0());
    // Along the view's nearest narrow directions (shear-warp's rays are parallel).
    qv.directions = modelDirectionsOf(qv.localDirection, 0.0, VolumeRenderMode::DVR);
    const ModelDirections dirs = qv.directions;
    const double scale = std::sqrt(std::clamp(qv.coverage, 0.0, 1.0));
    q.target = double(targetField) / 255.0;
    if (frame.interactive && node.interactiveSliceStep.isDefault()) {
        // The view's directions cast already, else the nearest cast one (the model's first
        // directions are cast in this frame).
        const ModelDirections from = castDirectionsNear(model, qv, 180.0);
        const auto predicted = [&](int step) {
            return scale * preClassifiedRmseAlong(model, from, step);
        };
        int step = 1;
        for (const int s : {2, 3, 4, 6, 8, 12, 16}) {
            if (predicted(s) > q.target) break;
            step = s;
        }
        const double viewer =
            frame.interactivePlaneScale > 0.0 ? std::min(frame.interactivePlaneScale, 1.0) : 1.0;
        q.sliceStep = int(std::clamp(std::lround(step / viewer), 1L, 16L));
    }
    if (!directionsCast(model, dirs)) {
        pending = ShearWarpVolume::PendingPrediction{dirs, scale};
        return q;
    }
    q.predicted = true;
    q.floorRmse = scale * preClassifiedRmseAlong(model, dirs, 1);
    q.predictedRmse = scale * preClassifiedRmseAlong(model, dirs, q.sliceStep);
    return q;
}

/// A paged volume's level for this view, read whole (shear-warp makes its voxel lists from one
/// grid): the coarsest whose voxels project to at most a pixel (shear-warp's parallel
/// projection), as fine as the memory budget allows, the stand-in while it loads. Null for a
/// volume in memory.
ref_ptr<const VolumeGrid> pagedLevelFor(const State& state, const RenderView& view,
                                        ShearWarpVolume::Quality& quality) {
    const VolumeData* data = state.nearestNode<VolumeData>();
    if (!data || data->isA<VolumeSeries>()) return nullptr;
    const std::shared_ptr<PagedVolume> paged = data->pagedVolume();
    if (!paged) return nullptr;
    const glm::dmat4 modelView = view.view * state.modelMatrix();
    const double pixelsPerEyeUnit = 0.5 * std::abs(view.projection[1][1]) * view.height;
    const PagedLayout& layout = paged->layout();
    int wanted = 0;
    for (int level = layout.levelCount() - 1; level >= 0; --level) {
        const glm::dvec3 voxel = layout.spacingOf(level);
        double eyeVoxel = 0.0;
        for (int a = 0; a < 3; ++a)
            eyeVoxel = std::max(eyeVoxel, voxel[a] * glm::length(glm::dvec3(modelView[a])));
        if (eyeVoxel * pixelsPerEyeUnit <= 1.0) {
            wanted = level;
            break;
        }
    }
    int drawn = 0;
    bool loading = false;
    ref_ptr<const VolumeGrid> grid = paged->wholeLevel(wanted, drawn, loading);
    quality.pagedLevel = drawn;
    quality.wantedLevel = wanted;
    quality.refining = loading;
    quality.levelError = paged->wholeLevelError();
    return grid;
}

void renderShearWarpVolume(RenderAction& action, ShearWarpVolume& node) {
    action.needFloatTarget();
    // Opaque results go through GL's depth buffer: a frame on the CPU is refused before the
    // engine runs when this node's last frame wrote depth (the first such frame is drawn twice).
    if (action.frame().cpuImage && node.lastFrame() && node.lastFrame()->wroteDepth) {
        action.frame().needsGl = true;
        return;
    }
    if (action.pass() != RenderPass::Volume) return;
    action.countVolumeInstance();
    const State& state = action.state();
    FrameContext& frame = action.frame();
    const RenderView& rv = frame.view;
    ShearWarpVolume::Quality paging;
    const ref_ptr<const VolumeGrid> level = pagedLevelFor(state, rv, paging);
    std::vector<VolumeObject*> sources;
    std::vector<ShearWarpObject> objects = gatherShearWarpObjects(node, state, &sources, level);
    if (objects.empty()) return;

    ShearWarpView view;
    view.modelView = rv.view * state.modelMatrix();
    view.projection = rv.projection;
    view.width = rv.width;
    view.height = rv.height;
    view.interObject = node.interObjectCompositing() == ShearWarpVolume::MIP
                           ? InterObjectCompositing::MIP
                           : InterObjectCompositing::DVR;
    view.threads = node.threads();
    view.valueSortedMip = node.valueSortedMip();
    std::optional<ShearWarpVolume::PendingPrediction> pending;
    ShearWarpVolume::Quality quality = predictQuality(node, state, objects, view, frame, pending);
    quality.pagedLevel = paging.pagedLevel;
    quality.wantedLevel = paging.wantedLevel;
    quality.refining = paging.refining;
    quality.levelError = paging.levelError;
    view.sliceStep = quality.sliceStep;
    view.simd = frame.debug.vectorKernels ? bestSimdLevel() : SimdLevel::Scalar;
    std::vector<SceneLight> lights;
    action.lightsInScope(lights);
    for (const SceneLight& l : lights)
        if (l.vector.w == 0.0f) { // the first directional light (or the headlight)
            view.lightDirection = glm::dvec3(rv.view * glm::dvec4(glm::dvec3(l.vector), 0.0));
            break;
        }
    // The opaque depth of this frame: voxels behind it do not count.
    ImageCompositor::readOpaqueDepth(frame, view.opaqueWindowDepth);

    const ShearWarpFrame& f =
        node.renderFrame(objects, view, std::move(sources), state.modelMatrix());
    node.setLastQuality(quality, pending);
    if (const VolumeData* data = state.nearestNode<VolumeData>();
        data && data->isA<VolumeSeries>()) // prefetched steps get this view's RenderList
        static_cast<const VolumeSeries*>(data)->setViewAxis(f.stats.principalAxis);

    CpuImage image;
    image.pixels = f.image.pixels.data();
    image.windowDepth = f.wroteDepth ? f.windowDepth.data() : nullptr;
    image.drawn = f.drawn;
    frame.cache.get<ImageCompositor>(node).composite(frame, image);
}

} // namespace

void addShearWarpRenderMethods(ActionMethods& methods) {
    methods.add(&renderShearWarpVolume);
}

} // namespace volsg
