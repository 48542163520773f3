#include <volsg/actions/Action.h>

namespace volsg {

void Action::apply(Node& root) {
    state_.reset();
    path_.clear();
    terminated_ = false;
    beginTraversal(root);
}

void Action::beginTraversal(Node& root) {
    traverse(root);
}

void Action::traverse(Node& node) {
    if (terminated_) return;
    path_.push_back(&node);
    dispatch(node);
    path_.pop_back();
}

} // namespace volsg
