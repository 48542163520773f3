#pragma once
// Switch: traverses one child (whichChild), none (-1) or all (-3).

#include <volsg/fields/Fields.h>
#include <volsg/nodes/Group.h>

namespace volsg {

class Switch : public Inherit<Group, Switch> {
public:
    static constexpr const char* typeName = "Switch";
    static constexpr bool inventorBuiltin() { return true; }
    static constexpr int SWITCH_NONE = -1;
    static constexpr int SWITCH_INHERIT = -2; ///< treated as none: no enclosing switch value
    static constexpr int SWITCH_ALL = -3;

    SFInt32 whichChild{this, "whichChild", SWITCH_NONE};

    void doAction(Action& action) override;

protected:
    ~Switch() override = default;
};

} // namespace volsg
