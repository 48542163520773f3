#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/core/Error.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/Light.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/render/ImageCompositor.h>
#include <volsg/render/RenderAction.h>
#include <volsg/render/RenderCache.h>
#include <volsg/render/RenderTarget.h>
#include <volsg/render/Renderer.h>
#include <volsg/render/ShapeRenderer.h>
#include <volsg/render/SharedMeshes.h>

#include <algorithm>
#include <atomic>
#include <cstdio>

namespace volsg {

namespace {

/// Walks the scene as every action does (doAction on each node, so transforms and
/// separators act) and notes the first Camera with its model matrix, whether any light is on
/// and whether a ShearWarpVolume is drawn. Stops as soon as it knows what it was asked for (so
/// the last is known when there is no camera).
class SceneSurveyAction : public Action {
public:
    explicit SceneSurveyAction(bool wantLights) : wantLights_(wantLights) {}

    Camera* camera() const { return camera_.get(); }
    const glm::dmat4& cameraModel() const { return cameraModel_; }
    bool hasLight() const { return hasLight_; }
    bool hasShearWarpVolume() const { return hasShearWarp_; }

protected:
    void dispatch(Node& node) override {
        if (!camera_ && node.isA<Camera>()) {
            camera_ = ref_ptr<Camera>(static_cast<Camera*>(&node));
            cameraModel_ = state().modelMatrix();
        }
        if (node.isA<Light>() && static_cast<Light&>(node).on()) hasLight_ = true;
        if (node.isA<ShearWarpVolume>()) hasShearWarp_ = true;
        node.doAction(*this);
        if (camera_ && (hasLight_ || !wantLights_)) terminate();
    }

private:
    bool wantLights_;
    ref_ptr<Camera> camera_;
    glm::dmat4 cameraModel_{1.0};
    bool hasLight_ = false;
    bool hasShearWarp_ = false;
};

/// The camera of a scene without one: perspective, or orthographic when the scene draws a
/// ShearWarpVolume (which renders parallel projections only).
SceneCamera makeViewAllCamera(Node& root, double aspect, bool orthographic) {
    ref_ptr<Camera> camera;
    if (orthographic)
        camera = OrthographicCamera::create();
    else
        camera = PerspectiveCamera::create();
    const Box3 box = computeBoundingBox(root);
    camera->viewAll(box, aspect);
    try {
        camera->check(glm::dmat4(1.0));
    } catch (const Error& e) {
        // The camera was made, not read: what is at fault is the scene's extent.
        char extent[160];
        std::snprintf(extent, sizeof extent, "from (%.3g, %.3g, %.3g) to (%.3g, %.3g, %.3g)",
                      box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z);
        const Error why("the scene has no camera, and none can view its bounding box " +
                        std::string(extent) + " whole (" + e.message() + "): give it a camera");
        const SourcePlace& place = root.sourcePlace();
        if (!place.file) throw why;
        throw Error::atSceneNode(why, root.description(), *place.file, place.line, place.column);
    }
    return {camera, glm::dmat4(1.0)};
}

/// The fixed GL state each pass starts from (see RenderPass).
void setPassState(RenderPass pass) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    switch (pass) {
    case RenderPass::Opaque:
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
        break;
    case RenderPass::Volume:
        glDepthMask(GL_FALSE);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        break;
    case RenderPass::Transparent:
        glDepthMask(GL_FALSE);
        glEnable(GL_BLEND);
        // Colour: src over dst with alpha = 1 - transparency. Alpha: coverage accumulates.
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        break;
    }
}

/// The framebuffer bindings of the caller, put back when a render is done (or throws).
class BoundFramebuffers {
public:
    BoundFramebuffers() {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_);
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_);
    }
    ~BoundFramebuffers() {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(draw_));
        glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(read_));
    }
    BoundFramebuffers(const BoundFramebuffers&) = delete;
    BoundFramebuffers& operator=(const BoundFramebuffers&) = delete;
    GLuint draw() const { return GLuint(draw_); }

private:
    GLint draw_ = 0, read_ = 0;
};

/// The bits of red in the colour buffer `framebuffer` draws into (0: the window's); 32 when
/// GL does not say.
int drawBufferBits(GLuint framebuffer) {
    GLint buffer = GL_NONE;
    glGetIntegerv(GL_DRAW_BUFFER0, &buffer);
    // The default framebuffer names its buffers GL_BACK and GL_FRONT; their attachments are
    // the left ones.
    if (framebuffer == 0 && buffer == GL_BACK) buffer = GL_BACK_LEFT;
    if (framebuffer == 0 && buffer == GL_FRONT) buffer = GL_FRONT_LEFT;
    if (buffer == GL_NONE) return 32;
    GLint bits = 32;
    glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GLenum(buffer),
                                          GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE, &bits);
    // A query GL refuses leaves an error behind; it must not reach the caller's next check.
    while (glGetError() != GL_NO_ERROR) {
    }
    return bits > 0 ? bits : 32;
}

