#pragma once
// Computes the world-space bounding box of everything a render would draw.

#include <volsg/actions/Action.h>
#include <volsg/actions/ActionMethods.h>
#include <volsg/math/Box3.h>

namespace volsg {

/// Inventor's SoGetBoundingBoxAction. Nodes without geometry (groups, transforms, properties,
/// cameras, lights, clip planes) only do their state work; shapes, volumes, slices and glTF
/// models add their local box (the methods in BoundingBoxAction.cpp). ClipPlanes do not
/// shrink the box, as in Inventor.
class BoundingBoxAction : public Action {
public:
    /// The bounding-box methods by node type (see RenderAction::methods()).
    static ActionMethods& methods();

    /// The box so far, in world coordinates.
    const Box3& boundingBox() const { return box_; }
    /// Adds a box given in the current node's local coordinates (uses the state's model matrix).
    void extendByLocal(const Box3& local);
    /// Empties the box accumulated so far inside the innermost Separator being traversed (the
    /// whole box outside any Separator): ResetTransform's BBOX, as Inventor's separators keep
    /// the box from before them apart from their children's.
    void emptyBoxInScope() { box_ = Box3{}; }

protected:
    void beginTraversal(Node& root) override;
    void dispatch(Node& node) override;

private:
    Box3 box_;
};

/// The world bounding box of a graph (empty if it draws nothing).
Box3 computeBoundingBox(Node& root);

} // namespace volsg
