#pragma once
// NurbsSurface and IndexedNurbsSurface (Inventor's SoNurbsSurface, SoIndexedNurbsSurface): a
// rational B-spline surface through numUControlPoints x numVControlPoints points of the
// Coordinate3 or Coordinate4 in scope (u running fastest), trimmed by the profiles in scope,
// tessellated at Complexity's rate with exact normals (lib/volsg/geometry/Nurbs.h). Texture
// coordinates: the s and t NURBS over TextureCoordinate2's points when numS/TControlPoints and
// their knots describe one, else u and v over the knot range. Counts, knots or indices that
// make no surface draw nothing.
#include <cstdint>

#include <volsg/fields/Fields.h>
#include <volsg/nodes/Shape.h>

namespace volsg {

class NurbsSurface : public Inherit<Shape, NurbsSurface> {
public:
    static constexpr const char* typeName = "NurbsSurface";
    static constexpr bool inventorBuiltin() { return true; }
    SFInt32 numUControlPoints{this, "numUControlPoints", 0};
    SFInt32 numVControlPoints{this, "numVControlPoints", 0};
    SFInt32 numSControlPoints{this, "numSControlPoints", 0};
    SFInt32 numTControlPoints{this, "numTControlPoints", 0};
    MFFloat uKnotVector{this, "uKnotVector", {0.0f}};
    MFFloat vKnotVector{this, "vKnotVector", {0.0f}};
    MFFloat sKnotVector{this, "sKnotVector", {0.0f}};
    MFFloat tKnotVector{this, "tKnotVector", {0.0f}};

    std::uint64_t meshKey(const State& state) const override;

protected:
    ~NurbsSurface() override = default;
    void buildMesh(const State& state, Mesh& out) const override;
};

class IndexedNurbsSurface : public Inherit<Shape, IndexedNurbsSurface> {
public:
    static constexpr const char* typeName = "IndexedNurbsSurface";
    static constexpr bool inventorBuiltin() { return true; }
    SFInt32 numUControlPoints{this, "numUControlPoints", 0};
    SFInt32 numVControlPoints{this, "numVControlPoints", 0};
    MFInt32 coordIndex{this, "coordIndex", {0}};
    MFFloat uKnotVector{this, "uKnotVector", {0.0f}};
    MFFloat vKnotVector{this, "vKnotVector", {0.0f}};
    SFInt32 numSControlPoints{this, "numSControlPoints", 0};
    SFInt32 numTControlPoints{this, "numTControlPoints", 0};
    MFInt32 textureCoordIndex{this, "textureCoordIndex", {-1}};
    MFFloat sKnotVector{this, "sKnotVector", {0.0f}};
    MFFloat tKnotVector{this, "tKnotVector", {0.0f}};

    std::uint64_t meshKey(const State& state) const override;

protected:
    ~IndexedNurbsSurface() override = default;
    void buildMesh(const State& state, Mesh& out) const override;
};

} // namespace volsg
