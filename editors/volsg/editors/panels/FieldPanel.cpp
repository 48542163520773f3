#include <volsg/editors/panels/FieldPanel.h>

#include <imgui.h>
#include <imgui_stdlib.h>

#include <volsg/editors/FieldPanelModel.h>
#include <volsg/fields/Fields.h>

namespace volsg {

bool drawFieldPanel(FieldPanelModel& model, FieldPanelState& state) {
    Node* node = model.node();
    if (!node) {
        ImGui::TextUnformatted("Nothing selected: click an object, or a node in the scene tree.");
        return false;
    }
    const auto& entries = model.entries();
    if (state.node != node || state.texts.size() != entries.size()) {
        state.node = node;
        state.texts.assign(entries.size(), std::string());
        state.errors.assign(entries.size(), std::string());
        for (std::size_t i = 0; i < entries.size(); ++i)
            state.texts[i] = model.text(i);
    }
    ImGui::Text("%s %s", node->type().name(), node->getName().c_str());
    bool edited = false;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        Field* f = entries[i].field;
        ImGui::PushID(int(i));
        bool changed = false;
        bool widget = true;
        switch (entries[i].kind) {
        case FieldPanelModel::Kind::Float: {
            auto* sf = static_cast<SFFloat*>(f);
            float v = sf->getValue();
            changed = ImGui::DragFloat(f->name(), &v, 0.01f);
            if (ImGui::IsItemActivated()) model.beginChange(i);
            if (changed) model.change(i, [&] { sf->setValue(v); });
            break;
        }
        case FieldPanelModel::Kind::Int: {
            auto* sf = static_cast<SFInt32*>(f);
            int v = sf->getValue();
            changed = ImGui::DragInt(f->name(), &v, 0.25f);
            if (ImGui::IsItemActivated()) model.beginChange(i);
            if (changed) model.change(i, [&] { sf->setValue(v); });
            break;
        }
        case FieldPanelModel::Kind::Bool: {
            auto* sf = static_cast<SFBool*>(f);
            bool v = sf->getValue();
            changed = ImGui::Checkbox(f->name(), &v);
            if (changed) model.change(i, [&] { sf->setValue(v); });
            break;
        }
        case FieldPanelModel::Kind::Enum: {
            auto* sf = static_cast<SFEnum*>(f);
            const char* current = sf->names().nameOf(sf->getValue());
            if (ImGui::BeginCombo(f->name(), current ? current : "?")) {
                for (const auto& [name, value] : sf->names().entries)
                    if (ImGui::Selectable(name, value == sf->getValue()) &&
                        value != sf->getValue()) {
                        const int chosen = value;
                        model.change(i, [&] { sf->setValue(chosen); });
                        changed = true;
                    }
                ImGui::EndCombo();
            }
            break;
        }
        case FieldPanelModel::Kind::Color: {
            auto* sf = static_cast<SFColor*>(f);
            glm::vec3 v = sf->getValue();
            changed = ImGui::ColorEdit3(f->name(), &v.x);
            if (ImGui::IsItemActivated()) model.beginChange(i);
            if (changed) model.change(i, [&] { sf->setValue(v); });
            break;
        }
        case FieldPanelModel::Kind::Vec2: {
            auto* sf = static_cast<SFVec2f*>(f);
            glm::vec2 v = sf->getValue();
            changed = ImGui::DragFloat2(f->name(), &v.x, 0.01f);
            if (ImGui::IsItemActivated()) model.beginChange(i);
            if (changed) model.change(i, [&] { sf->setValue(v); });
            break;
        }
        case FieldPanelModel::Kind::Vec3: {
            auto* sf = static_cast<SFVec3f*>(f);
            glm::vec3 v = sf->getValue();
            changed = ImGui::DragFloat3(f->name(), &v.x, 0.01f);
            if (ImGui::IsItemActivated()) model.beginChange(i);
            if (changed) model.change(i, [&] { sf->setValue(v); });
            break;
        }
        case FieldPanelModel::Kind::Rotation: {
            auto* sf = static_cast<SFRotation*>(f);
            Rotation r = sf->getValue();
            float v[4] = {r.axis.x, r.axis.y, r.axis.z, r.angle};
            changed = ImGui::DragFloat4(f->name(), v, 0.01f);
            if (ImGui::IsItemActivated()) model.beginChange(i);
            if (changed)
                model.change(i, [&] { sf->setValue(Rotation{glm::vec3(v[0], v[1], v[2]), v[3]}); });
            break;
        }
        case FieldPanelModel::Kind::String: {
            auto* sf = static_cast<SFString*>(f);
            std::string v = sf->getValue();
            if (ImGui::InputText(f->name(), &v, ImGuiInputTextFlags_EnterReturnsTrue)) {
                model.change(i, [&] { sf->setValue(v); });
                changed = true;
            }
            break;
        }
        case FieldPanelModel::Kind::Text: {
            if (ImGui::InputText(f->name(), &state.texts[i],
                                 ImGuiInputTextFlags_EnterReturnsTrue)) {
                changed = model.setText(i, state.texts[i], &state.errors[i]);
                if (changed) state.errors[i].clear();
            }
            if (!ImGui::IsItemActive()) state.texts[i] = model.text(i);
            break;
        }
        case FieldPanelModel::Kind::Node:
            widget = false;
            ImGui::Text("%s: (nodes)", f->name());
            break;
        }
        if (widget && ImGui::IsItemDeactivated()) model.endChange();
        if (!state.errors[i].empty())
            ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", state.errors[i].c_str());
        edited |= changed;
        ImGui::PopID();
    }
    return edited;
}

} // namespace volsg
