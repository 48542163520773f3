// The ShearWarpVolume node gathers its objects' state, runs the CPU engine
// (lib/volsg/shearwarp) and composites the result into the frame with GL.
#include <volsg/nodes/ShearWarpVolume.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/core/Error.h>
#include <volsg/core/KeyMixing.h>
#include <volsg/gl/Program.h>
#include <volsg/gl/Shader.h>
#include <volsg/gl/Texture.h>
#include <volsg/gl/VertexArray.h>
#include <volsg/io/ReadContext.h>
#include <volsg/nodes/BoxClip.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/nodes/VolumeObject.h>
#include <volsg/nodes/VolumeSeries.h>
#include <volsg/reference/ReferenceRayCaster.h>
#include <volsg/render/RenderAction.h>
#include <volsg/render/RenderTarget.h>
#include <volsg/render/ShapeRenderer.h>
#include <volsg/shearwarp/VoxelListOptimizer.h>
#include <volsg/volume/VolumeGrid.h>
#include <volsg/voxelfile/PackedVolume.h>

namespace volsg {

const EnumValues ShearWarpVolume::interObjectNames{{"DVR", DVR}, {"MIP", MIP}};

namespace {

VoxelRenderMode modeOf(int mode) {
    switch (mode) {
    case VolumeObject::SHADED:
        return VoxelRenderMode::Shaded;
    case VolumeObject::GRADIENT_OPACITY:
        return VoxelRenderMode::GradientOpacity;
    case VolumeObject::CONTOUR:
        return VoxelRenderMode::Contour;
    case VolumeObject::COLORED_CONTOUR:
        return VoxelRenderMode::ColoredContour;
    default:
        return VoxelRenderMode::TF;
    }
}

/// A transfer function node in scope, with the key of its content.
struct ScopedTransfer {
    const TransferFunction* node = nullptr;
};

/// A BoxClip in scope with the model matrix at its place.
struct ScopedBox {
    const BoxClip* node = nullptr;
    glm::dmat4 model{1.0};
};

/// The state walk over the children: what each VolumeObject sees.
struct ObjectScope {
    VolumeObject* object;
    const TransferFunction* transfer; // null: the identity ramp
    ScopedBox box;
};

std::vector<ObjectScope> scopesOf(ShearWarpVolume& node, const State& state) {
    std::map<int, const TransferFunction*> transfers;
    for (const StateEntry& e : state.entries())
        if (e.node->isA<TransferFunction>()) {
            const auto* tf = static_cast<const TransferFunction*>(e.node);
            transfers[tf->tag()] = tf;
        }
    ScopedBox box;
    if (const StateEntry* e = state.nearest<BoxClip>())
        box = {static_cast<const BoxClip*>(e->node), e->model};
    std::vector<ObjectScope> out;
    for (const auto& child : *node.children()) {
        if (!child) continue;
        if (child->isA<TransferFunction>()) {
            const auto* tf = static_cast<const TransferFunction*>(child.get());
            transfers[tf->tag()] = tf;
        } else if (child->isA<BoxClip>()) {
            box = {static_cast<const BoxClip*>(child.get()), state.modelMatrix()};
        } else if (child->isA<VolumeObject>()) {
            auto* object = static_cast<VolumeObject*>(child.get());
            const TransferFunction* tf = nullptr;
            if (object->source() == VolumeObject::TAG && transfers.count(object->tag()))
                tf = transfers[object->tag()];
            else if (transfers.count(-1))
                tf = transfers[-1];
            out.push_back({object, tf, box});
        }
    }
    return out;
}

constexpr const char* kCompositeVertex = R"GLSL(#version 330 core
void main() {
    vec2 corner = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
    gl_Position = vec4(corner, 0.0, 1.0);
}
)GLSL";

// Row 0 of the engine's image is the top row: flip y when fetching.
constexpr const char* kCompositeFragment = R"GLSL(#version 330 core
uniform sampler2D uColor;
uniform sampler2D uDepth;
uniform int uDepthPass;
out vec4 fragColor;
void main() {
    ivec2 size = textureSize(uColor, 0);
    ivec2 p = ivec2(gl_FragCoord.xy);
    p.y = size.y - 1 - p.y;
    if (uDepthPass == 1) {
        float d = texelFetch(uDepth, p, 0).r;
        if (d >= 1.0) discard;
        gl_FragDepth = d;
        fragColor = vec4(0.0);
    } else {
        fragColor = texelFetch(uColor, p, 0);
    }
}
)GLSL";

