#pragma once
// Cylinder along +Y, centred on the origin.
#include <volsg/fields/Fields.h>
#include <volsg/math/Box3.h>
#include <volsg/nodes/Shape.h>

#include <cstdint>

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

    /// Also the tessellation (SCREEN_SPACE complexity changes it with the view).
    std::uint64_t meshKey(const State& state) const override;
    void buildCoarserMeshes(const State& state, std::vector<CoarserMesh>& out) const override;
    /// The box the tessellation's screen size is measured by (Coin's computeBBox).
    Box3 objectBox() const;

protected:
    ~Cylinder() override = default;
    void buildMesh(const State& state, Mesh& out) const override;
};

} // namespace volsg
