#pragma once
// IndexedFaceSet: polygons from Coordinate3 points, each index list ended by -1; convex
// polygons are fanned; normals from the Normal node in scope (normalIndex, else coordIndex
// order) or computed per face (rules in volsg/geometry/IndexedMeshes.h). A polygon with an
// out-of-range index is skipped silently, never a crash or an error.
#include <volsg/fields/Fields.h>
#include <volsg/nodes/Shape.h>

namespace volsg {

class IndexedFaceSet : public Inherit<Shape, IndexedFaceSet> {
public:
    static constexpr const char* typeName = "IndexedFaceSet";
    static constexpr bool inventorBuiltin() { return true; }
    MFInt32 coordIndex{this, "coordIndex", {0}};
    MFInt32 materialIndex{this, "materialIndex", {-1}};
    MFInt32 normalIndex{this, "normalIndex", {-1}};
    MFInt32 textureCoordIndex{this, "textureCoordIndex", {-1}};

protected:
    ~IndexedFaceSet() override = default;
    void buildMesh(const State& state, Mesh& out) const override;
    std::uint64_t meshKey(const State& state) const override;
};

} // namespace volsg
