#pragma once
// Complexity: how finely the shapes after it are tessellated (Inventor's SoComplexity): value
// 0..1 scales the number of slices of spheres, cones and cylinders and the steps of NURBS and
// text (0.5: the default tessellation). SCREEN_SPACE and BOUNDING_BOX are taken as
// OBJECT_SPACE (the tessellation does not follow the view).
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class Complexity : public Inherit<Node, Complexity> {
public:
    static constexpr const char* typeName = "Complexity";
    static constexpr bool inventorBuiltin() { return true; }
    enum Type { OBJECT_SPACE, SCREEN_SPACE, BOUNDING_BOX };
    static const EnumValues typeNames;

    SFEnum type{this, "type", typeNames, OBJECT_SPACE};
    SFFloat value{this, "value", 0.5f};
    SFFloat textureQuality{this, "textureQuality", 0.5f};

    void doAction(Action& action) override;

protected:
    ~Complexity() override = default;
};

} // namespace volsg
