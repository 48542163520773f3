#pragma once
// ProfileCoordinate3: homogeneous profile points: (x, y, w) stands for (x / w, y / w), and
// gives NurbsProfile its weights (ProfileCoordinate2.h says what profile points are).
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class ProfileCoordinate3 : public Inherit<Node, ProfileCoordinate3> {
public:
    static constexpr const char* typeName = "ProfileCoordinate3";
    static constexpr bool inventorBuiltin() { return true; }
    MFVec3f point{this, "point", {glm::vec3(0.0f, 0.0f, 1.0f)}};
    void doAction(Action& action) override;

protected:
    ~ProfileCoordinate3() override = default;
};

} // namespace volsg
