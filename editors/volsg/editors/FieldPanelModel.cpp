#include <volsg/editors/FieldPanelModel.h>

#include <cstring>

#include <volsg/core/Error.h>
#include <volsg/editors/EditHistory.h>
#include <volsg/editors/FieldText.h>
#include <volsg/fields/Field.h>

namespace volsg {

FieldPanelModel::Kind FieldPanelModel::kindOf(const Field& field) {
    const std::string t = field.typeName();
    if (t == "SFFloat") return Kind::Float;
    if (t == "SFInt32") return Kind::Int;
    if (t == "SFBool") return Kind::Bool;
    if (t == "SFEnum") return Kind::Enum;
    if (t == "SFColor") return Kind::Color;
    if (t == "SFVec2f") return Kind::Vec2;
    if (t == "SFVec3f") return Kind::Vec3;
    if (t == "SFRotation") return Kind::Rotation;
    if (t == "SFString") return Kind::String;
    if (t == "SFNode" || t == "MFNode") return Kind::Node;
    return Kind::Text;
}

FieldPanelModel::FieldPanelModel(EditHistory& history) : history_(history) {}

void FieldPanelModel::setNode(Node* node) {
    endChange();
    node_ = ref_ptr<Node>(node);
    entries_.clear();
    if (!node) return;
    for (std::size_t i = 0; i < node->fieldCount(); ++i) {
        Field* f = node->fieldAt(i);
        entries_.push_back({f, kindOf(*f)});
    }
}

void FieldPanelModel::change(std::size_t i, const std::function<void()>& set) {
    Field* f = entries_.at(i).field;
    if (changing_) {
        history_.include({f});
        set();
        return;
    }
    history_.begin(std::string("set ") + f->name(), {f});
    set();
    history_.commit();
}

void FieldPanelModel::beginChange(std::size_t i) {
    if (changing_) endChange();
    history_.begin(std::string("change ") + entries_.at(i).field->name(), {entries_[i].field});
    changing_ = true;
}

void FieldPanelModel::endChange() {
    if (!changing_) return;
    changing_ = false;
    history_.commit();
}

std::string FieldPanelModel::text(std::size_t i) const {
    const Field* f = entries_.at(i).field;
    return isTextField(*f) ? fieldValueText(*f) : std::string("(nodes)");
}

bool FieldPanelModel::setText(std::size_t i, const std::string& text, std::string* error) {
    Field* f = entries_.at(i).field;
    const bool own = !changing_;
    if (own)
        history_.begin(std::string("set ") + f->name(), {f});
    else
        history_.include({f});
    try {
        setFieldFromText(*f, text);
    } catch (const Error& e) {
        if (own) history_.cancel();
        if (error) *error = e.what();
        return false;
    }
    if (own) history_.commit();
    return true;
}

} // namespace volsg
