#pragma once
// AppearanceKit: the property parts of a kit, all directly under the kit (no separator), so
// they apply to what follows in the enclosing kit (Inventor's SoAppearanceKit).
#include <volsg/nodes/BaseKit.h>

namespace volsg {

class AppearanceKit : public Inherit<BaseKit, AppearanceKit> {
public:
    static constexpr const char* typeName = "AppearanceKit";
    static constexpr bool inventorBuiltin() { return true; }

    SFNode lightModel{this, "lightModel"};
    SFNode environment{this, "environment"};
    SFNode drawStyle{this, "drawStyle"};
    SFNode material{this, "material"};
    SFNode complexity{this, "complexity"};
    SFNode texture2{this, "texture2"};
    SFNode font{this, "font"};

    void doAction(Action& action) override;

protected:
    ~AppearanceKit() override = default;
};

} // namespace volsg
