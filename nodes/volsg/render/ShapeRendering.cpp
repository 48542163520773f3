// Shapes draw their mesh, uploaded once per (node, mesh key) and kept in the frame's
// RenderCache while the node is drawn, with what the state says they look like: material,
// light model, draw style, shape hints, texture, environment, lights and clip planes.
#include <vector>

#include <volsg/nodes/DrawStyle.h>
#include <volsg/nodes/Environment.h>
#include <volsg/nodes/LightModel.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/Shape.h>
#include <volsg/nodes/ShapeHints.h>
#include <volsg/nodes/ShapeState.h>
#include <volsg/nodes/Texture2.h>
#include <volsg/nodes/TextureCoordinateEnvironment.h>
#include <volsg/nodes/VertexShape.h>
#include <volsg/render/BuiltinRendering.h>
#include <volsg/render/GpuMesh.h>
#include <volsg/render/RenderAction.h>
#include <volsg/render/ShapeRenderer.h>

namespace volsg {

namespace {

template <class F, class V> V firstOr(const F& field, V fallback) {
    return field.empty() ? fallback : field[0];
}

/// The first value of each material field (Inventor's default for an empty one), with the
/// diffuse colour and transparency from the nodes that set them last (Material, BaseColor,
/// VertexProperty).
SurfaceMaterial surfaceMaterial(const ShapeState& shape) {
    SurfaceMaterial out;
    if (const Material* m = shape.material) {
        out.ambient = firstOr(m->ambientColor, out.ambient);
        out.specular = firstOr(m->specularColor, out.specular);
        out.emissive = firstOr(m->emissiveColor, out.emissive);
        out.shininess = firstOr(m->shininess, out.shininess);
    }
    const glm::vec4 first = materialColor(shape, 0);
    out.diffuse = glm::vec3(first);
    out.transparency = 1.0f - first.a;
    return out;
}

ShapeLook::Style styleOf(const DrawStyle* d) {
    if (!d) return ShapeLook::Style::Filled;
    switch (d->style()) {
    case DrawStyle::LINES:
        return ShapeLook::Style::Lines;
    case DrawStyle::POINTS:
        return ShapeLook::Style::Points;
    case DrawStyle::INVISIBLE:
        return ShapeLook::Style::Invisible;
    default:
        return ShapeLook::Style::Filled;
    }
}

ShapeEnvironment environmentOf(const Environment* e) {
    ShapeEnvironment out;
    if (!e) return out;
    out.ambient = e->ambientIntensity() * e->ambientColor();
    out.attenuation = e->attenuation();
    out.fogType = e->fogType();
    out.fogColor = e->fogColor();
    out.fogVisibility = e->fogVisibility();
    return out;
}

ShapeTexturing texturingOf(FrameContext& frame, const ShapeState& shape) {
    ShapeTexturing out;
    const Texture2* node = shape.texture;
    if (!node) return out;
    // One GPU copy per texture node and version (shared by every shape that uses it).
    ShapeTexture& gpu = frame.cache.get<ShapeTexture>(*node, node->version());
    if (!gpu.uploaded)
        gpu.upload(node->texels(), node->wrapS() == Texture2::REPEAT,
                   node->wrapT() == Texture2::REPEAT);
    out.texture = &gpu;
    out.model = ShapeTexturing::Model(node->model());
    out.blendColor = node->blendColor();
    out.matrix = shape.textureMatrix;
    out.sphereMap = shape.textureCoords && shape.textureCoords->isA<TextureCoordinateEnvironment>();
    return out;
}

void renderShape(RenderAction& action, Shape& shape) {
    if (action.pass() == RenderPass::Volume) return;
    FrameContext& frame = action.frame();
    const State& state = action.state();
    const VertexProperty* own =
        shape.isA<VertexShape>() ? static_cast<VertexShape&>(shape).ownVertexProperty() : nullptr;
    const ShapeState scope = gatherShapeState(state, own);
    if (scope.drawStyle && scope.drawStyle->style() == DrawStyle::INVISIBLE) return;
    GpuMesh& gpu = frame.cache.get<GpuMesh>(shape, shape.meshKey(state));
    if (!gpu.uploaded) frame.shapes.upload(gpu, shape.mesh(state));
    if (gpu.indexCount == 0) return;

    // Scratch kept across shapes: gathering allocates nothing per shape.
    thread_local std::vector<SceneLight> lights;
    thread_local std::vector<glm::dvec4> clipPlanes;
    ShapeLook look;
    look.model = state.modelMatrix();
    look.material = surfaceMaterial(scope);
    look.baseColorOnly = scope.lightModel && scope.lightModel->model() == LightModel::BASE_COLOR;
    look.style = styleOf(scope.drawStyle);
    if (scope.drawStyle) {
        look.lineWidth = scope.drawStyle->lineWidth();
        look.pointSize = scope.drawStyle->pointSize();
    }
    if (scope.hints) {
        const int ordering = scope.hints->vertexOrdering();
        look.cullBackFaces = ordering != ShapeHints::UNKNOWN_ORDERING &&
                             scope.hints->shapeType() == ShapeHints::SOLID;
        look.clockwise = ordering == ShapeHints::CLOCKWISE;
        look.twoSidedLighting = ordering != ShapeHints::UNKNOWN_ORDERING &&
                                scope.hints->shapeType() == ShapeHints::UNKNOWN_SHAPE_TYPE;
    }
    look.texturing = texturingOf(frame, scope);
    look.environment = environmentOf(scope.environment);
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
