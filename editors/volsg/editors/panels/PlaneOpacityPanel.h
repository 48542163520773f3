#pragma once
// The Dear ImGui panel of the plane-opacity editor (Volume.planeOpacity over view depth).

#include <volsg/editors/panels/CurveCanvas.h>

namespace volsg {

class PlaneOpacityEditor;

/// Draws the panel's contents into the current window; returns whether anything was edited.
bool drawPlaneOpacityPanel(PlaneOpacityEditor& editor, CurveCanvasState& state);

} // namespace volsg
