#pragma once
// Sphere centred on the origin.
#include <volsg/fields/Fields.h>
#include <volsg/math/Box3.h>
#include <volsg/nodes/Shape.h>

#include <cstdint>

namespace volsg {

class Sphere : public Inherit<Shape, Sphere> {
public:
    static constexpr const char* typeName = "Sphere";
    static constexpr bool inventorBuiltin() { return true; }
    SFFloat radius{this, "radius", 1.0f};

    /// Also the tessellation (SCREEN_SPACE complexity changes it with the view).
    std::uint64_t meshKey(const State& state) const override;
    void buildCoarserMeshes(const State& state, std::vector<CoarserMesh>& out) const override;
    /// The box the tessellation's screen size is measured by (Coin's computeBBox).
    Box3 objectBox() const;

protected:
    ~Sphere() override = default;
    void buildMesh(const State& state, Mesh& out) const override;
};

} // namespace volsg