/// GL objects of one node in one context.
struct ShearWarpGl {
    Program program;
    VertexArray vertexArray;
    Texture color, depth;
    glm::ivec2 size{0}; ///< of the textures' storage
};

} // namespace

ShearWarpVolume::ShearWarpVolume() = default;

ShearWarpVolume::~ShearWarpVolume() = default;

std::vector<ShearWarpObject> ShearWarpVolume::gatherObjects(const State& state,
                                                            std::vector<VolumeObject*>* sources) {
    std::vector<ShearWarpObject> out;
    if (sources) sources->clear();
    // A voxelFile replaces the VolumeData: its stored objects stand for the extraction.
    std::optional<PackedVolume> packed;
    if (!voxelFile().empty()) packed = PackedVolume::load(voxelFile(), directory_);
    const VolumeData* data = packed ? nullptr : state.nearestNode<VolumeData>();
    if (!data && !packed) return out;
    // A series hands out each step's lists from its step cache (which reads the grids).
    const VolumeSeries* series =
        data && data->isA<VolumeSeries>() ? static_cast<const VolumeSeries*>(data) : nullptr;
    const ref_ptr<const VolumeGrid> grid = data && !series ? data->grid() : nullptr;
    if (!grid && !packed && !series) return out;
    const ref_ptr<const VolumeGrid> tags = data && !series ? data->tagGrid() : nullptr;
    const glm::dmat4 model = state.modelMatrix();
    const glm::dmat4 worldToLocal = glm::inverse(model);

    // Clip planes in scope, in local coordinates: a world plane p (keeping p.xyz . x >= p.w)
    // is (n, -d) . (x, 1) >= 0; with x = M l that is (M^T (n, -d)) . (l, 1) >= 0.
    std::vector<glm::dvec4> worldPlanes, localPlanes;
    for (const StateEntry& e : state.entries())
        if (e.node->isA<ClipPlane>())
            worldPlanes.push_back(
                ClipPlane::worldPlane(static_cast<const ClipPlane&>(*e.node).plane(), e.model));
    std::uint64_t planeKey = 0xcbf29ce484222325ULL;
    for (const glm::dvec4& p : worldPlanes) {
        const glm::dvec4 h = glm::transpose(model) * glm::dvec4(glm::dvec3(p), -p.w);
        localPlanes.push_back(glm::dvec4(glm::dvec3(h), -h.w));
        for (int i = 0; i < 4; ++i)
            planeKey = mixKey(planeKey, bitsOf(p[i]));
    }

    for (const ObjectScope& scope : scopesOf(*this, state)) {
        VolumeObject& vo = *scope.object;
        ShearWarpObject o;
        std::uint64_t transferKey = 0x9e3779b97f4a7c15ULL;
        if (scope.transfer) {
            o.transferFunction = scope.transfer->function();
            transferKey = mixKey(transferKey,
                                 std::uint64_t(reinterpret_cast<std::uintptr_t>(scope.transfer)));
            transferKey = mixKey(transferKey, scope.transfer->version());
        }
        o.object = packed   ? packed->voxels(out.size(), vo.extractionSpec(o.transferFunction))
                   : series ? series->voxelObject(vo.extractionSpec(o.transferFunction))
                            : vo.voxelObject(*grid, tags.get(), o.transferFunction, transferKey);
        o.compositing = vo.compositing() == VolumeObject::MIP           ? ObjectCompositing::MIP
                        : vo.compositing() == VolumeObject::SURFACE_HIT ? ObjectCompositing::Surface
                                                                        : ObjectCompositing::DVR;
        o.unclipped = {modeOf(vo.renderMode()), vo.opacity()};
        o.clipped = {modeOf(vo.clippedRenderMode()), vo.clippedOpacity()};
        o.contourColor = vo.contourColor();
        o.contourSharpness = vo.contourSharpness();
        o.shininess = vo.shininess();
        o.thinLayer = vo.voxels() == VolumeObject::SURFACE;
        o.clipPlanes = localPlanes;
        std::uint64_t clipKey = worldPlanes.empty() ? 0 : planeKey;
        if (scope.box.node) {
            ShearWarpBox box;
            box.localToBox = glm::inverse(scope.box.model) * model;
            box.origin = glm::dvec3(scope.box.node->origin());
            box.extent = glm::dvec3(scope.box.node->extent());
            o.box = box;
            clipKey =
                mixKey(clipKey == 0 ? 0xcbf29ce484222325ULL : clipKey, scope.box.node->version());
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r)
                    clipKey = mixKey(clipKey, bitsOf(box.localToBox[c][r]));
        }
        // Also re-split when the model matrix moves the volume against world clip planes.
        if (clipKey != 0)
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r)
                    clipKey = mixKey(clipKey, bitsOf(worldToLocal[c][r]));
        o.clipKey = clipKey;
        o.tableKey = mixKey(mixKey(vo.version(), transferKey), 1);
        out.push_back(std::move(o));
        if (sources) sources->push_back(&vo);
    }
    if (packed) packed->checkObjectCount(out.size());
    return out;
}

