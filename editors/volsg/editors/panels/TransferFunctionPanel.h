#pragma once
// The Dear ImGui panel of the transfer-function editor: function (tag) choice, channel
// selection, edit mode, presets, the RGBA curves over the data histogram (log scale option) and
// the resulting colour bar.

#include <volsg/editors/panels/CurveCanvas.h>

namespace volsg {

class TransferFunctionEditor;

struct TransferFunctionPanelState {
    CurveCanvasState canvas;
    bool logHistogram = true;
    int preset = 0;
};

/// Draws the panel's contents into the current window; returns whether anything was edited.
bool drawTransferFunctionPanel(TransferFunctionEditor& editor, TransferFunctionPanelState& state);

} // namespace volsg
