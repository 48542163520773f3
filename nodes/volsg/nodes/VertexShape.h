#pragma once
// The vertex shapes (Inventor's SoVertexShape family): their points, normals, materials and
// texture coordinates come from their vertexProperty field or the state, bound by the
// bindings in scope (lib/volsg/geometry/VertexShapes.h has the rules).
#include <cstdint>

#include <volsg/fields/Fields.h>
#include <volsg/geometry/VertexShapes.h>
#include <volsg/nodes/Shape.h>

namespace volsg {

class VertexProperty;

class VertexShape : public Inherit<Shape, VertexShape> {
public:
    static constexpr const char* typeName = "VertexShape";
    SFNode vertexProperty{this, "vertexProperty"};

    /// vertexProperty's value if it is a VertexProperty, else null.
    const VertexProperty* ownVertexProperty() const;
    std::uint64_t meshKey(const State& state) const override;

protected:
    ~VertexShape() override = default;
    void buildMesh(const State& state, Mesh& out) const override;
    /// The shape's faces over `pointCount` points.
    virtual ShapeTopology topology(std::size_t pointCount) const = 0;
};

/// Shapes that take consecutive points from startIndex (FaceSet, LineSet, ...).
class NonIndexedShape : public Inherit<VertexShape, NonIndexedShape> {
public:
    static constexpr const char* typeName = "NonIndexedShape";
    SFInt32 startIndex{this, "startIndex", 0};

protected:
    ~NonIndexedShape() override = default;
};

/// Shapes that index their points (IndexedFaceSet, ...): each list ended by -1; materialIndex,
/// normalIndex and textureCoordIndex run parallel to coordIndex for PER_VERTEX_INDEXED (or
/// count faces or parts for the other indexed bindings); [-1] means "as coordIndex".
class IndexedShape : public Inherit<VertexShape, IndexedShape> {
public:
    static constexpr const char* typeName = "IndexedShape";
    MFInt32 coordIndex{this, "coordIndex", {0}};
    MFInt32 materialIndex{this, "materialIndex", {-1}};
    MFInt32 normalIndex{this, "normalIndex", {-1}};
    MFInt32 textureCoordIndex{this, "textureCoordIndex", {-1}};

protected:
    ~IndexedShape() override = default;
    /// The topology with this shape's index fields attached.
    ShapeTopology withIndices(ShapeTopology t) const;
};

} // namespace volsg
