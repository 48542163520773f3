#include <volsg/engines/GlobalField.h>

namespace volsg {

GlobalField::~GlobalField() = default;

Field* GlobalField::makeValueField(const std::string& name) {
    if (value_ || name.empty()) return nullptr;
    valueName_ = name;
    value_ = createFieldOfType(type(), this, valueName_.c_str());
    if (value_) touch();
    return value_.get();
}

std::size_t GlobalField::fieldCount() const {
    return Node::fieldCount() + (value_ ? 1 : 0);
}

Field* GlobalField::fieldAt(std::size_t i) {
    const std::size_t own = Node::fieldCount();
    if (i < own) return Node::fieldAt(i);
    return i == own ? value_.get() : nullptr;
}

void GlobalField::evaluate(const EngineContext& context) {
    if (!value_ || valueName_ != "realTime") return;
    SFTime now(nullptr, "realTime", context.seconds);
    now.setDefault(false);
    assignConverted(*value_, now);
}

} // namespace volsg
