// Shapes draw their mesh, uploaded once per (node, mesh key) and kept in the frame's
// RenderCache while the node is drawn, with what the state says they look like: material,
// light model, draw style, shape hints, texture, environment, lights and clip planes.
#include <memory>
#include <vector>

#include <volsg/nodes/Complexity.h>
#include <volsg/nodes/DrawStyle.h>
#include <volsg/nodes/Environment.h>
#include <volsg/nodes/LightModel.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/PrimitiveComplexity.h>
#include <volsg/nodes/Shape.h>
#include <volsg/nodes/ShapeHints.h>
#include <volsg/nodes/ShapeState.h>
#include <volsg/nodes/Texture2.h>
#include <volsg/nodes/TextureCoordinateEnvironment.h>
#include <volsg/nodes/VertexProperty.h>
#include <volsg/nodes/VertexShape.h>
#include <volsg/render/BuiltinRendering.h>
#include <volsg/render/GpuMesh.h>
#include <volsg/render/RenderAction.h>
#include <volsg/render/RenderCaching.h>
#include <volsg/render/ShapeDetail.h>
#include <volsg/render/ShapeRenderer.h>
#include <volsg/render/SharedMeshes.h>

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

/// A texture's GPU copy, held by the cache entry and by the render caches that use it.
struct SharedTexture {
    std::shared_ptr<ShapeTexture> gpu;
};

ShapeTexturing texturingOf(FrameContext& frame, const ShapeState& shape,
                           std::shared_ptr<const ShapeTexture>* holder) {
    ShapeTexturing out;
    const Texture2* node = shape.texture;
    if (!node) return out;
    // One GPU copy per texture node and version (shared by every shape that uses it).
    SharedTexture& entry = frame.cache.get<SharedTexture>(*node, node->version());
    if (!entry.gpu) {
        entry.gpu = std::make_shared<ShapeTexture>();
        entry.gpu->upload(node->texels(), node->wrapS() == Texture2::REPEAT,
                          node->wrapT() == Texture2::REPEAT);
    }
    *holder = entry.gpu;
    out.texture = entry.gpu.get();
    out.model = ShapeTexturing::Model(node->model());
    out.blendColor = node->blendColor();
    out.matrix = shape.textureMatrix;
    out.sphereMap = shape.textureCoords && shape.textureCoords->isA<TextureCoordinateEnvironment>();
    return out;
}

/// The shape's coarser meshes on the GPU (shared by equal content), or null without any.
std::shared_ptr<const ShapeDetail> detailOf(FrameContext& frame, const Shape& shape,
                                            const State& state, const GpuMesh& full) {
    // A SCREEN_SPACE complexity fits the tessellation to the view already.
    if (tessellationFollowsView(state)) return nullptr;
    thread_local std::vector<CoarserMesh> coarser;
    coarser.clear();
    shape.buildCoarserMeshes(state, coarser);
    if (coarser.empty() || full.bounds.isEmpty()) return nullptr;
    auto detail = std::make_shared<ShapeDetail>();
    for (const CoarserMesh& c : coarser)
        detail->levels.push_back(
            {frame.cache.shared<SharedMeshes>().find(c.mesh, frame.shapes), c.deviation});
    detail->centre = 0.5 * (full.bounds.min + full.bounds.max);
    // The coarser meshes' vertices lie on the true surface, which the full mesh's box may not
    // reach: its half diagonal plus a deviation larger than the full mesh's encloses them.
    detail->radius =
        0.5 * glm::length(full.bounds.max - full.bounds.min) + detail->levels.front().deviation;
    return detail;
}

void renderShape(RenderAction& action, Shape& shape) {
    if (action.pass() == RenderPass::Volume) return;
    FrameContext& frame = action.frame();
    const State& state = action.state();
    const VertexProperty* own =
        shape.isA<VertexShape>() ? static_cast<VertexShape&>(shape).ownVertexProperty() : nullptr;
    const ShapeState scope = gatherShapeState(state, own);
    if (scope.drawStyle && scope.drawStyle->style() == DrawStyle::INVISIBLE) return;
    ShapeMesh& entry = frame.cache.get<ShapeMesh>(shape, shape.meshKey(state));
    if (!entry.gpu) {
        entry.gpu = frame.cache.shared<SharedMeshes>().find(shape.mesh(state), frame.shapes);
        entry.detail = detailOf(frame, shape, state, *entry.gpu);
    }
    const GpuMesh& gpu =
        entry.detail ? entry.detail->chooseFor(frame, state.modelMatrix(), *entry.gpu) : *entry.gpu;
    if (own && frame.recording) noteForCache(*frame.recording, *own); // a field, not a child
    // A tessellation that follows the view cannot be replayed from another view (as Coin's
    // sogl_render_* say DONT_AUTO_CACHE for SCREEN_SPACE).
    if (frame.recording && scope.complexity && scope.complexity->type() == Complexity::SCREEN_SPACE)
        frame.recording->cacheable = false;
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
    std::shared_ptr<const ShapeTexture> texture;
    look.texturing = texturingOf(frame, scope, &texture);
    look.environment = environmentOf(scope.environment);
    if (frame.recording && action.pass() == RenderPass::Opaque) {
        const bool transparent = look.material.transparency > 0.0f || gpu.hasTranslucentColors;
        frame.recording->shapes.push_back({entry.gpu, texture, look, transparent, entry.detail});
    }
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

bool rendersAsShape(const NodeType& type) {
    return RenderAction::methods().runs(type, &renderShape);
}

} // namespace volsg
