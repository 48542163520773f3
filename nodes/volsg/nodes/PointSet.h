#pragma once
// PointSet: numPoints consecutive points (-1: all from startIndex). Unlit, not pickable.
#include <volsg/nodes/VertexShape.h>

namespace volsg {

/// numPoints consecutive points (-1: all from startIndex). Unlit, not pickable.
class PointSet : public Inherit<NonIndexedShape, PointSet> {
public:
    static constexpr const char* typeName = "PointSet";
    static constexpr bool inventorBuiltin() { return true; }
    SFInt32 numPoints{this, "numPoints", -1};

protected:
    ~PointSet() override = default;
    ShapeTopology topology(std::size_t pointCount) const override;
};

} // namespace volsg
