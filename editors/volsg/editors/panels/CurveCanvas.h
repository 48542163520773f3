#pragma once
// The Dear ImGui canvas shared by the transfer-function and plane-opacity panels: draws the
// curves of a CurveEditor (over an optional histogram) and turns mouse input into its edits.
//   points mode: click empty space to add a point (and keep dragging it), drag a point to move
//                it, right-click a point to delete it;
//   freehand:    draw with the left button held; released, the stroke is simplified;
//   line:        press at one end, release at the other.

#include <vector>

#include <imgui.h>

namespace volsg {

class CurveEditor;

struct CurveCanvasState {
    enum Mode { Points, Freehand, Line };
    int mode = Points;
    bool lineActive = false;
    ImVec2 lineStart{0, 0}; ///< curve coordinates
    /// Freehand simplification tolerance, in canvas pixels (converted to curve units).
    float tolerancePixels = 2.0f;
    /// Where the canvas was drawn last (screen pixels), e.g. for scripted input.
    ImVec2 rectMin{0, 0}, rectMax{0, 0};
};

/// Draws the canvas at the cursor, `size` pixels; `colors` per field of the editor; `histogram`
/// bar heights in [0, 1] (may be null). Returns whether anything was edited this frame.
bool drawCurveCanvas(const char* id, CurveEditor& editor, CurveCanvasState& state, ImVec2 size,
                     const std::vector<ImU32>& colors, const std::vector<float>* histogram);

} // namespace volsg
