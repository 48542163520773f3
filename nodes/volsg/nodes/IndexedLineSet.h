#pragma once
// IndexedLineSet: polylines, each index list ended by -1. Unlit, not pickable.
#include <volsg/nodes/VertexShape.h>

namespace volsg {

/// Polylines, each index list ended by -1. Unlit, not pickable.
class IndexedLineSet : public Inherit<IndexedShape, IndexedLineSet> {
public:
    static constexpr const char* typeName = "IndexedLineSet";
    static constexpr bool inventorBuiltin() { return true; }

protected:
    ~IndexedLineSet() override = default;
    ShapeTopology topology(std::size_t pointCount) const override;
};

} // namespace volsg
