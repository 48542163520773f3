#pragma once
// Selection: a Separator that, in an interactive Inventor viewer, keeps the list of selected
// paths under it by its policy (Inventor's SoSelection). volsg has no event handling: it reads,
// keeps and writes the policy and draws, bounds and picks as a Separator.
#include <volsg/fields/Fields.h>
#include <volsg/nodes/Separator.h>

namespace volsg {

class Selection : public Inherit<Separator, Selection> {
public:
    static constexpr const char* typeName = "Selection";
    static constexpr bool inventorBuiltin() { return true; }
    enum Policy { SINGLE, TOGGLE, SHIFT, DISABLE };
    static const EnumValues policyNames;

    SFEnum policy{this, "policy", policyNames, SHIFT};

protected:
    ~Selection() override = default;
};

} // namespace volsg