/// GL's row 0 is the bottom; the Image's is the top.
template <class T> void flipRows(std::vector<T>& pixels, int width, int height) {
    const std::size_t w = std::size_t(width);
    for (std::size_t top = 0, bottom = std::size_t(height) - 1; top < bottom; ++top, --bottom)
        std::swap_ranges(pixels.begin() + std::ptrdiff_t(top * w),
                         pixels.begin() + std::ptrdiff_t((top + 1) * w),
                         pixels.begin() + std::ptrdiff_t(bottom * w));
}

} // namespace

SceneCamera findOrMakeCamera(Node& root, double viewportAspect) {
    SceneSurveyAction survey(false);
    survey.apply(root);
    if (survey.camera()) return {ref_ptr<Camera>(survey.camera()), survey.cameraModel()};
    return makeViewAllCamera(root, viewportAspect, survey.hasShearWarpVolume());
}

struct Renderer::Impl {
    RenderCache cache;
    ShapeRenderer shapes;
    RenderTarget target;
    RenderStats stats;
    ImageCompositor depthWriter; ///< writes RenderOptions::opaqueDepth (sort-last)
    bool inViewGroup = false;    ///< the cache frame spans several renders (beginViewGroup)
    /// The last frame drew a volume: this one starts on the float target.
    bool floatTarget = false;

    /// The last frame was drawn on the CPU into `cpuFrame` (the GL target is stale).
    bool lastOnCpu = false;
    Image cpuFrame;

    /// Draws one frame seen as `view` (frameView) into `target` (left bound).
    void drawFrame(Node& root, const RenderOptions& options, const RenderView& view);
    /// Draws one frame into `cpuFrame` without GL where the scene allows (RenderDebug::cpuFrames:
    /// it draws nothing but CPU images); false, and nothing drawn, where it does not.
    bool drawCpuFrame(Node& root, const RenderOptions& options, const RenderView& view);
    /// The frame's camera, as every render takes it (the scene's, the options', or one made).
    RenderView frameView(Node& root, const RenderOptions& options) const;
    /// A new frame's context: this render's serial, the options' switches and partition.
    FrameContext frameOf(const RenderOptions& options, const RenderView& view);
    /// What the last frame did, into `stats`.
    void noteFrame(const FrameContext& frame);
};

namespace {
std::atomic<std::uint64_t> renders{0}; ///< FrameContext::renderSerial
} // namespace

RenderView Renderer::Impl::frameView(Node& root, const RenderOptions& options) const {
    if (options.width <= 0 || options.height <= 0)
        throw Error("render size " + std::to_string(options.width) + "x" +
                    std::to_string(options.height) + " is empty");
    const double aspect = double(options.width) / double(options.height);

    SceneSurveyAction survey(true);
    survey.apply(root);
    SceneCamera scene;
    if (options.camera)
        scene = {options.camera, glm::dmat4(1.0)};
    else if (survey.camera())
        scene = {ref_ptr<Camera>(survey.camera()), survey.cameraModel()};
    else
        scene = makeViewAllCamera(root, aspect, survey.hasShearWarpVolume());
    scene.camera->check(scene.model);

    RenderView view;
    view.view = scene.camera->viewMatrix(scene.model);
    view.projection = scene.camera->projectionMatrix(aspect);
    view.width = options.width;
    view.height = options.height;
    // An affine projection (last row 0 0 0 1) is orthographic: every ray has one direction.
    view.orthographic = view.projection[3][3] == 1.0 && view.projection[2][3] == 0.0;
    const glm::dmat4 eyeToWorld = glm::inverse(view.view);
    view.viewer = view.orthographic ? glm::dvec4(glm::normalize(glm::dvec3(eyeToWorld[2])), 0.0)
                                    : glm::dvec4(glm::dvec3(eyeToWorld[3]), 1.0);
    view.headlight = !survey.hasLight();
    return view;
}

FrameContext Renderer::Impl::frameOf(const RenderOptions& options, const RenderView& view) {
    FrameContext frame{cache,
                       shapes,
                       target,
                       view,
                       RenderPass::Opaque,
                       options.interactive,
                       options.interactivePlaneScale,
                       options.debug};
    frame.renderSerial = ++renders;
    frame.partition = options.partition;
    return frame;
}

