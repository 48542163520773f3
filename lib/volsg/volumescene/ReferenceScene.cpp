#include <volsg/volumescene/ReferenceScene.h>

#include <string>
#include <utility>

#include <volsg/actions/Action.h>
#include <volsg/core/Error.h>
#include <volsg/nodes/BoxClip.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeData.h>

namespace volsg {

namespace {

/// Walks the graph as a render does (every node's doAction, so transforms, separators,
/// switches and property nodes act) and describes each Volume node it meets from the state.
class VolumeCollector : public Action {
public:
    std::vector<RayCastVolume> volumes;

protected:
    void dispatch(Node& node) override {
        // Before its doAction: the state nodes among its children are scoped to it.
        if (node.isA<ShearWarpVolume>())
            if (auto v = static_cast<ShearWarpVolume&>(node).describeForReference(state()))
                volumes.push_back(std::move(*v));
        node.doAction(*this);
        if (node.isA<Volume>())
            volumes.push_back(describeVolume(static_cast<const Volume&>(node), state()));
    }
};

} // namespace

RayCastVolume describeVolume(const Volume& volume, const State& state) {
    const VolumeData* data = state.nearestNode<VolumeData>();
    if (!data) throw Error("Volume without VolumeData in scope");
    RayCastVolume out;
    out.data = data->grid();
    out.tags = data->tagGrid();
    out.model = state.modelMatrix();
    // Outermost first, so a later TransferFunction for the same tag replaces an earlier one.
    for (const StateEntry* entry : state.all<TransferFunction>()) {
        const auto& tf = static_cast<const TransferFunction&>(*entry->node);
        if (tf.tag() < -1)
            throw Error("TransferFunction tag must be -1 (every voxel) or >= 0, got " +
                        std::to_string(tf.tag()));
        out.transferFunctions.insert_or_assign(tf.tag(), tf.function());
    }
    out.mode = volume.mode();
    for (const glm::vec2& p : volume.planeOpacity.getValues())
        out.planeOpacity.push_back({double(p.x), double(p.y)});
    // The box is in the BoxClip's own coordinates, which its model matrix maps to world.
    if (const StateEntry* entry = state.nearest<BoxClip>())
        out.boxClip = static_cast<const BoxClip&>(*entry->node).describe(entry->model);
    // ClipPlane::doAction puts only planes that are on in scope.
    for (const StateEntry* entry : state.all<ClipPlane>())
        out.clipPlanes.push_back(ClipPlane::worldPlane(
            static_cast<const ClipPlane&>(*entry->node).plane(), entry->model));
    return out;
}

std::vector<RayCastVolume> collectVolumes(Node& root) {
    VolumeCollector collector;
    collector.apply(root);
    return std::move(collector.volumes);
}

RayCastCamera referenceCamera(Node& root, const RenderOptions& options) {
    if (options.width <= 0 || options.height <= 0)
        throw Error("render size " + std::to_string(options.width) + "x" +
                    std::to_string(options.height) + " is empty");
    const double aspect = double(options.width) / double(options.height);
    // The same camera, and the same projection for this viewport, as the GL Renderer uses.
    const SceneCamera scene = options.camera ? SceneCamera{options.camera, glm::dmat4(1.0)}
                                             : findOrMakeCamera(root, aspect);
    RayCastCamera camera;
    camera.view = scene.camera->viewMatrix(scene.model);
    camera.projection = scene.camera->projectionMatrix(aspect);
    camera.width = options.width;
    camera.height = options.height;
    camera.clipToNearFar = true; // as GL clips everything it draws
    return camera;
}

Image renderReference(Node& root, const RenderOptions& options, RayCastResult* details,
                      const RayCastOptions& rayOptions) {
    RayCastScene scene;
    scene.camera = referenceCamera(root, options);
    scene.volumes = collectVolumes(root);

    // Opaque geometry by GL: its colour is what lies behind the volumes, its depth ends rays.
    RenderOptions opaque = options;
    opaque.opaqueOnly = true;
    Renderer renderer;
    const Image behind = renderer.render(root, opaque);
    const std::vector<float> depth = renderer.readWindowDepth();
    const std::size_t pixels = std::size_t(options.width) * std::size_t(options.height);
    scene.behind.background = glm::dvec3(options.background);
    scene.behind.backgroundPixels.resize(pixels);
    scene.behind.opaqueDistance.resize(pixels);
    for (int y = 0; y < options.height; ++y)
        for (int x = 0; x < options.width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(options.width) + std::size_t(x);
            scene.behind.backgroundPixels[i] = glm::dvec3(behind.pixels[i]);
            scene.behind.opaqueDistance[i] =
                ReferenceRayCaster::rayDistanceFromWindowDepth(scene.camera, x, y, depth[i]);
        }

    RayCastResult result = ReferenceRayCaster(rayOptions).render(scene);
    if (!details) return std::move(result.image);
    *details = std::move(result);
    return details->image;
}

} // namespace volsg
