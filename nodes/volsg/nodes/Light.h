#pragma once
// Base of lights: they light the shapes after them in scope.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class Light : public Inherit<Node, Light> {
public:
    static constexpr const char* typeName = "Light";
    SFBool on{this, "on", true};
    SFFloat intensity{this, "intensity", 1.0f};
    SFColor color{this, "color", glm::vec3(1.0f)};

    void doAction(Action& action) override;

protected:
    ~Light() override = default;
};

/// Light from one direction (towards -Z by default), in the node's coordinates.
class DirectionalLight : public Inherit<Light, DirectionalLight> {
public:
    static constexpr const char* typeName = "DirectionalLight";
    static constexpr bool inventorBuiltin() { return true; }
    SFVec3f direction{this, "direction", glm::vec3(0.0f, 0.0f, -1.0f)};

protected:
    ~DirectionalLight() override = default;
};

/// Light from a point, without attenuation (Inventor's default).
class PointLight : public Inherit<Light, PointLight> {
public:
    static constexpr const char* typeName = "PointLight";
    static constexpr bool inventorBuiltin() { return true; }
    SFVec3f location{this, "location", glm::vec3(0.0f, 0.0f, 1.0f)};

protected:
    ~PointLight() override = default;
};

/// Light from a point into a cone (Inventor's SoSpotLight): full inside cutOffAngle of the
/// direction, none outside; within the cone, intensity times cos(angle)^(dropOffRate * 128).
class SpotLight : public Inherit<Light, SpotLight> {
public:
    static constexpr const char* typeName = "SpotLight";
    static constexpr bool inventorBuiltin() { return true; }
    SFVec3f location{this, "location", glm::vec3(0.0f, 0.0f, 1.0f)};
    SFVec3f direction{this, "direction", glm::vec3(0.0f, 0.0f, -1.0f)};
    SFFloat dropOffRate{this, "dropOffRate", 0.0f};
    SFFloat cutOffAngle{this, "cutOffAngle", 0.785398163f}; ///< radians

protected:
    ~SpotLight() override = default;
};

} // namespace volsg
