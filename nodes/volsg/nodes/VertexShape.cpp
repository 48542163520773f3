#include <volsg/nodes/VertexShape.h>

#include <volsg/nodes/FaceSet.h>
#include <volsg/nodes/IndexedFaceSet.h>
#include <volsg/nodes/IndexedLineSet.h>
#include <volsg/nodes/IndexedTriangleStripSet.h>
#include <volsg/nodes/LineSet.h>
#include <volsg/nodes/PointSet.h>
#include <volsg/nodes/QuadMesh.h>
#include <volsg/nodes/TriangleStripSet.h>

#include <volsg/geometry/MeshKey.h>
#include <volsg/nodes/ShapeState.h>
#include <volsg/nodes/VertexProperty.h>
#include <volsg/state/State.h>

namespace volsg {

const VertexProperty* VertexShape::ownVertexProperty() const {
    const Node* n = vertexProperty.getValue();
    return n && n->isA<VertexProperty>() ? static_cast<const VertexProperty*>(n) : nullptr;
}

std::uint64_t VertexShape::meshKey(const State& state) const {
    return combineMeshKey(version(), gatherShapeState(state, ownVertexProperty()).meshKey());
}

void VertexShape::buildMesh(const State& state, Mesh& out) const {
    const ShapeState shape = gatherShapeState(state, ownVertexProperty());
    VertexArrays storage;
    const VertexAttributes attributes = vertexAttributes(shape, storage);
    buildVertexShapeMesh(topology(attributes.points.size()), attributes, out);
}

ShapeTopology IndexedShape::withIndices(ShapeTopology t) const {
    t.materialIndex = materialIndex.getValues();
    t.normalIndex = normalIndex.getValues();
    t.textureCoordIndex = textureCoordIndex.getValues();
    return t;
}

ShapeTopology FaceSet::topology(std::size_t pointCount) const {
    return makeFaceSetTopology(numVertices.getValues(), startIndex(), pointCount);
}
ShapeTopology IndexedFaceSet::topology(std::size_t pointCount) const {
    return withIndices(makeIndexedFaceSetTopology(coordIndex.getValues(), pointCount));
}
ShapeTopology TriangleStripSet::topology(std::size_t pointCount) const {
    return makeTriangleStripSetTopology(numVertices.getValues(), startIndex(), pointCount);
}
ShapeTopology IndexedTriangleStripSet::topology(std::size_t pointCount) const {
    return withIndices(makeIndexedTriangleStripSetTopology(coordIndex.getValues(), pointCount));
}
ShapeTopology QuadMesh::topology(std::size_t pointCount) const {
    return makeQuadMeshTopology(verticesPerRow(), verticesPerColumn(), startIndex(), pointCount);
}
ShapeTopology LineSet::topology(std::size_t pointCount) const {
    return makeLineSetTopology(numVertices.getValues(), startIndex(), pointCount);
}
ShapeTopology IndexedLineSet::topology(std::size_t pointCount) const {
    return withIndices(makeIndexedLineSetTopology(coordIndex.getValues(), pointCount));
}
ShapeTopology PointSet::topology(std::size_t pointCount) const {
    return makePointSetTopology(numPoints(), startIndex(), pointCount);
}

} // namespace volsg
