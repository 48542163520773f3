// Shapes draw their mesh, uploaded once per (node, mesh key) and kept in the frame's
// RenderCache while the node is drawn, with the material, light model, lights and clip planes
// in scope.
#include <vector>

#include <volsg/nodes/LightModel.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/Shape.h>
#include <volsg/render/BuiltinRendering.h>
#include <volsg/render/GpuMesh.h>
#include <volsg/render/RenderAction.h>
#include <volsg/render/ShapeRenderer.h>

namespace volsg {

namespace {

template <class F, class V> V firstOr(const F& field, V fallback) {
    return field.empty() ? fallback : field[0];
}

/// The first value of each field of the nearest Material (Inventor's default for an empty one).
SurfaceMaterial surfaceMaterial(const State& state) {
    SurfaceMaterial out;
    if (const Material* m = state.nearestNode<Material>()) {
        out.ambient = firstOr(m->ambientColor, out.ambient);
        out.diffuse = firstOr(m->diffuseColor, out.diffuse);
        out.specular = firstOr(m->specularColor, out.specular);
        out.emissive = firstOr(m->emissiveColor, out.emissive);
        out.shininess = firstOr(m->shininess, out.shininess);
        out.transparency = firstOr(m->transparency, out.transparency);
    }
    return out;
}

void renderShape(RenderAction& action, Shape& shape) {
    if (action.pass() == RenderPass::Volume) return;
    FrameContext& frame = action.frame();
    const State& state = action.state();
    GpuMesh& gpu = frame.cache.get<GpuMesh>(shape, shape.meshKey(state));
    if (!gpu.uploaded) frame.shapes.upload(gpu, shape.mesh(state));
    if (gpu.indexCount == 0) return;

    // Scratch kept across shapes: gathering allocates nothing per shape.
    thread_local std::vector<SceneLight> lights;
    thread_local std::vector<glm::dvec4> clipPlanes;
    ShapeLook look;
    look.model = state.modelMatrix();
    look.material = surfaceMaterial(state);
    const LightModel* lightModel = state.nearestNode<LightModel>();
    look.baseColorOnly = lightModel && lightModel->model() == LightModel::BASE_COLOR;
    action.lightsInScope(lights);
    action.clipPlanesInScope(clipPlanes);
    look.lights = lights;
    look.clipPlanes = clipPlanes;
    frame.shapes.submit(frame, gpu, look);
}

} // namespace

void addShapeRenderMethods(ActionMethods& methods) {
    methods.add(&renderShape);
}

} // namespace volsg
