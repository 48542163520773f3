#pragma once
// A field's value as the scene file writes it, and setting a field from such text: the one
// representation that the undo history and the generic field panel share for every type.

#include <string>
#include <string_view>

namespace volsg {

class Field;

/// The value as written after the field name in a scene file (`0.5`, `[ 0 0, 1 1 ]`, `DVR`).
/// Throws Error for node-valued fields (SFNode, MFNode), whose value is a graph, not text.
std::string fieldValueText(const Field& field);

/// Reads `text` as the field's value (the scene reader's syntax) and sets it. The whole text
/// must be one value; an Error names the field and what was wrong, and leaves it unchanged.
void setFieldFromText(Field& field, std::string_view text);

/// Whether a field's value can be shown and edited as text (not SFNode or MFNode).
bool isTextField(const Field& field);

} // namespace volsg
