#pragma once
// What the clip-plane, box and transform manipulators share: standing in for a plain node in
// the scene while active (Inventor's replaceNode / replaceManip), drawing pickable handles, and
// turning mouse rays into field changes that are written back to the plain node.

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/core/Node.h>
#include <volsg/manipulators/DraggerGeometry.h>
#include <volsg/math/Ray.h>

namespace volsg {

class Action;

/// Copies every field value of `from` into `to` (same node type, or one derived from the
/// other with the same fields), keeping each field's default flag, so a field never set stays
/// unwritten. Fields whose values are already equal are left alone (no version bump).
void copyFieldValues(const Node& from, Node& to);

/// Replaces every occurrence of `from` among the children of groups under `root` (each group
/// once, so USE-shared groups are not visited twice) by `to`; returns how many were replaced.
int replaceNodeInGraph(Node& root, const Node& from, const ref_ptr<Node>& to);

/// Base of the manipulator nodes. A manipulator derives from the node type it edits (a
/// ClipPlaneManip is a ClipPlane), so while it stands in the graph it does everything the plain
/// node does, and draws its handles before it, outside the clipping in scope (so no clip plane,
/// its own included, hides or disables them).
///
/// The render and pick actions reach a manipulator through methods of their own
/// (handlesThenState), added to RenderAction and PickAction when the first one is made.
class Manipulator {
public:
    Manipulator();
    virtual ~Manipulator() = default;

    /// The manipulator as a node of the graph.
    virtual Node& node() = 0;

    /// Puts this manipulator where `original` is under `root` (every occurrence) after copying
    /// the original's fields. Returns false when `original` is not under `root`.
    bool attach(Node& root, Node& original);
    /// Writes the fields back and puts the original node back in place.
    void detach();
    bool isAttached() const { return root_ != nullptr; }
    Node* original() const { return original_.get(); }
    /// Copies this manipulator's fields into the original node (done after every drag step, so
    /// the plain node always holds what is shown).
    void writeBack();

    /// How large the handles are drawn, in world units (the viewer passes the scene's size).
    void setHandleSize(double worldSize) { handleSize_ = worldSize; }
    /// A world point the handles stay near (the scene's centre), e.g. where on an infinite clip
    /// plane its frame is drawn.
    void setAnchor(const glm::dvec3& worldPoint) { anchor_ = worldPoint; }

    /// Starts a drag when `pickPath` (from a PickAction of the world ray) goes through one of
    /// the handles; returns false otherwise, leaving everything unchanged.
    bool beginDrag(const Ray& worldRay, const std::vector<Node*>& pickPath);
    /// Moves the dragged handle to follow the world ray and writes the fields back.
    void drag(const Ray& worldRay);
    void endDrag();
    bool isDragging() const { return activePart_ >= 0; }
    /// The handle being dragged (an id of the manipulator's own part list), -1 when none.
    int activePart() const { return activePart_; }

    /// What the render and pick actions do with a manipulator: its handles, then what the
    /// plain node does (its doAction).
    void handlesThenState(Action& action);

    /// The model matrix at the manipulator in the last traversal that drew or picked it.
    const glm::dmat4& model() const { return model_; }
    void setModel(const glm::dmat4& model) { model_ = model; }

protected:
    /// Records the model matrix, re-places the handles and traverses them.
    void drawHandles(Action& action);
    /// Handle size and anchor in the manipulator's local coordinates.
    double localHandleSize() const;
    glm::dvec3 localAnchor() const;

    /// The handles, built on first use (not in the constructor: node types record their field
    /// tables from a prototype, and the handles' own nodes must not be built into it).
    DraggerGeometry& handles();
    virtual void buildHandles(DraggerGeometry& handles) = 0;
    virtual void placeHandles() = 0;
    /// The drag of part `part` starts with the local ray; the subclass keeps what it needs.
    virtual void startDrag(int part, const Ray& localRay) = 0;
    virtual void continueDrag(int part, const Ray& localRay) = 0;

private:
    std::unique_ptr<DraggerGeometry> handles_;
    Ray toLocal(const Ray& worldRay) const;
    ref_ptr<Node> original_;
    Node* root_ = nullptr; ///< not owned: the viewer owns the scene and detaches before dropping it
    double handleSize_ = 1.0;
    glm::dvec3 anchor_{0.0};
    glm::dmat4 model_{1.0};
    int activePart_ = -1;
};

} // namespace volsg
