#pragma once
// DrawStyle: how the shapes after it are drawn (Inventor's SoDrawStyle): filled, as lines
// (polygon outlines), as points (their vertices) or not at all; line width and point size in
// pixels (0: 1 pixel) and a 16-bit line stipple pattern.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class DrawStyle : public Inherit<Node, DrawStyle> {
public:
    static constexpr const char* typeName = "DrawStyle";
    static constexpr bool inventorBuiltin() { return true; }
    enum Style { FILLED, LINES, POINTS, INVISIBLE };
    static const EnumValues styleNames;

    SFEnum style{this, "style", styleNames, FILLED};
    SFFloat pointSize{this, "pointSize", 0.0f};
    SFFloat lineWidth{this, "lineWidth", 0.0f};
    SFUInt32 linePattern{this, "linePattern", 0xFFFFu}; ///< the low 16 bits, bit 0 first

    void doAction(Action& action) override;

protected:
    ~DrawStyle() override = default;
};

} // namespace volsg