std::optional<RayCastVolume> ShearWarpVolume::describeForReference(const State& state) {
    std::vector<VolumeObject*> sources;
    const std::vector<ShearWarpObject> objects = gatherObjects(state, &sources);
    const VolumeData* data = state.nearestNode<VolumeData>();
    if (!data) throw Error("ShearWarpVolume without VolumeData in scope");
    RayCastVolume out;
    out.data = data->grid();
    out.tags = data->tagGrid();
    out.model = state.modelMatrix();
    bool allMip = !objects.empty(), anyWhole = false;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const VolumeObject& vo = *sources[i];
        if (objects[i].compositing != ObjectCompositing::MIP) allMip = false;
        const int key = vo.source() == VolumeObject::TAG ? vo.tag() : -1;
        if (key == -1) anyWhole = true;
        out.transferFunctions.insert_or_assign(key, objects[i].transferFunction);
    }
    if (!anyWhole) { // voxels of no object are not drawn
        TransferFunction1D none;
        none.setChannel(TransferFunction1D::Alpha, {{0.0, 0.0}});
        out.transferFunctions.insert_or_assign(-1, none);
    }
    out.mode = allMip ? VolumeRenderMode::MIP : VolumeRenderMode::DVR;
    if (!objects.empty() && objects.front().box) {
        RayCastBoxClip box;
        box.origin = objects.front().box->origin;
        box.extent = objects.front().box->extent;
        box.model = out.model * glm::inverse(objects.front().box->localToBox);
        box.insideOpacity = 1.0;
        box.outsideOpacity = objects.front().clipped.opacity;
        out.boxClip = box;
    }
    for (const StateEntry& e : state.entries())
        if (e.node->isA<ClipPlane>())
            out.clipPlanes.push_back(
                ClipPlane::worldPlane(static_cast<const ClipPlane&>(*e.node).plane(), e.model));
    return out;
}

void ShearWarpVolume::doAction(Action& action) {
    // The state nodes among the children apply to the objects only.
    action.state().push();
    Group::doAction(action);
    action.state().pop();
}

int ShearWarpVolume::sliceStepFor(bool interactive, double interactivePlaneScale) const {
    constexpr int maximumStep = 16;
    if (!interactive) return 1;
    const double scale = interactivePlaneScale > 0.0 ? std::min(interactivePlaneScale, 1.0) : 1.0;
    const double step = std::max(1, interactiveSliceStep()) / scale;
    return int(std::clamp(std::lround(step), 1L, long(maximumStep)));
}

