#pragma once
// IndexedLineSet: polylines from Coordinate3 points, each index list ended by -1. Unlit, not
// pickable. A polyline with an out-of-range index is skipped silently.
#include <volsg/fields/Fields.h>
#include <volsg/nodes/Shape.h>

namespace volsg {

class IndexedLineSet : public Inherit<Shape, IndexedLineSet> {
public:
    static constexpr const char* typeName = "IndexedLineSet";
    static constexpr bool inventorBuiltin() { return true; }
    MFInt32 coordIndex{this, "coordIndex", {0}};
    MFInt32 materialIndex{this, "materialIndex", {-1}};
    MFInt32 normalIndex{this, "normalIndex", {-1}};
    MFInt32 textureCoordIndex{this, "textureCoordIndex", {-1}};

protected:
    ~IndexedLineSet() override = default;
    void buildMesh(const State& state, Mesh& out) const override;
    std::uint64_t meshKey(const State& state) const override;
};

} // namespace volsg
