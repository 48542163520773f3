#include <volsg/editors/panels/TransferFunctionPanel.h>

#include <algorithm>
#include <string>

#include <volsg/editors/TransferFunctionEditor.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/volume/TransferFunction1D.h>

namespace volsg {

namespace {
ImU32 channelColor(int bit) {
    switch (bit) {
    case TransferFunctionEditor::Red:
        return IM_COL32(255, 80, 80, 255);
    case TransferFunctionEditor::Green:
        return IM_COL32(80, 230, 80, 255);
    case TransferFunctionEditor::Blue:
        return IM_COL32(90, 140, 255, 255);
    default:
        return IM_COL32(240, 240, 240, 255);
    }
}

std::string functionLabel(const TransferFunction& tf) {
    return tf.tag() < 0 ? std::string("default (tag -1)") : "tag " + std::to_string(tf.tag());
}
} // namespace

bool drawTransferFunctionPanel(TransferFunctionEditor& editor, TransferFunctionPanelState& state) {
    TransferFunction* selected = editor.selected();
    if (!selected) {
        ImGui::TextUnformatted("No TransferFunction in the scene.");
        return false;
    }
    bool edited = false;
    if (ImGui::BeginCombo("function", functionLabel(*selected).c_str())) {
        for (std::size_t i = 0; i < editor.functions().size(); ++i) {
            const bool isSelected = editor.functions()[i].get() == selected;
            if (ImGui::Selectable(functionLabel(*editor.functions()[i]).c_str(), isSelected))
                editor.select(i);
        }
        ImGui::EndCombo();
    }
    int mask = editor.channels();
    for (int bit : {TransferFunctionEditor::Red, TransferFunctionEditor::Green,
                    TransferFunctionEditor::Blue, TransferFunctionEditor::Alpha}) {
        if (bit != TransferFunctionEditor::Red) ImGui::SameLine();
        bool on = (mask & bit) != 0;
        if (ImGui::Checkbox(TransferFunctionEditor::channelName(bit), &on))
            mask = on ? (mask | bit) : (mask & ~bit);
    }
    if (mask != editor.channels()) editor.setChannels(mask);
    ImGui::RadioButton("points", &state.canvas.mode, CurveCanvasState::Points);
    ImGui::SameLine();
    ImGui::RadioButton("freehand", &state.canvas.mode, CurveCanvasState::Freehand);
    ImGui::SameLine();
    ImGui::RadioButton("line", &state.canvas.mode, CurveCanvasState::Line);
    ImGui::SameLine();
    ImGui::Checkbox("log histogram", &state.logHistogram);

    std::vector<ImU32> colors;
    for (std::size_t i = 0; i < editor.curves().fields().size(); ++i)
        colors.push_back(channelColor(editor.channelOfField(i)));
    const std::vector<float> heights = editor.histogram().heights(state.logHistogram);
    const float width = std::max(ImGui::GetContentRegionAvail().x, 120.0f);
    edited |= drawCurveCanvas("##tf", editor.curves(), state.canvas, ImVec2(width, 150.0f), colors,
                              &heights);

    // The colour bar: the function's RGB over v, alpha as brightness of a checker-free strip.
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 bar = ImGui::GetCursorScreenPos();
    try {
        const TransferFunction1D function = selected->function();
        const int steps = 128;
        for (int i = 0; i < steps; ++i) {
            const glm::dvec4 c = function.evaluate((double(i) + 0.5) / steps);
            const float x0 = bar.x + width * float(i) / steps,
                        x1 = bar.x + width * float(i + 1) / steps;
            draw->AddRectFilled(
                {x0, bar.y}, {x1, bar.y + 10.0f},
                ImGui::GetColorU32(ImVec4(float(c.r), float(c.g), float(c.b), 1.0f)));
            const float a = float(c.a);
            draw->AddRectFilled(
                {x0, bar.y + 10.0f}, {x1, bar.y + 16.0f},
                ImGui::GetColorU32(ImVec4(a * float(c.r), a * float(c.g), a * float(c.b), 1.0f)));
        }
    } catch (const std::exception&) {
        // A function with an empty channel cannot be drawn; the curves above show why.
    }
    ImGui::Dummy(ImVec2(width, 18.0f));

    const char* current =
        TransferFunctionEditor::presetName(TransferFunctionEditor::Preset(state.preset));
    ImGui::SetNextItemWidth(140.0f);
    if (ImGui::BeginCombo("##preset", current)) {
        for (int p = 0; p < TransferFunctionEditor::presetCount; ++p)
            if (ImGui::Selectable(
                    TransferFunctionEditor::presetName(TransferFunctionEditor::Preset(p)),
                    p == state.preset))
                state.preset = p;
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    if (ImGui::Button("apply preset")) {
        editor.applyPreset(TransferFunctionEditor::Preset(state.preset));
        edited = true;
    }
    return edited;
}

} // namespace volsg
