#include <volsg/actions/Action.h>
#include <volsg/nodes/Group.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Switch.h>

namespace volsg {

void Group::addChild(ref_ptr<Node> child) {
    children_.push_back(std::move(child));
    touch();
}

void Group::insertChild(ref_ptr<Node> child, std::size_t index) {
    if (index > children_.size()) index = children_.size();
    children_.insert(children_.begin() + static_cast<std::ptrdiff_t>(index), std::move(child));
    touch();
}

void Group::removeChild(std::size_t index) {
    if (index >= children_.size()) return;
    children_.erase(children_.begin() + static_cast<std::ptrdiff_t>(index));
    touch();
}

void Group::removeAllChildren() {
    children_.clear();
    touch();
}

void Group::doAction(Action& action) {
    for (const auto& child : children_) {
        if (action.isTerminated()) return;
        if (child) action.traverse(*child);
    }
}

const EnumValues Separator::cachingNames{{"OFF", OFF}, {"ON", ON}, {"AUTO", AUTO}};

void Separator::doAction(Action& action) {
    action.state().push();
    Group::doAction(action);
    action.state().pop();
}

void Switch::doAction(Action& action) {
    const int which = whichChild();
    if (which == SWITCH_ALL || action.traversesAllChildren()) {
        Group::doAction(action);
    } else if (which >= 0 && static_cast<std::size_t>(which) < getNumChildren()) {
        if (Node* child = getChild(static_cast<std::size_t>(which))) action.traverse(*child);
    }
}

} // namespace volsg
