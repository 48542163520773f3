#pragma once
// BaseColor: the diffuse colours of the shapes after it, leaving the other Material values
// (Inventor's SoBaseColor).
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class BaseColor : public Inherit<Node, BaseColor> {
public:
    static constexpr const char* typeName = "BaseColor";
    static constexpr bool inventorBuiltin() { return true; }
    MFColor rgb{this, "rgb", {glm::vec3(0.8f)}};
    void doAction(Action& action) override;

protected:
    ~BaseColor() override = default;
};

} // namespace volsg
