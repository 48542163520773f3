#include <volsg/editors/panels/CurveCanvas.h>

#include <algorithm>
#include <cmath>

#include <volsg/editors/CurveEditor.h>

namespace volsg {

namespace {
constexpr float kPointRadius = 4.0f, kHitRadius = 7.0f, kMargin = 6.0f;

struct Mapping {
    ImVec2 min, max;
    float yMin, yMax;
    ImVec2 toScreen(glm::vec2 p) const {
        return {min.x + p.x * (max.x - min.x),
                max.y - (p.y - yMin) / (yMax - yMin) * (max.y - min.y)};
    }
    glm::vec2 toCurve(ImVec2 s) const {
        return {(s.x - min.x) / (max.x - min.x),
                yMin + (max.y - s.y) / (max.y - min.y) * (yMax - yMin)};
    }
    glm::vec2 pixelScale() const { return {max.x - min.x, (max.y - min.y) / (yMax - yMin)}; }
};
} // namespace

bool drawCurveCanvas(const char* id, CurveEditor& editor, CurveCanvasState& state, ImVec2 size,
                     const std::vector<ImU32>& colors, const std::vector<float>* histogram) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    // The button reaches kMargin beyond the drawn area, so points on its border can be grabbed.
    const ImVec2 corner = ImGui::GetCursorScreenPos();
    const ImVec2 min(corner.x + kMargin, corner.y + kMargin);
    const ImVec2 max(corner.x + size.x - kMargin, corner.y + size.y - kMargin);
    size = ImVec2(max.x - min.x, max.y - min.y);
    state.rectMin = min;
    state.rectMax = max;
    ImGui::InvisibleButton(id, ImVec2(size.x + 2 * kMargin, size.y + 2 * kMargin),
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    const Mapping map{min, max, editor.yMin(), editor.yMax()};
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const glm::vec2 at = map.toCurve(mouse);
    bool edited = false;

    // Background, grid and histogram.
    draw->AddRectFilled(min, max, IM_COL32(30, 30, 34, 255));
    if (histogram && !histogram->empty()) {
        const float barWidth = size.x / float(histogram->size());
        for (std::size_t i = 0; i < histogram->size(); ++i) {
            const float h = (*histogram)[i] * size.y;
            if (h <= 0.0f) continue;
            const float x0 = min.x + float(i) * barWidth;
            draw->AddRectFilled({x0, max.y - h}, {x0 + std::max(barWidth, 1.0f), max.y},
                                IM_COL32(90, 90, 100, 255));
        }
    }
    for (int i = 1; i < 4; ++i) {
        const float x = min.x + size.x * float(i) / 4.0f, y = min.y + size.y * float(i) / 4.0f;
        draw->AddLine({x, min.y}, {x, max.y}, IM_COL32(60, 60, 66, 255));
        draw->AddLine({min.x, y}, {max.x, y}, IM_COL32(60, 60, 66, 255));
    }

    // Input.
    const bool hovered = ImGui::IsItemHovered();
    if (state.mode == CurveCanvasState::Points) {
        if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
            int field = -1, point = -1;
            for (std::size_t f = 0; f < editor.fields().size() && point < 0; ++f) {
                point = editor.curve(f).nearest(at, kHitRadius, map.pixelScale());
                if (point >= 0) field = int(f);
            }
            if (point < 0) { // a new point, held for dragging
                point = editor.addPoint(at);
                field = 0;
                edited = true;
            }
            editor.beginDrag(std::size_t(field), point);
        }
        if (editor.isDragging()) {
            if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
                editor.dragTo(at);
                edited = true;
            } else {
                editor.endDrag();
            }
        }
        if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
            for (std::size_t f = 0; f < editor.fields().size(); ++f) {
                const int point = editor.curve(f).nearest(at, kHitRadius, map.pixelScale());
                if (point >= 0) {
                    edited = editor.deletePoint(f, point);
                    break;
                }
            }
        }
    } else if (state.mode == CurveCanvasState::Freehand) {
        if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) editor.beginStroke();
        if (editor.isStroking()) {
            if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
                editor.addStrokePoint(at);
            } else {
                const float tolerance =
                    state.tolerancePixels / size.y * (editor.yMax() - editor.yMin());
                editor.endStroke(tolerance);
                edited = true;
            }
        }
    } else {
        if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
            state.lineActive = true;
            state.lineStart = {at.x, at.y};
        }
        if (state.lineActive && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
            state.lineActive = false;
            editor.drawLine({state.lineStart.x, state.lineStart.y}, at);
            edited = true;
        }
    }

    // Curves and their points, clipped to the canvas.
    draw->PushClipRect(min, max, true);
    for (std::size_t f = 0; f < editor.fields().size(); ++f) {
        const ImU32 color = f < colors.size() ? colors[f] : IM_COL32(255, 255, 255, 255);
        const auto& points = editor.fields()[f]->getValues();
        if (points.empty()) continue;
        std::vector<ImVec2> line;
        line.push_back(map.toScreen({0.0f, points.front().y}));
        for (const glm::vec2& p : points)
            line.push_back(map.toScreen(p));
        line.push_back(map.toScreen({1.0f, points.back().y}));
        draw->AddPolyline(line.data(), int(line.size()), color, 0, 2.0f);
        for (const glm::vec2& p : points)
            draw->AddCircleFilled(map.toScreen(p), kPointRadius, color);
    }
    if (editor.isStroking() && editor.stroke().size() > 1) {
        std::vector<ImVec2> line;
        for (const glm::vec2& p : editor.stroke())
            line.push_back(map.toScreen(p));
        draw->AddPolyline(line.data(), int(line.size()), IM_COL32(255, 255, 0, 255), 0, 1.0f);
    }
    if (state.lineActive)
        draw->AddLine(map.toScreen({state.lineStart.x, state.lineStart.y}), mouse,
                      IM_COL32(255, 255, 0, 255), 1.5f);
    draw->PopClipRect();
    draw->AddRect(min, max, IM_COL32(120, 120, 130, 255));
    return edited;
}

} // namespace volsg
