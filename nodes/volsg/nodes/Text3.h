#pragma once
// Text3: extruded 3D text (Inventor's SoText3) in the x-y plane, the Font's size in object
// units: front faces at z = 0 facing +z, sides swept back along the profile in scope (or to
// z = -1 without one, as Coin), back faces at the back facing -z. Under a MaterialBinding
// other than OVERALL the front, sides and back take materials 0, 1 and 2.
#include <cstdint>

#include <volsg/fields/Fields.h>
#include <volsg/nodes/Shape.h>

namespace volsg {

class Text3 : public Inherit<Shape, Text3> {
public:
    static constexpr const char* typeName = "Text3";
    static constexpr bool inventorBuiltin() { return true; }
    enum Justification { LEFT = 1, RIGHT = 2, CENTER = 3 };
    enum Part { FRONT = 1, SIDES = 2, BACK = 4, ALL = 7 };
    static const EnumValues justificationNames, partNames;
    MFString string{this, "string", {""}};
    SFFloat spacing{this, "spacing", 1.0f};
    SFEnum justification{this, "justification", justificationNames, LEFT};
    SFBitMask parts{this, "parts", partNames, FRONT};

    std::uint64_t meshKey(const State& state) const override;

protected:
    ~Text3() override = default;
    void buildMesh(const State& state, Mesh& out) const override;
};

} // namespace volsg
