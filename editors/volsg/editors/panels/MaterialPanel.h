#pragma once
// The Dear ImGui panel of the material editor (Material, or a BoxClip's inside and outside).

namespace volsg {

class MaterialEditor;

/// Draws the panel's contents into the current window; returns whether anything was edited.
bool drawMaterialPanel(MaterialEditor& editor);

} // namespace volsg
