#include <volsg/editors/panels/MaterialPanel.h>

#include <imgui.h>

#include <volsg/editors/MaterialEditor.h>

namespace volsg {

bool drawMaterialPanel(MaterialEditor& editor) {
    if (!editor.node()) {
        ImGui::TextUnformatted("Select a Material or a BoxClip.");
        return false;
    }
    bool edited = false;
    for (std::size_t i = 0; i < editor.properties().size(); ++i) {
        const MaterialEditor::Property& p = editor.properties()[i];
        ImGui::PushID(int(i));
        bool changed;
        if (p.isColor) {
            glm::vec3 c = editor.color(i);
            changed = ImGui::ColorEdit3(p.label.c_str(), &c.x);
            if (ImGui::IsItemActivated()) editor.beginChange(i);
            if (changed) editor.setColor(i, c);
        } else {
            float v = editor.scalar(i);
            changed = ImGui::SliderFloat(p.label.c_str(), &v, p.minimum, p.maximum);
            if (ImGui::IsItemActivated()) editor.beginChange(i);
            if (changed) editor.setScalar(i, v);
        }
        if (ImGui::IsItemDeactivated()) editor.endChange();
        edited |= changed;
        ImGui::PopID();
    }
    return edited;
}

} // namespace volsg
