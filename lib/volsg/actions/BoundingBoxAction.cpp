#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/nodes/Separator.h>

namespace volsg {

// Nodes without geometry (groups, transforms, properties, cameras, lights, clip planes) only
// do their state work here; shapes add their mesh bounds (Shape::getBoundingBox). ClipPlanes
// do not shrink the box, as in Inventor.
void Node::getBoundingBox(BoundingBoxAction& action) {
    doAction(action);
}

void BoundingBoxAction::extendByLocal(const Box3& local) {
    box_.extendBy(local, state().modelMatrix());
}

void BoundingBoxAction::beginTraversal(Node& root) {
    box_ = Box3{};
    Action::beginTraversal(root);
}

void BoundingBoxAction::dispatch(Node& node) {
    if (!node.isA<Separator>()) {
        node.getBoundingBox(*this);
        return;
    }
    // A Separator's children start from an empty box and the box from before it is added back
    // after them, so emptyBoxInScope() inside it forgets only what its own children added.
    Box3 before = box_;
    box_ = Box3{};
    node.getBoundingBox(*this);
    before.extendBy(box_);
    box_ = before;
}

Box3 computeBoundingBox(Node& root) {
    BoundingBoxAction action;
    action.apply(root);
    return action.boundingBox();
}

} // namespace volsg
