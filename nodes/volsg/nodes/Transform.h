#pragma once
// Transform: model = model * T * C * R * SR * S * SR^-1 * C^-1 (Inventor SoTransform).
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class Transform : public Inherit<Node, Transform> {
public:
    static constexpr const char* typeName = "Transform";
    static constexpr bool inventorBuiltin() { return true; }
    SFVec3f translation{this, "translation", glm::vec3(0.0f)};
    SFRotation rotation{this, "rotation"};
    SFVec3f scaleFactor{this, "scaleFactor", glm::vec3(1.0f)};
    SFRotation scaleOrientation{this, "scaleOrientation"};
    SFVec3f center{this, "center", glm::vec3(0.0f)};

    glm::dmat4 matrix() const;
    void doAction(Action& action) override;

protected:
    ~Transform() override = default;
};

} // namespace volsg
