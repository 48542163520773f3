#include <volsg/actions/Action.h>
#include <volsg/actions/ActionMethods.h>

namespace volsg {

void ActionMethods::addErased(const NodeType& type, ErasedFunction function, Trampoline call) {
    std::lock_guard lock(mutex_);
    added_[&type] = Method{function, call};
    resolved_.clear(); // a new method may be the nearest one for derived types
}

ActionMethods::Method ActionMethods::find(const NodeType& type) const {
    std::lock_guard lock(mutex_);
    if (auto it = resolved_.find(&type); it != resolved_.end()) return it->second;
    Method method;
    for (const NodeType* t = &type; t; t = t->parent())
        if (auto it = added_.find(t); it != added_.end()) {
            method = it->second;
            break;
        }
    resolved_.emplace(&type, method);
    return method;
}

void ActionMethods::apply(Action& action, Node& node) const {
    const Method method = find(node.type());
    if (method.call)
        method.call(method.function, action, node);
    else
        node.doAction(action);
}

} // namespace volsg
