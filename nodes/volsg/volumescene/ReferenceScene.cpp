#include <volsg/volumescene/ReferenceScene.h>

#include <string>
#include <utility>

#include <volsg/actions/Action.h>
#include <volsg/core/Error.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/Volume.h>
#include <volsg/volumescene/ShearWarpObjects.h>
#include <volsg/volumescene/VolumeInScope.h>

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
            volumes.push_back(
                describeShearWarpVolume(static_cast<ShearWarpVolume&>(node), state()));
        node.doAction(*this);
        if (node.isA<Volume>())
            volumes.push_back(describeVolume(static_cast<const Volume&>(node), state()));
    }
};

} // namespace

RayCastVolume describeVolume(const Volume& volume, VolumeInScope scope) {
    RayCastVolume out;
    static_cast<VolumeInScope&>(out) = std::move(scope);
    out.mode = volume.mode();
    for (const glm::vec2& p : volume.planeOpacity.getValues())
        out.planeOpacity.push_back({double(p.x), double(p.y)});
    return out;
}

RayCastVolume describeVolume(const Volume& volume, const State& state) {
    std::optional<VolumeInScope> scope = gatherVolumeInScope(state);
    if (!scope) throw Error("Volume without VolumeData in scope");
    return describeVolume(volume, std::move(*scope));
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
    scene.camera->check(scene.model); // the GL renderer refuses the same cameras
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
