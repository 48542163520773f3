#pragma once
// TransformSeparator: a Group that restores only the model matrix after its children; every
// other change they make (materials, lights, units, ...) stays in scope after it (Inventor's
// SoTransformSeparator).
#include <volsg/nodes/Group.h>

namespace volsg {

class TransformSeparator : public Inherit<Group, TransformSeparator> {
public:
    static constexpr const char* typeName = "TransformSeparator";
    static constexpr bool inventorBuiltin() { return true; }

    void doAction(Action& action) override;

protected:
    ~TransformSeparator() override = default;
};

} // namespace volsg
