#pragma once
// IndexedFaceSet: polygons, each index list ended by -1.
#include <volsg/nodes/VertexShape.h>

namespace volsg {

/// Polygons, each index list ended by -1.
class IndexedFaceSet : public Inherit<IndexedShape, IndexedFaceSet> {
public:
    static constexpr const char* typeName = "IndexedFaceSet";
    static constexpr bool inventorBuiltin() { return true; }

protected:
    ~IndexedFaceSet() override = default;
    ShapeTopology topology(std::size_t pointCount) const override;
};

} // namespace volsg
