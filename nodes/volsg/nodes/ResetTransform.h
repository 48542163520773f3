#pragma once
// ResetTransform: TRANSFORM sets the current model matrix back to identity (render, pick and
// bounding-box actions); BBOX empties the bounding box accumulated so far in its Separator
// scope (bounding-box action only). Inventor's SoResetTransform.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class ResetTransform : public Inherit<Node, ResetTransform> {
public:
    static constexpr const char* typeName = "ResetTransform";
    static constexpr bool inventorBuiltin() { return true; }
    enum Reset { TRANSFORM = 1, BBOX = 2 };
    static const EnumValues whatToResetNames;

    SFBitMask whatToReset{this, "whatToReset", whatToResetNames, TRANSFORM};

    void doAction(Action& action) override;

protected:
    ~ResetTransform() override = default;
};

} // namespace volsg
