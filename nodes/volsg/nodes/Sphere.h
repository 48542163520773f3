#pragma once
// Sphere centred on the origin.
#include <volsg/fields/Fields.h>
#include <volsg/nodes/Shape.h>

namespace volsg {

class Sphere : public Inherit<Shape, Sphere> {
public:
    static constexpr const char* typeName = "Sphere";
    static constexpr bool inventorBuiltin() { return true; }
    SFFloat radius{this, "radius", 1.0f};

protected:
    ~Sphere() override = default;
    void buildMesh(const State& state, Mesh& out) const override;
};

} // namespace volsg
