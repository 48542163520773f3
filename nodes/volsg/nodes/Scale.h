#pragma once
// Scale: model = model * S(scaleFactor) (Inventor's SoScale).
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class Scale : public Inherit<Node, Scale> {
public:
    static constexpr const char* typeName = "Scale";
    static constexpr bool inventorBuiltin() { return true; }
    SFVec3f scaleFactor{this, "scaleFactor", glm::vec3(1.0f)};

    void doAction(Action& action) override;

protected:
    ~Scale() override = default;
};

} // namespace volsg
