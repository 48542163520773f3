#include <volsg/actions/Action.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/UnknownNode.h>
#include <volsg/state/State.h>

namespace volsg {

UnknownNode::~UnknownNode() = default;

Field* UnknownNode::adopt(std::unique_ptr<Field> f) {
    fields_.push_back(std::move(f));
    byName_.emplace(fieldNames_.back(), fields_.back().get());
    touch();
    return fields_.back().get();
}

Field* UnknownNode::addField(std::string_view fieldType, std::string_view name) {
    if (findField(name)) return nullptr;
    fieldNames_.emplace_back(name);
    std::unique_ptr<Field> f = createFieldOfType(fieldType, this, fieldNames_.back().c_str());
    if (!f) {
        fieldNames_.pop_back();
        return nullptr;
    }
    return adopt(std::move(f));
}

RawValueField* UnknownNode::addRawField(std::string_view name) {
    if (findField(name)) return nullptr;
    fieldNames_.emplace_back(name);
    return static_cast<RawValueField*>(
        adopt(std::make_unique<RawValueField>(this, fieldNames_.back().c_str())));
}

Field* UnknownNode::findField(std::string_view name) const {
    const auto it = byName_.find(name);
    return it == byName_.end() ? nullptr : it->second;
}

Field* UnknownNode::fieldAt(std::size_t i) {
    return i < fields_.size() ? fields_[i].get() : nullptr;
}

void UnknownNode::doAction(Action& action) {
    if (const auto* alternate = dynamic_cast<const SFNode*>(findField("alternateRep"))) {
        if (Node* node = alternate->getValue()) action.traverse(*node);
        return;
    }
    const Field* isA = findField("isA");
    std::string base;
    if (const auto* mf = dynamic_cast<const MFString*>(isA); mf && !mf->empty())
        base = (*mf)[0];
    else if (const auto* sf = dynamic_cast<const SFString*>(isA))
        base = sf->getValue();
    if (base != "Group" && base != "Separator") return;
    if (base == "Separator") action.state().push();
    for (const auto& child : children_) {
        if (action.isTerminated()) break;
        if (child) action.traverse(*child);
    }
    if (base == "Separator") action.state().pop();
}

} // namespace volsg