bool Renderer::Impl::drawCpuFrame(Node& root, const RenderOptions& options,
                                  const RenderView& view) {
    if (!options.debug.cpuFrames || options.volumePartial || options.opaqueOnly ||
        options.opaqueDepth || options.samples > 1 || inViewGroup)
        return false;
    cpuFrame.width = options.width;
    cpuFrame.height = options.height;
    cpuFrame.pixels.assign(std::size_t(options.width) * std::size_t(options.height),
                           glm::vec4(options.background, 1.0f));
    FrameContext frame = frameOf(options, view);
    // Separators traverse their children: a render cache would replay GL draws unseen.
    frame.debug.renderCaching = false;
    frame.cpuImage = &cpuFrame;
    // A refused frame ends no cache frame: the GL frame after it marks what it uses and
    // drops the rest, as after any frame.
    cache.beginFrame();
    shapes.beginFrame(view);
    RenderAction action(frame);
    for (RenderPass pass : {RenderPass::Opaque, RenderPass::Volume, RenderPass::Transparent}) {
        action.setPass(pass);
        action.apply(root);
        if (frame.needsGl) return false;
    }
    cache.endFrame();
    floatTarget = frame.floatTargetNeeded;
    lastOnCpu = true;
    noteFrame(frame);
    return true;
}

