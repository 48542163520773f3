#pragma once
// Environment: the ambient light and fog of the shapes after it (Inventor's SoEnvironment).
// Fog mixes a fragment's colour with fogColor by its eye distance d: HAZE linearly to
// fogVisibility, FOG e^(-4 d / v), SMOKE e^(-(2 d / v)^2) (v = fogVisibility; 0: the far plane).
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class Environment : public Inherit<Node, Environment> {
public:
    static constexpr const char* typeName = "Environment";
    static constexpr bool inventorBuiltin() { return true; }
    enum FogType { NONE, HAZE, FOG, SMOKE };
    static const EnumValues fogTypeNames;

    SFFloat ambientIntensity{this, "ambientIntensity", 0.2f};
    SFColor ambientColor{this, "ambientColor", glm::vec3(1.0f)};
    SFVec3f attenuation{this, "attenuation", glm::vec3(0.0f, 0.0f, 1.0f)};
    SFEnum fogType{this, "fogType", fogTypeNames, NONE};
    SFColor fogColor{this, "fogColor", glm::vec3(1.0f)};
    SFFloat fogVisibility{this, "fogVisibility", 0.0f};

    void doAction(Action& action) override;

protected:
    ~Environment() override = default;
};

} // namespace volsg
