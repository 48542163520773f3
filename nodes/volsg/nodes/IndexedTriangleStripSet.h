#pragma once
// IndexedTriangleStripSet: triangle strips, each index list ended by -1.
#include <volsg/nodes/VertexShape.h>

namespace volsg {

/// Triangle strips, each index list ended by -1.
class IndexedTriangleStripSet : public Inherit<IndexedShape, IndexedTriangleStripSet> {
public:
    static constexpr const char* typeName = "IndexedTriangleStripSet";
    static constexpr bool inventorBuiltin() { return true; }

protected:
    ~IndexedTriangleStripSet() override = default;
    ShapeTopology topology(std::size_t pointCount) const override;
};

} // namespace volsg
