#pragma once
// NurbsCurve and IndexedNurbsCurve (Inventor's SoNurbsCurve, SoIndexedNurbsCurve): a rational
// B-spline curve through the Coordinate3 (weight 1) or Coordinate4 (homogeneous) points in
// scope, drawn as an unlit polyline (lib/volsg/geometry/Nurbs.h). The order is the number of
// knots minus numControlPoints. Counts, knots or indices that make no curve draw nothing.
#include <volsg/fields/Fields.h>
#include <volsg/nodes/Shape.h>

namespace volsg {

class NurbsCurve : public Inherit<Shape, NurbsCurve> {
public:
    static constexpr const char* typeName = "NurbsCurve";
    static constexpr bool inventorBuiltin() { return true; }
    SFInt32 numControlPoints{this, "numControlPoints", 0};
    MFFloat knotVector{this, "knotVector", {0.0f}};

protected:
    ~NurbsCurve() override = default;
    void buildMesh(const State& state, Mesh& out) const override;
};

class IndexedNurbsCurve : public Inherit<Shape, IndexedNurbsCurve> {
public:
    static constexpr const char* typeName = "IndexedNurbsCurve";
    static constexpr bool inventorBuiltin() { return true; }
    SFInt32 numControlPoints{this, "numControlPoints", 0};
    MFInt32 coordIndex{this, "coordIndex", {0}};
    MFFloat knotVector{this, "knotVector", {0.0f}};

protected:
    ~IndexedNurbsCurve() override = default;
    void buildMesh(const State& state, Mesh& out) const override;
};

} // namespace volsg
