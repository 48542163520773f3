#include <volsg/fields/Fields.h>
#include <volsg/io/UnknownNode.h>

namespace volsg {

UnknownNode::~UnknownNode() = default;

Field* UnknownNode::addField(std::string_view fieldType, std::string_view name) {
    if (findField(name)) return nullptr;
    fieldNames_.emplace_back(name);
    std::unique_ptr<Field> f = createFieldOfType(fieldType, this, fieldNames_.back().c_str());
    if (!f) {
        fieldNames_.pop_back();
        return nullptr;
    }
    fields_.push_back(std::move(f));
    byName_.emplace(fieldNames_.back(), fields_.back().get());
    touch();
    return fields_.back().get();
}

Field* UnknownNode::findField(std::string_view name) const {
    const auto it = byName_.find(name);
    return it == byName_.end() ? nullptr : it->second;
}

Field* UnknownNode::fieldAt(std::size_t i) {
    return i < fields_.size() ? fields_[i].get() : nullptr;
}

} // namespace volsg
