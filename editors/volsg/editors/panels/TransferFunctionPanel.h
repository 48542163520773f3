#pragma once
// The Dear ImGui panel of the transfer-function editor: function (tag) choice, channel
// selection, edit mode, the RGBA curves over the data histogram (log scale option), the data
// value axis and the hover readout, the resulting colour bar, presets (colour, opacity or both)
// and window/level.

#include <volsg/editors/panels/CurveCanvas.h>

namespace volsg {

class TransferFunctionEditor;

struct TransferFunctionPanelState {
    CurveCanvasState canvas;
    bool logHistogram = true;
    int preset = 0;
    int presetApply = 1; ///< PresetApply: opacity alone unless the user asks for more
    /// Draw without the histogram this frame (it needs a pass over the data): the viewer's
    /// first image comes first.
    bool deferHistogram = false;
};

/// Draws the panel's contents into the current window; returns whether anything was edited.
bool drawTransferFunctionPanel(TransferFunctionEditor& editor, TransferFunctionPanelState& state);

} // namespace volsg
