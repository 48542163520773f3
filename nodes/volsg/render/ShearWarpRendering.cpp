// ShearWarpVolume gathers its objects, renders them with its CPU engine and composites the
// frame into the Volume pass (lib/volsg/render/ImageCompositor).
#include <vector>

#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/nodes/VolumeSeries.h>
#include <volsg/render/BuiltinRendering.h>
#include <volsg/render/ImageCompositor.h>
#include <volsg/render/RenderAction.h>
#include <volsg/shearwarp/SimdLevel.h>
#include <volsg/volumescene/ShearWarpObjects.h>

namespace volsg {

namespace {

void renderShearWarpVolume(RenderAction& action, ShearWarpVolume& node) {
    action.needFloatTarget();
    if (action.pass() != RenderPass::Volume) return;
    action.countVolumeInstance();
    const State& state = action.state();
    std::vector<VolumeObject*> sources;
    std::vector<ShearWarpObject> objects = gatherShearWarpObjects(node, state, &sources);
    if (objects.empty()) return;

    FrameContext& frame = action.frame();
    const RenderView& rv = frame.view;
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
    view.sliceStep = node.sliceStepFor(frame.interactive, frame.interactivePlaneScale);
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
