#pragma once
// The font the text nodes read from the state: the nearest Font in scope (Inventor's font
// name and size elements), opened through lib/volsg/text.
#include <cstdint>
#include <memory>
#include <string>

#include <volsg/nodes/NodeNames.h>
#include <volsg/text/TextLayout.h>

namespace volsg {

class FontFace;
class Font;
class Node;
class State;
class Text2;

struct FontInScope {
    const Font* node = nullptr; ///< null: Inventor's defaults
    std::string name = "defaultFont";
    float size = 10.0f;
    std::uint64_t key() const; ///< changes with the node and its fields
};
FontInScope fontInScope(const State& state);

/// The face for the font's name. Throws Error naming `textNode` (its type, and its name if it
/// has one) when no font file is found.
std::shared_ptr<FontFace> openFontFor(const Node& textNode, const FontInScope& font);

/// Largest Font size Text2 draws, in pixels.
inline constexpr int kMaxScreenTextPixels = 1024;

/// Text2's glyphs at the Font in scope, in pixels; `face` is set to the font they come from.
/// Empty for a size below half a pixel. Throws Error naming the node for a size that is not
/// finite or beyond kMaxScreenTextPixels, a missing font, or too many characters.
ScreenText screenTextInScope(const Text2& text, const State& state,
                             std::shared_ptr<FontFace>& face);

} // namespace volsg
