#pragma once
// LineSet: polylines of numVertices consecutive points each (-1: the rest). Unlit, not pickable.
#include <volsg/nodes/VertexShape.h>

namespace volsg {

/// Polylines of numVertices consecutive points each (-1: the rest). Unlit, not pickable.
class LineSet : public Inherit<NonIndexedShape, LineSet> {
public:
    static constexpr const char* typeName = "LineSet";
    static constexpr bool inventorBuiltin() { return true; }
    MFInt32 numVertices{this, "numVertices", {-1}};

protected:
    ~LineSet() override = default;
    ShapeTopology topology(std::size_t pointCount) const override;
};

} // namespace volsg
