#pragma once
// Coordinate4: homogeneous points (x, y, z, w) for the shapes after it; a vertex shape uses
// (x, y, z) / w.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class Coordinate4 : public Inherit<Node, Coordinate4> {
public:
    static constexpr const char* typeName = "Coordinate4";
    static constexpr bool inventorBuiltin() { return true; }
    MFVec4f point{this, "point", {glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)}};
    void doAction(Action& action) override;

protected:
    ~Coordinate4() override = default;
};

} // namespace volsg
