#pragma once
// FaceSet: polygons of numVertices consecutive points each (-1: the rest).
#include <volsg/nodes/VertexShape.h>

namespace volsg {

/// Polygons of numVertices consecutive points each (-1: the rest).
class FaceSet : public Inherit<NonIndexedShape, FaceSet> {
public:
    static constexpr const char* typeName = "FaceSet";
    static constexpr bool inventorBuiltin() { return true; }
    MFInt32 numVertices{this, "numVertices", {-1}};

protected:
    ~FaceSet() override = default;
    ShapeTopology topology(std::size_t pointCount) const override;
};

} // namespace volsg
