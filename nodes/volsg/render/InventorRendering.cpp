// Render methods of the Inventor nodes that draw other than by their doAction: LOD and
// LevelOfDetail (one child, chosen by the frame's camera), Annotation (its children after the
// rest of the frame, without depth test) and File (its read error).
#include <limits>
#include <memory>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/gl/GlLoader.h>
#include <volsg/nodes/Annotation.h>
#include <volsg/nodes/File.h>
#include <volsg/nodes/LOD.h>
#include <volsg/nodes/LevelOfDetail.h>
#include <volsg/render/BuiltinRendering.h>
#include <volsg/render/InventorRendering.h>
#include <volsg/render/RenderAction.h>
#include <volsg/render/ShapeRenderer.h>

namespace volsg {

int levelOfDetailChild(const State& state, LevelOfDetail& node, const glm::dmat4& view,
                       const glm::dmat4& projection, int width, int height) {
    if (node.getNumChildren() <= 1 || node.screenArea.empty()) return node.childFor(0.0);
    // The box of all the children in the node's coordinates, with what is in scope here (a
    // Coordinate3 for an IndexedFaceSet, a VolumeData for a Volume).
    BoundingBoxAction boxes;
    boxes.state() = state;
    boxes.state().setModelMatrix(glm::dmat4(1.0));
    for (std::size_t i = 0; i < node.getNumChildren(); ++i)
        if (Node* child = node.getChild(i)) boxes.traverse(*child);
    const glm::ivec2 size = LevelOfDetail::screenSize(
        boxes.boundingBox(), projection * view * state.modelMatrix(), width, height);
    return node.childFor(double(size.x) * double(size.y));
}

namespace {

void traverseChild(RenderAction& action, Group& group, int index) {
    if (index < 0 || std::size_t(index) >= group.getNumChildren()) return;
    if (Node* child = group.getChild(std::size_t(index))) action.traverse(*child);
}

void renderLOD(RenderAction& action, LOD& node) {
    const glm::dvec3 eye(glm::inverse(action.viewMatrix())[3]);
    traverseChild(action, node, node.childFor(eye, action.state().modelMatrix()));
}

void renderLevelOfDetail(RenderAction& action, LevelOfDetail& node) {
    const RenderView& view = action.view();
    traverseChild(action, node,
                  levelOfDetailChild(action.state(), node, view.view, view.projection, view.width,
                                     view.height));
}

/// The shape renderer of the annotations: their transparent shapes queue and sort among
/// themselves while the frame's renderer is going through its own queue.
struct AnnotationShapes {
    std::unique_ptr<ShapeRenderer> shapes;
};

/// Set while annotations are drawn: an Annotation inside one is a plain Separator.
thread_local bool drawingAnnotation = false;

/// Draws an Annotation's children at the end of the frame: the opaque ones, then the
/// transparent ones back to front, all without depth test (so nothing hides them and they do
/// not hide each other by depth: later ones are drawn over earlier ones).
void drawAnnotation(FrameContext& frame, const State& state, Annotation& node) {
    AnnotationShapes& own = frame.cache.shared<AnnotationShapes>();
    if (!own.shapes) {
        own.shapes = std::make_unique<ShapeRenderer>();
        own.shapes->setBatching(false); // no depth test: scene order decides
    }
    ShapeRenderer& shapes = *own.shapes;
    FrameContext sub{frame.cache,
                     shapes,
                     frame.target,
                     frame.view,
                     RenderPass::Opaque,
                     frame.interactive,
                     frame.interactivePlaneScale,
                     frame.debug};
    RenderAction action(sub);
    struct Flag {
        Flag() { drawingAnnotation = true; }
        ~Flag() { drawingAnnotation = false; }
    } flag;
    shapes.beginFrame(frame.view);
    glDisable(GL_DEPTH_TEST);
    for (RenderPass pass : {RenderPass::Opaque, RenderPass::Transparent}) {
        if (pass == RenderPass::Opaque)
            glDisable(GL_BLEND);
        else
            glEnable(GL_BLEND);
        shapes.beginPass();
        action.setPass(pass);
        action.state() = state;
        action.traverse(node);
        if (pass == RenderPass::Transparent) shapes.drawQueuedTransparent();
    }
    shapes.endFrame();
    // Back to the transparent pass's state (FrameContext.h), for the draws queued after this.
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    frame.shapes.beginPass(); // its clip distances were switched off behind its back
}

void renderAnnotation(RenderAction& action, Annotation& node) {
    if (drawingAnnotation || action.pass() == RenderPass::Volume) {
        // Inside an annotation being drawn, and in the volume pass (volumes under an Annotation
        // are drawn as under a Separator): a Separator.
        node.doAction(action);
        return;
    }
    if (action.pass() != RenderPass::Transparent) return; // the opaque pass: drawn later
    // Last of all the frame's transparent draws (they run farthest first).
    FrameContext& frame = action.frame();
    auto state = std::make_shared<const State>(action.state());
    ref_ptr<Annotation> keep(&node);
    frame.shapes.queueTransparent(std::numeric_limits<double>::infinity(),
                                  [&frame, state, keep] { drawAnnotation(frame, *state, *keep); });
}

void renderFile(RenderAction& action, File& node) {
    node.update();
    if (node.readError()) throw *node.readError();
    node.doAction(action);
}

} // namespace

void addInventorRenderMethods(ActionMethods& methods) {
    methods.add(&renderLOD);
    methods.add(&renderLevelOfDetail);
    methods.add(&renderAnnotation);
    methods.add(&renderFile);
}

} // namespace volsg