void Renderer::Impl::drawFrame(Node& root, const RenderOptions& options, const RenderView& view) {
    lastOnCpu = false;
    const bool floatColor = floatTarget || options.volumePartial ||
                            !(options.eightBitOutput || options.debug.byteTarget);
    target.resize(options.width, options.height, floatColor);
    const bool multisample = target.setMultisample(options.samples) > 1;
    if (multisample)
        target.bindMultisample();
    else
        target.bind();
    glViewport(0, 0, options.width, options.height);
    glDepthMask(GL_TRUE);
    glClearColor(options.background.r, options.background.g, options.background.b, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    if (!inViewGroup) cache.beginFrame();
    shapes.beginFrame(view);
    FrameContext frame = frameOf(options, view);
    shapes.setBatching(options.debug.batchShapes);
    shapes.setShare(options.shapeShareIndex, options.shapeShareCount);
    const bool givenDepth = options.volumePartial && options.opaqueDepth;
    if (givenDepth && !options.opaqueDepth->empty() &&
        options.opaqueDepth->size() != std::size_t(options.width) * std::size_t(options.height))
        throw Error("sort-last: the composited opaque depth is not of the frame's size");
    shapes.setLighting(options.debug.shapeLighting);
    RenderAction action(frame);
    for (RenderPass pass : {RenderPass::Opaque, RenderPass::Volume, RenderPass::Transparent}) {
        // The multisampled opaque pass is resolved into the target for everything after it.
        if (pass == RenderPass::Volume && multisample) target.resolveMultisample();
        if (options.opaqueOnly && pass != RenderPass::Opaque) break;
        if (options.volumePartial && pass == RenderPass::Transparent) break;
        if (options.volumePartial && pass == RenderPass::Volume) {
            // The opaque colour goes (rank 0 composites over its own opaque image); its depth
            // stays and stops the volume as in a whole frame.
            glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
            glClear(GL_COLOR_BUFFER_BIT);
        }
        if (givenDepth && pass == RenderPass::Opaque) continue;
        setPassState(pass);
        shapes.beginPass();
        if (givenDepth && pass == RenderPass::Volume && !options.opaqueDepth->empty()) {
            CpuImage depthOnly;
            depthOnly.windowDepth = options.opaqueDepth->data();
            depthOnly.drawn = glm::ivec4(0, 0, options.width, options.height);
            depthWriter.composite(frame, depthOnly);
        }
        action.setPass(pass);
        action.apply(root);
        if (pass == RenderPass::Opaque) shapes.flushOpaque();
        if (pass == RenderPass::Transparent) shapes.drawQueuedTransparent();
        if (pass == RenderPass::Opaque && frame.floatTargetNeeded && !floatColor) {
            // A volume on an 8-bit target: start again on the float one (the opaque pass
            // reaches every node the volume pass does, so nothing has been composited yet).
            shapes.endFrame();
            floatTarget = true;
            drawFrame(root, options, view);
            return;
        }
    }
    floatTarget = frame.floatTargetNeeded;
    shapes.endFrame();
    if (!inViewGroup) cache.endFrame();

    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    noteFrame(frame);
}

void Renderer::Impl::noteFrame(const FrameContext& frame) {
    ++stats.frames;
    stats.cpuFrame = lastOnCpu;
    stats.meshUploads = shapes.meshUploads();
    stats.programBuilds = shapes.programBuilds();
    stats.cachedEntries = cache.size();
    stats.shapeDraws = shapes.drawsLastFrame();
    stats.opaqueShapes = shapes.opaqueShapesLastFrame();
    stats.sharedOutShapes = shapes.sharedOutLastFrame();
    stats.batches = shapes.batchesLastFrame();
    stats.replayedShapes = frame.replayedShapes;
    stats.culledSeparators = frame.culledSeparators;
    stats.coarserShapes = frame.coarserShapes;
    stats.litShapes = shapes.litLastFrame();
    stats.vertexLitShapes = shapes.vertexLitLastFrame();
    stats.batchedShapes = shapes.batchedShapesLastFrame();
    stats.meshBytes = cache.shared<SharedMeshes>().bytes();
    stats.instanceBytes = shapes.instanceBytes();
    stats.drawnMeshBytes = shapes.submittedMeshBytesLastFrame();
}

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {
    impl_->stats.programBuilds = impl_->shapes.programBuilds();
}

Renderer::~Renderer() = default;

std::vector<float> Renderer::readWindowDepth() const {
    if (impl_->lastOnCpu) // nothing opaque: the depth a GL frame would hold
        return std::vector<float>(impl_->cpuFrame.pixels.size(), 1.0f);
    const RenderTarget& target = impl_->target;
    if (target.width() == 0) return {};
    const BoundFramebuffers caller;
    std::vector<float> depth(std::size_t(target.width()) * std::size_t(target.height()));
    target.framebuffer().bind(GL_READ_FRAMEBUFFER);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, target.width(), target.height(), GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    flipRows(depth, target.width(), target.height());
    checkGlError("Renderer::readWindowDepth");
    return depth;
}

void Renderer::beginViewGroup() {
    if (!impl_->inViewGroup) impl_->cache.beginFrame();
    impl_->inViewGroup = true;
}

void Renderer::endViewGroup() {
    if (!impl_->inViewGroup) return;
    impl_->inViewGroup = false;
    impl_->cache.endFrame();
    impl_->stats.cachedEntries = impl_->cache.size();
}

const RenderStats& Renderer::stats() const {
    return impl_->stats;
}

Image Renderer::render(Node& root, const RenderOptions& options) {
    Image image;
    render(root, options, image);
    return image;
}

void Renderer::render(Node& root, const RenderOptions& options, Image& into) {
    const RenderView view = impl_->frameView(root, options);
    if (impl_->drawCpuFrame(root, options, view)) {
        into.width = impl_->cpuFrame.width;
        into.height = impl_->cpuFrame.height;
        into.pixels.assign(impl_->cpuFrame.pixels.begin(), impl_->cpuFrame.pixels.end());
        return;
    }
    {
        const BoundFramebuffers caller;
        impl_->drawFrame(root, options, view);
    }
    readImage(into);
}

void Renderer::renderFrame(Node& root, const RenderOptions& options) {
    const BoundFramebuffers caller;
    impl_->drawFrame(root, options, impl_->frameView(root, options));
}

Image Renderer::readImage() const {
    Image image;
    readImage(image);
    return image;
}

void Renderer::readImage(Image& into) const {
    if (impl_->lastOnCpu) {
        into = impl_->cpuFrame;
        return;
    }
    const RenderTarget& target = impl_->target;
    const int width = target.width(), height = target.height();
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    if (into.pixels.size() != pixels) into.pixels.resize(pixels); // every pixel is read below
    into.width = width;
    into.height = height;
    if (pixels == 0) return;
    const BoundFramebuffers caller;
    target.framebuffer().bind(GL_READ_FRAMEBUFFER);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    // GL's rows run bottom-up, the Image's top-down: Mesa's GL_MESA_pack_invert reads them in
    // the Image's order (no second pass over the pixels); elsewhere they are swapped after.
    const bool invert = GLAD_GL_MESA_pack_invert != 0;
    if (invert) glPixelStorei(GL_PACK_INVERT_MESA, GL_TRUE);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, into.pixels.data());
    if (invert)
        glPixelStorei(GL_PACK_INVERT_MESA, GL_FALSE);
    else
        flipRows(into.pixels, width, height);
    checkGlError("Renderer::readImage");
}

void Renderer::renderToBoundFramebuffer(Node& root, const RenderOptions& options) {
    const BoundFramebuffers caller;
    RenderOptions o = options;
    o.eightBitOutput = o.eightBitOutput || drawBufferBits(caller.draw()) <= 8;
    impl_->drawFrame(root, o, impl_->frameView(root, o));
    impl_->target.framebuffer().bind(GL_READ_FRAMEBUFFER);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, caller.draw());
    glBlitFramebuffer(0, 0, options.width, options.height, 0, 0, options.width, options.height,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glViewport(0, 0, options.width, options.height);
    checkGlError("Renderer::renderToBoundFramebuffer");
}

} // namespace volsg
