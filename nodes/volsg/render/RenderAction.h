#pragma once
// The traversal that draws: one per pass, with the frame's camera, target and caches.

#include <vector>

#include <glm/glm.hpp>

#include <volsg/actions/Action.h>
#include <volsg/actions/ActionMethods.h>
#include <volsg/render/FrameContext.h>

namespace volsg {

/// Draws a graph into the frame of a Renderer, one RenderPass at a time (FrameContext.h says
/// what each pass draws). What a node type draws is the render method registered for it
/// (methods(); the library's own types have theirs in nodes/volsg/render/*Rendering.cpp); a
/// type without one only does its state work (Node::doAction).
class RenderAction : public Action {
public:
    explicit RenderAction(FrameContext& frame) : frame_(frame) {}

    /// The render methods by node type. An application drawing its own node type adds its
    /// method here: `RenderAction::methods().add(&drawMyNode)` with
    /// `void drawMyNode(RenderAction&, MyNode&)`.
    static ActionMethods& methods();

    FrameContext& frame() { return frame_; }
    RenderPass pass() const { return frame_.pass; }
    void setPass(RenderPass pass) { frame_.pass = pass; }
    /// The user is moving the view: volumes use their fast settings.
    bool isInteractive() const { return frame_.interactive; }
    const RenderView& view() const { return frame_.view; }
    const glm::dmat4& viewMatrix() const { return frame_.view.view; }
    const glm::dmat4& projectionMatrix() const { return frame_.view.projection; }

    /// Says the frame draws a volume or section: it needs the float target. Volume render
    /// methods call it in every pass, before anything else.
    void needFloatTarget() { frame_.floatTargetNeeded = true; }
    /// Counts one more volume drawn in this frame; throws Error past limits::maxVolumeInstances
    /// (each volume costs a whole pass over its data: 100,000 USEs of one would never end).
    void countVolumeInstance();
    /// Counts `glyphs` more screen-text characters laid out in this frame; throws Error past
    /// limits::maxFrameTextGlyphs (a long Text2 USEd thousands of times would never end).
    void countTextGlyphs(std::size_t glyphs);

    /// The lights in scope at the current node (plus the headlight when the scene has no
    /// light), in world coordinates. Fills `out` (cleared first) to reuse its memory.
    void lightsInScope(std::vector<SceneLight>& out) const;
    /// The ClipPlanes in scope as world planes (a, b, c, d), keeping a*x + b*y + c*z >= d.
    void clipPlanesInScope(std::vector<glm::dvec4>& out) const;

protected:
    /// Gives the state the frame's view (projected, in pixels), as the shapes whose
    /// tessellation follows the view (SCREEN_SPACE complexity) read it.
    void beginTraversal(Node& root) override;
    void dispatch(Node& node) override;

private:
    FrameContext& frame_;
};

} // namespace volsg
