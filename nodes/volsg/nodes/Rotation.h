#pragma once
// Rotation: model = model * R(rotation) (Inventor's SoRotation). The node type is
// volsg::RotationNode because volsg::Rotation is the SFRotation value type; in files it is
// `Rotation`.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class RotationNode : public Inherit<Node, RotationNode> {
public:
    static constexpr const char* typeName = "Rotation";
    static constexpr bool inventorBuiltin() { return true; }
    SFRotation rotation{this, "rotation"};

    void doAction(Action& action) override;

protected:
    ~RotationNode() override = default;
};

} // namespace volsg
