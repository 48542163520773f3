#include <volsg/editors/panels/TransferFunctionPanel.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <volsg/editors/TransferFunctionEditor.h>
#include <volsg/editors/ValueAxis.h>
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

/// Under the canvas: ticks at round data values of the function's range, and the readout of
/// the value under the mouse (a line marks it on the canvas).
void drawValueAxis(TransferFunctionEditor& editor, const TransferFunctionPanelState& state) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 min = state.canvas.rectMin, max = state.canvas.rectMax;
    const glm::dvec2 range = editor.effectiveDataRange();
    const ImVec2 top = ImGui::GetCursorScreenPos();
    const float width = max.x - min.x;
    const ImU32 tickColour = IM_COL32(170, 170, 180, 255);
    const int maxTicks = std::max(2, int(width / 70.0f));
    for (const double t : niceTicks(range.x, range.y, maxTicks)) {
        const float x = min.x + float((t - range.x) / (range.y - range.x)) * width;
        draw->AddLine({x, top.y}, {x, top.y + 4.0f}, tickColour);
        char label[32];
        std::snprintf(label, sizeof label, "%g", t);
        const float textWidth = ImGui::CalcTextSize(label).x;
        const float left = std::clamp(x - 0.5f * textWidth, min.x - 6.0f, max.x + 6.0f - textWidth);
        draw->AddText({left, top.y + 4.0f}, tickColour, label);
    }
    ImGui::Dummy(ImVec2(width, 4.0f + ImGui::GetTextLineHeight()));

    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const bool inside =
        mouse.x >= min.x && mouse.x <= max.x && mouse.y >= min.y && mouse.y <= max.y;
    if (!inside) {
        ImGui::TextDisabled("data range %g to %g (hover the curves for a readout)", range.x,
                            range.y);
        return;
    }
    const double v = std::clamp(double((mouse.x - min.x) / width), 0.0, 1.0);
    draw->AddLine({mouse.x, min.y}, {mouse.x, max.y}, IM_COL32(255, 255, 255, 90));
    try {
        const TransferFunctionEditor::Readout r = editor.readout(v);
        ImGui::Text("value %.4g  opacity %.3f  colour %.2f %.2f %.2f", r.value, r.rgba.a, r.rgba.r,
                    r.rgba.g, r.rgba.b);
    } catch (const std::exception& e) {
        ImGui::TextWrapped("%s", e.what());
    }
}

/// The preset choice, what it replaces (colour, opacity or both) and the button; window/level.
void drawPresetControls(TransferFunctionEditor& editor, TransferFunctionPanelState& state,
                        bool& edited) {
    const auto& presets = transferFunctionPresets();
    state.preset = std::clamp(state.preset, 0, int(presets.size()) - 1);
    auto label = [](const TransferFunctionPreset& p) { return p.name; };
    ImGui::SetNextItemWidth(std::min(200.0f, ImGui::GetContentRegionAvail().x * 0.55f));
    if (ImGui::BeginCombo("##preset", label(presets[std::size_t(state.preset)]).c_str())) {
        for (int p = 0; p < int(presets.size()); ++p)
            if (ImGui::Selectable(label(presets[std::size_t(p)]).c_str(), p == state.preset))
                state.preset = p;
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    if (ImGui::Button("apply preset")) {
        editor.applyPreset(presets[std::size_t(state.preset)], PresetApply(state.presetApply));
        edited = true;
    }
    if (presets[std::size_t(state.preset)].units == TransferFunctionPreset::Units::Hounsfield) {
        double zero = editor.hounsfieldZero();
        ImGui::SetNextItemWidth(90.0f);
        if (ImGui::InputDouble("data value of 0 HU", &zero, 0.0, 0.0, "%g") && std::isfinite(zero))
            editor.setHounsfieldZero(zero);
    }
    ImGui::TextUnformatted("preset sets");
    for (int a = 0; a < 3; ++a) {
        ImGui::SameLine();
        ImGui::RadioButton(presetApplyName(PresetApply(a)), &state.presetApply, a);
    }
    const WindowLevel wl = editor.windowLevel();
    ImGui::Text("window %.4g  level %.4g", wl.width, wl.level);
    ImGui::SameLine();
    if (ImGui::SmallButton("data range")) {
        editor.beginWindowLevel(); // one undo step, as a drag
        if (TransferFunction* tf = editor.selected())
            tf->dataRange = glm::vec2(editor.dataMinMax());
        editor.endWindowLevel();
        edited = true;
    }
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
    const std::vector<float> heights = state.deferHistogram
                                           ? std::vector<float>{}
                                           : editor.histogram().heights(state.logHistogram);
    const float width = std::max(ImGui::GetContentRegionAvail().x, 120.0f);
    edited |= drawCurveCanvas("##tf", editor.curves(), state.canvas, ImVec2(width, 150.0f), colors,
                              &heights);
    drawValueAxis(editor, state);

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

    drawPresetControls(editor, state, edited);
    return edited;
}

} // namespace volsg
