#pragma once
// Font: the face and size of the text nodes after it (Inventor's SoFont). The name maps to a
// DejaVu face (lib/volsg/text/Font.h: Times to Serif, Courier to Sans Mono, anything else to
// Sans, with Bold and Italic); the size is the em square in object units for Text3 and
// AsciiText, in pixels for Text2.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class Font : public Inherit<Node, Font> {
public:
    static constexpr const char* typeName = "Font";
    static constexpr bool inventorBuiltin() { return true; }
    SFString name{this, "name", "defaultFont"};
    SFFloat size{this, "size", 10.0f};
    void doAction(Action& action) override;

protected:
    ~Font() override = default;
};

} // namespace volsg
