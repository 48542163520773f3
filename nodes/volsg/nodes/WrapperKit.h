#pragma once
// WrapperKit: a SeparatorKit with a localTransform and a contents part (a Separator holding
// any graph) after its childList (Inventor's SoWrapperKit).
#include <volsg/nodes/SeparatorKit.h>

namespace volsg {

class WrapperKit : public Inherit<SeparatorKit, WrapperKit> {
public:
    static constexpr const char* typeName = "WrapperKit";
    static constexpr bool inventorBuiltin() { return true; }

    SFNode localTransform{this, "localTransform"};
    SFNode contents{this, "contents"};

    void doAction(Action& action) override;

protected:
    ~WrapperKit() override = default;
};

} // namespace volsg
