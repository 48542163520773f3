#pragma once
// PickStyle: how the shapes after it in scope are picked (Inventor's SoPickStyle): SHAPE
// exactly, BOUNDING_BOX by their local bounding box, UNPICKABLE not at all. PickAction reads
// the nearest one from the state (nodes/volsg/actions/PickAction.cpp); no other action uses it.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class State;

class PickStyle : public Inherit<Node, PickStyle> {
public:
    static constexpr const char* typeName = "PickStyle";
    static constexpr bool inventorBuiltin() { return true; }
    /// Inventor 2.1's three styles, then Coin's three additions (read and written; picked as
    /// SHAPE, BOUNDING_BOX and SHAPE: docs/SCENE-FORMAT.md section 2.5).
    enum Style {
        SHAPE,
        BOUNDING_BOX,
        UNPICKABLE,
        SHAPE_ON_TOP,
        BOUNDING_BOX_ON_TOP,
        SHAPE_FRONTFACES
    };
    static const EnumValues styleNames;

    SFEnum style{this, "style", styleNames, SHAPE};

    /// SHAPE, BOUNDING_BOX or UNPICKABLE: how shapes at the current node are picked (Coin's
    /// additions folded into the first two).
    static Style inScope(const State& state);
    void doAction(Action& action) override;

protected:
    ~PickStyle() override = default;
};

} // namespace volsg
