#pragma once
// QuadMesh: a grid of verticesPerColumn rows of verticesPerRow points, drawn as quads.
#include <volsg/nodes/VertexShape.h>

namespace volsg {

/// A grid of verticesPerColumn rows of verticesPerRow points, drawn as quads.
class QuadMesh : public Inherit<NonIndexedShape, QuadMesh> {
public:
    static constexpr const char* typeName = "QuadMesh";
    static constexpr bool inventorBuiltin() { return true; }
    SFInt32 verticesPerColumn{this, "verticesPerColumn", 1};
    SFInt32 verticesPerRow{this, "verticesPerRow", 1};

protected:
    ~QuadMesh() override = default;
    ShapeTopology topology(std::size_t pointCount) const override;
};

} // namespace volsg
