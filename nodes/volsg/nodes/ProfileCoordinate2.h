#pragma once
// ProfileCoordinate2: the points the profiles (LinearProfile, NurbsProfile) index. For a NURBS
// surface they lie in its (u, v) parameter space; for Text3 (x, y) is a depth and a distance
// out from the glyph outline.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class ProfileCoordinate2 : public Inherit<Node, ProfileCoordinate2> {
public:
    static constexpr const char* typeName = "ProfileCoordinate2";
    static constexpr bool inventorBuiltin() { return true; }
    MFVec2f point{this, "point", {glm::vec2(0.0f)}};
    void doAction(Action& action) override;

protected:
    ~ProfileCoordinate2() override = default;
};

} // namespace volsg
