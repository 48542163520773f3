#include <volsg/editors/panels/PlaneOpacityPanel.h>

#include <algorithm>

#include <volsg/editors/PlaneOpacityEditor.h>

namespace volsg {

bool drawPlaneOpacityPanel(PlaneOpacityEditor& editor, CurveCanvasState& state) {
    if (!editor.volume()) {
        ImGui::TextUnformatted("Select a Volume to edit its plane opacity.");
        return false;
    }
    ImGui::TextUnformatted("extinction x m(t): t = 0 nearest, 1 farthest; m from 0 to 2");
    ImGui::RadioButton("points##po", &state.mode, CurveCanvasState::Points);
    ImGui::SameLine();
    ImGui::RadioButton("freehand##po", &state.mode, CurveCanvasState::Freehand);
    ImGui::SameLine();
    ImGui::RadioButton("line##po", &state.mode, CurveCanvasState::Line);
    const float width = std::max(ImGui::GetContentRegionAvail().x, 120.0f);
    bool edited = drawCurveCanvas("##planeOpacity", editor.curves(), state, ImVec2(width, 100.0f),
                                  {IM_COL32(240, 200, 80, 255)}, nullptr);
    if (ImGui::Button("reset to 1")) {
        editor.reset();
        edited = true;
    }
    return edited;
}

} // namespace volsg
