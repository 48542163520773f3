#pragma once
// Normal: the normals that indexed shapes after it refer to.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class Normal : public Inherit<Node, Normal> {
public:
    static constexpr const char* typeName = "Normal";
    static constexpr bool inventorBuiltin() { return true; }
    MFVec3f vector{this, "vector", {}};

    void doAction(Action& action) override;

protected:
    ~Normal() override = default;
};

} // namespace volsg
