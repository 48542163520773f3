#pragma once
// Coordinate3: the points that indexed shapes after it refer to.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class Coordinate3 : public Inherit<Node, Coordinate3> {
public:
    static constexpr const char* typeName = "Coordinate3";
    static constexpr bool inventorBuiltin() { return true; }
    MFVec3f point{this, "point", {glm::vec3(0.0f)}};

    void doAction(Action& action) override;

protected:
    ~Coordinate3() override = default;
};

} // namespace volsg