void ShearWarpVolume::render(RenderAction& action) {
    if (action.pass() != RenderPass::Volume) return;
    std::vector<VolumeObject*> sources;
    std::vector<ShearWarpObject> objects = gatherObjects(action.state(), &sources);
    if (objects.empty()) return;

    const RenderView& rv = action.view();
    ShearWarpView view;
    view.modelView = rv.view * action.state().modelMatrix();
    view.projection = rv.projection;
    view.width = rv.width;
    view.height = rv.height;
    view.interObject =
        interObjectCompositing() == MIP ? InterObjectCompositing::MIP : InterObjectCompositing::DVR;
    view.threads = threads();
    view.valueSortedMip = valueSortedMip();
    view.sliceStep = sliceStepFor(action.isInteractive(), action.interactivePlaneScale());
    std::vector<SceneLight> lights;
    action.lightsInScope(lights);
    for (const SceneLight& l : lights)
        if (l.vector.w == 0.0f) { // the first directional light (or the headlight)
            view.lightDirection = glm::dvec3(rv.view * glm::dvec4(glm::dvec3(l.vector), 0.0));
            break;
        }

    // The opaque depth of this frame: voxels behind it do not count. Only read when something
    // drew into the depth buffer before (shapes, glTF, slices and shear-warp surfaces count
    // their draws, as for the Volume slicer); otherwise it is all 1.
    RenderTarget& target = action.target();
    if (action.shapeRenderer().drawsLastFrame() > 0) {
        target.framebuffer().bind(GL_READ_FRAMEBUFFER);
        view.opaqueWindowDepth.resize(std::size_t(rv.width) * std::size_t(rv.height));
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(0, 0, rv.width, rv.height, GL_DEPTH_COMPONENT, GL_FLOAT,
                     view.opaqueWindowDepth.data());
        for (int y = 0; y < rv.height / 2; ++y) // GL rows are bottom-up
            std::swap_ranges(view.opaqueWindowDepth.begin() + std::ptrdiff_t(y) * rv.width,
                             view.opaqueWindowDepth.begin() + std::ptrdiff_t(y + 1) * rv.width,
                             view.opaqueWindowDepth.begin() +
                                 std::ptrdiff_t(rv.height - 1 - y) * rv.width);
    }

    if (lastFrame_) { // its buffers serve the new frame
        renderer_.recycle(std::move(*lastFrame_));
        lastFrame_.reset();
    }
    lastFrame_ = std::make_unique<ShearWarpFrame>(renderer_.render(objects, view));
    lastSources_ = sources;
    lastObjects_.clear();
    for (const ShearWarpObject& o : objects)
        lastObjects_.push_back(o.object);
    lastModel_ = action.state().modelMatrix();
    if (const VolumeData* data = action.state().nearestNode<VolumeData>();
        data && data->isA<VolumeSeries>()) // prefetched steps get this view's RenderList
        static_cast<const VolumeSeries*>(data)->setViewAxis(lastFrame_->stats.principalAxis);
    if (optimize()) {
        std::vector<std::pair<ref_ptr<VoxelObject>, int>> lists;
        for (const ShearWarpObject& o : objects)
            lists.emplace_back(o.object, lastFrame_->stats.principalAxis);
        if (!optimizer_) optimizer_ = std::make_unique<VoxelListOptimizer>(); // its thread
        optimizer_->schedule(std::move(lists));
    }

    // Composite the premultiplied image (blending as set for the Volume pass), then write the
    // depth of opaque results so later geometry mixes with them.
    ShearWarpGl& gl = action.cache<ShearWarpGl>(*this);
    if (!gl.program) {
        const Shader vertex(GL_VERTEX_SHADER, kCompositeVertex, "shear-warp composite");
        const Shader fragment(GL_FRAGMENT_SHADER, kCompositeFragment, "shear-warp composite");
        gl.program = Program({&vertex, &fragment}, "shear-warp composite");
        gl.vertexArray = VertexArray::create();
        gl.color = Texture(GL_TEXTURE_2D);
        gl.depth = Texture(GL_TEXTURE_2D);
        gl.color.setFilter(GL_NEAREST, GL_NEAREST);
        gl.depth.setFilter(GL_NEAREST, GL_NEAREST);
    }
    // Only the rectangle the warp wrote is uploaded and drawn: outside it the image is 0
    // (nothing to blend) and the depth 1.
    const ShearWarpFrame& f = *lastFrame_;
    const glm::ivec4 drawn = f.drawn;
    if (drawn.x >= drawn.z || drawn.y >= drawn.w) return;
    glActiveTexture(GL_TEXTURE0);
    if (gl.size != glm::ivec2(rv.width, rv.height)) {
        gl.color.image2D(GL_RGBA32F, rv.width, rv.height, GL_RGBA, GL_FLOAT, nullptr);
        gl.depth.image2D(GL_R32F, rv.width, rv.height, GL_RED, GL_FLOAT, nullptr);
        gl.size = glm::ivec2(rv.width, rv.height);
    }
    // The rectangle alone (texels outside it are never read: the draw is scissored to it).
    const std::size_t first = std::size_t(drawn.y) * std::size_t(rv.width) + std::size_t(drawn.x);
    const int width = drawn.z - drawn.x, height = drawn.w - drawn.y;
    gl.color.subImage(drawn.x, drawn.y, 0, width, height, 1, GL_RGBA, GL_FLOAT,
                      f.image.pixels.data() + first, rv.width);
    if (f.wroteDepth)
        gl.depth.subImage(drawn.x, drawn.y, 0, width, height, 1, GL_RED, GL_FLOAT,
                          f.windowDepth.data() + first, rv.width);
    target.bind();
    const GLboolean scissorWasOn = glIsEnabled(GL_SCISSOR_TEST);
    GLint scissorBox[4];
    glGetIntegerv(GL_SCISSOR_BOX, scissorBox);
    glEnable(GL_SCISSOR_TEST);
    glScissor(drawn.x, rv.height - drawn.w, drawn.z - drawn.x, drawn.w - drawn.y); // GL: bottom-up
    gl.color.bind(0);
    gl.depth.bind(1);
    gl.program.use();
    gl.program.set("uColor", 0);
    gl.program.set("uDepth", 1);
    gl.vertexArray.bind();
    glDisable(GL_DEPTH_TEST);
    gl.program.set("uDepthPass", 0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnable(GL_DEPTH_TEST);
    if (f.wroteDepth) {
        glDepthFunc(GL_ALWAYS);
        glDepthMask(GL_TRUE);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        gl.program.set("uDepthPass", 1);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthMask(GL_FALSE);
        glDepthFunc(GL_LESS);
        action.shapeRenderer().countDraw(); // later volumes must read the depth written
    }
    if (!scissorWasOn) glDisable(GL_SCISSOR_TEST);
    glScissor(scissorBox[0], scissorBox[1], scissorBox[2], scissorBox[3]);
    VertexArray::unbind();
    glActiveTexture(GL_TEXTURE0);
}

std::optional<ShearWarpVolume::Pick> ShearWarpVolume::pickAt(int x, int y) const {
    if (!lastFrame_) return std::nullopt;
    const auto hit = ShearWarpRenderer::pick(*lastFrame_, x, y);
    if (!hit || hit->object < 0 || std::size_t(hit->object) >= lastSources_.size())
        return std::nullopt;
    Pick pick;
    pick.object = lastSources_[std::size_t(hit->object)];
    pick.worldPosition = glm::dvec3(lastModel_ * glm::dvec4(hit->localPosition, 1.0));
    return pick;
}

std::size_t ShearWarpVolume::voxelListBytes() const {
    std::size_t bytes = 0;
    for (const auto& object : lastObjects_)
        bytes += object->memoryBytes();
    return bytes;
}

void ShearWarpVolume::waitForOptimizer() {
    if (optimizer_) optimizer_->waitUntilIdle();
}

void ShearWarpVolume::readDone(const ReadContext& context) {
    directory_ = context.directory;
}

void ShearWarpVolume::getBoundingBox(BoundingBoxAction& action) {
    if (!voxelFile().empty()) {
        PackedVolume::load(voxelFile(), directory_).extendBoundingBox(action);
        return;
    }
    if (const VolumeData* data = action.state().nearestNode<VolumeData>())
        data->extendBoundingBox(action);
}

} // namespace volsg
