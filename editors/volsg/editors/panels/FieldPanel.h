#pragma once
// The Dear ImGui panel generated from any node's fields (RTVR's automatic control panel): a
// widget per field by its type, and a text box for the rest.

#include <string>
#include <vector>

namespace volsg {

class FieldPanelModel;

struct FieldPanelState {
    std::vector<std::string> texts;  ///< text boxes being edited, per field
    std::vector<std::string> errors; ///< the last parse error, per field
    const void* node = nullptr;      ///< the node the texts belong to
};

/// Draws the panel's contents into the current window; returns whether anything was edited.
bool drawFieldPanel(FieldPanelModel& model, FieldPanelState& state);

} // namespace volsg
