#pragma once
// Cube: an axis-aligned box centred on the origin.
#include <volsg/fields/Fields.h>
#include <volsg/nodes/Shape.h>

namespace volsg {

class Cube : public Inherit<Shape, Cube> {
public:
    static constexpr const char* typeName = "Cube";
    static constexpr bool inventorBuiltin() { return true; }
    SFFloat width{this, "width", 2.0f};
    SFFloat height{this, "height", 2.0f};
    SFFloat depth{this, "depth", 2.0f};

protected:
    ~Cube() override = default;
    void buildMesh(const State& state, Mesh& out) const override;
};

} // namespace volsg
