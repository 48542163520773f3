#pragma once
// RotationXYZ: model = model * R(axis, angle) about the X, Y or Z axis (Inventor's
// SoRotationXYZ; fields in Coin's order, angle first).
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class RotationXYZ : public Inherit<Node, RotationXYZ> {
public:
    static constexpr const char* typeName = "RotationXYZ";
    static constexpr bool inventorBuiltin() { return true; }
    enum Axis { X, Y, Z };
    static const EnumValues axisNames;

    SFFloat angle{this, "angle", 0.0f}; ///< radians
    SFEnum axis{this, "axis", axisNames, X};

    glm::dmat4 matrix() const;
    void doAction(Action& action) override;

protected:
    ~RotationXYZ() override = default;
};

} // namespace volsg
