#include <volsg/actions/BoundingBoxAction.h>

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
    node.getBoundingBox(*this);
}

Box3 computeBoundingBox(Node& root) {
    BoundingBoxAction action;
    action.apply(root);
    return action.boundingBox();
}

} // namespace volsg
