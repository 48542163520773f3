// GltfModel draws its asset, uploaded once per load and kept in the frame's RenderCache, with
// the Inventor state around it (lib/volsg/gltf/GltfRenderer).
#include <vector>

#include <volsg/gltf/GltfGpuAsset.h>
#include <volsg/gltf/GltfRenderer.h>
#include <volsg/nodes/BoxClip.h>
#include <volsg/nodes/GltfModel.h>
#include <volsg/nodes/Material.h>
#include <volsg/render/BuiltinRendering.h>
#include <volsg/render/RenderAction.h>

namespace volsg {

namespace {

void renderGltfModel(RenderAction& action, GltfModel& model) {
    if (action.pass() == RenderPass::Volume) return;
    FrameContext& frame = action.frame();
    const State& state = action.state();
    const GltfAsset& asset = model.asset();
    // Keyed by the load, so a reload starts a fresh GPU copy and the old one is dropped.
    GltfGpuAsset& gpu = frame.cache.get<GltfGpuAsset>(model, model.loadSerial());
    if (!gpu.uploaded()) gpu.upload(asset);

    GltfLook look;
    look.model = state.modelMatrix();
    if (const Material* m = state.nearestNode<Material>()) {
        if (!m->emissiveColor.empty()) look.extraEmissive = m->emissiveColor[0];
        if (!m->transparency.empty()) look.transparency = m->transparency[0];
    }
    if (const StateEntry* e = state.nearest<BoxClip>()) {
        const auto& b = static_cast<const BoxClip&>(*e->node);
        GltfBoxClip box;
        box.boxFromWorld = glm::mat4(glm::inverse(e->model));
        box.min = glm::min(b.origin(), b.origin() + b.extent());
        box.max = glm::max(b.origin(), b.origin() + b.extent());
        box.insideOpacity = b.insideOpacity();
        box.outsideOpacity = b.outsideOpacity();
        look.boxClip = box;
    }
    thread_local std::vector<SceneLight> lights;
    thread_local std::vector<glm::dvec4> clipPlanes;
    action.lightsInScope(lights);
    action.clipPlanesInScope(clipPlanes);
    look.lights = lights;
    look.clipPlanes = clipPlanes;
    GltfRenderer::of(frame).submit(frame, asset, gpu, look);
}

} // namespace

void addGltfRenderMethods(ActionMethods& methods) {
    methods.add(&renderGltfModel);
}

} // namespace volsg
