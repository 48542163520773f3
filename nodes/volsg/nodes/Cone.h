#pragma once
// Cone along +Y, centred on the origin: apex at height/2, base at -height/2.
#include <volsg/fields/Fields.h>
#include <volsg/nodes/Shape.h>

namespace volsg {

class Cone : public Inherit<Shape, Cone> {
public:
    static constexpr const char* typeName = "Cone";
    static constexpr bool inventorBuiltin() { return true; }
    enum Part { SIDES = 1, BOTTOM = 2, ALL = 3 };
    static const EnumValues partNames;
    SFBitMask parts{this, "parts", partNames, ALL};
    SFFloat bottomRadius{this, "bottomRadius", 1.0f};
    SFFloat height{this, "height", 2.0f};

protected:
    ~Cone() override = default;
    void buildMesh(const State& state, Mesh& out) const override;
};

} // namespace volsg
