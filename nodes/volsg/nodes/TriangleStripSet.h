#pragma once
// TriangleStripSet: triangle strips of numVertices consecutive points each (-1: the rest).
#include <volsg/nodes/VertexShape.h>

namespace volsg {

/// Triangle strips of numVertices consecutive points each (-1: the rest).
class TriangleStripSet : public Inherit<NonIndexedShape, TriangleStripSet> {
public:
    static constexpr const char* typeName = "TriangleStripSet";
    static constexpr bool inventorBuiltin() { return true; }
    MFInt32 numVertices{this, "numVertices", {-1}};

protected:
    ~TriangleStripSet() override = default;
    ShapeTopology topology(std::size_t pointCount) const override;
};

} // namespace volsg
