#pragma once
// LightModel: BASE_COLOR draws the shapes after it in scope unlit in their diffuse colour,
// PHONG lights them (Inventor's SoLightModel).
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class LightModel : public Inherit<Node, LightModel> {
public:
    static constexpr const char* typeName = "LightModel";
    static constexpr bool inventorBuiltin() { return true; }
    enum Model { BASE_COLOR, PHONG };
    static const EnumValues modelNames;

    SFEnum model{this, "model", modelNames, PHONG};

    void doAction(Action& action) override;

protected:
    ~LightModel() override = default;
};

} // namespace volsg
