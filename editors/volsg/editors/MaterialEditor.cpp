#include <volsg/editors/MaterialEditor.h>

#include <algorithm>

#include <volsg/editors/EditHistory.h>
#include <volsg/nodes/BoxClip.h>
#include <volsg/nodes/Material.h>

namespace volsg {

MaterialEditor::MaterialEditor(EditHistory& history) : history_(history) {}

bool MaterialEditor::setNode(Node* node) {
    endChange();
    properties_.clear();
    node_ = ref_ptr<Node>(node);
    if (auto* m = dynamic_cast<Material*>(node)) {
        properties_ = {{"ambient", true, 0, 1, &m->ambientColor},
                       {"diffuse", true, 0, 1, &m->diffuseColor},
                       {"specular", true, 0, 1, &m->specularColor},
                       {"emissive", true, 0, 1, &m->emissiveColor},
                       {"shininess", false, 0, 1, &m->shininess},
                       {"transparency", false, 0, 1, &m->transparency}};
    } else if (auto* b = dynamic_cast<BoxClip*>(node)) {
        properties_ = {{"inside colour", true, 0, 1, &b->insideColor},
                       {"inside colour weight", false, 0, 1, &b->insideColorWeight},
                       {"inside opacity", false, 0, 4, &b->insideOpacity},
                       {"outside colour", true, 0, 1, &b->outsideColor},
                       {"outside colour weight", false, 0, 1, &b->outsideColorWeight},
                       {"outside opacity", false, 0, 4, &b->outsideOpacity}};
    } else {
        node_ = nullptr;
    }
    return node_ != nullptr;
}

glm::vec3 MaterialEditor::color(std::size_t i) const {
    const Field* f = properties_.at(i).field;
    if (const auto* mf = dynamic_cast<const MFColor*>(f))
        return mf->empty() ? glm::vec3(0) : (*mf)[0];
    if (const auto* sf = dynamic_cast<const SFColor*>(f)) return sf->getValue();
    return glm::vec3(0.0f);
}

float MaterialEditor::scalar(std::size_t i) const {
    const Field* f = properties_.at(i).field;
    if (const auto* mf = dynamic_cast<const MFFloat*>(f)) return mf->empty() ? 0.0f : (*mf)[0];
    if (const auto* sf = dynamic_cast<const SFFloat*>(f)) return sf->getValue();
    return 0.0f;
}

void MaterialEditor::edit(std::size_t i, const char* label) {
    if (changing_)
        history_.include({properties_[i].field});
    else
        history_.begin(std::string(label) + " " + properties_[i].label, {properties_[i].field});
}

void MaterialEditor::setColor(std::size_t i, const glm::vec3& value) {
    const Property& p = properties_.at(i);
    const glm::vec3 v = glm::clamp(value, glm::vec3(p.minimum), glm::vec3(p.maximum));
    if (v == color(i)) return;
    edit(i, "set");
    if (auto* mf = dynamic_cast<MFColor*>(p.field)) mf->set1Value(0, v);
    if (auto* sf = dynamic_cast<SFColor*>(p.field)) sf->setValue(v);
    if (!changing_) history_.commit();
}

void MaterialEditor::setScalar(std::size_t i, float value) {
    const Property& p = properties_.at(i);
    const float v = std::clamp(value, p.minimum, p.maximum);
    if (v == scalar(i)) return;
    edit(i, "set");
    if (auto* mf = dynamic_cast<MFFloat*>(p.field)) mf->set1Value(0, v);
    if (auto* sf = dynamic_cast<SFFloat*>(p.field)) sf->setValue(v);
    if (!changing_) history_.commit();
}

void MaterialEditor::beginChange(std::size_t i) {
    if (changing_) endChange();
    history_.begin("change " + properties_.at(i).label, {properties_[i].field});
    changing_ = true;
}

void MaterialEditor::endChange() {
    if (!changing_) return;
    changing_ = false;
    history_.commit();
}

} // namespace volsg
