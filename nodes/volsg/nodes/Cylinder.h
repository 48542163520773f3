#pragma once
// Cylinder along +Y, centred on the origin.
#include <volsg/fields/Fields.h>
#include <volsg/nodes/Shape.h>

namespace volsg {

class Cylinder : public Inherit<Shape, Cylinder> {
public:
    static constexpr const char* typeName = "Cylinder";
    static constexpr bool inventorBuiltin() { return true; }
    enum Part { SIDES = 1, TOP = 2, BOTTOM = 4, ALL = 7 };
    static const EnumValues partNames;
    SFBitMask parts{this, "parts", partNames, ALL};
    SFFloat radius{this, "radius", 1.0f};
    SFFloat height{this, "height", 2.0f};

protected:
    ~Cylinder() override = default;
    void buildMesh(const State& state, Mesh& out) const override;
};

} // namespace volsg
