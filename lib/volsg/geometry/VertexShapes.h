#pragma once
// Meshes of Inventor's vertex shapes (SoFaceSet, SoIndexedFaceSet, SoTriangleStripSet,
// SoIndexedTriangleStripSet, SoQuadMesh, SoLineSet, SoIndexedLineSet, SoPointSet) from plain
// arrays: the topology of each shape, and the bindings that say which normal, material and
// texture coordinate each corner takes. No scene graph: the node types gather the arrays from
// the state (nodes/volsg/nodes/VertexAttributes.h).

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/geometry/Mesh.h>

namespace volsg {

/// Inventor's bindings (SoMaterialBinding, SoNormalBinding, SoTextureCoordinateBinding), with
/// DEFAULT already resolved by the caller. What a part and a face are depends on the shape:
/// face sets: both a polygon; triangle strips: a strip and a triangle; quad meshes: a row and
/// a quad; line sets: a segment and a polyline; point sets: a point and a point.
enum class Binding {
    Overall,
    PerPart,
    PerPartIndexed,
    PerFace,
    PerFaceIndexed,
    PerVertex,
    PerVertexIndexed,
};

/// One corner of a face: which point it is, and where it stands for the bindings.
struct Corner {
    std::int32_t point = 0;   ///< index into the points
    std::uint32_t slot = 0;   ///< position in coordIndex (indexed shapes), -1s counted
    std::uint32_t vertex = 0; ///< running number of the shape's vertices, -1s not counted
};

/// A polygon (a polyline or a point for line and point sets): corners [begin, end) of the
/// topology's corners, and its face and part numbers for PER_FACE and PER_PART bindings.
struct Face {
    std::uint32_t begin = 0, end = 0;
    std::uint32_t face = 0, part = 0;
};

/// What a vertex shape is made of, before attributes. Built by the make*Topology functions.
struct ShapeTopology {
    Mesh::Primitive primitive = Mesh::Primitive::Triangles;
    std::vector<Corner> corners;
    std::vector<Face> faces;
    bool indexed = false; ///< PER_*_INDEXED bindings read the index fields below
    /// Generated normals average every face at a point whatever the crease angle (Inventor's
    /// quad meshes are always smooth).
    bool alwaysSmooth = false;
    /// For indexed shapes: the index fields as the node has them ([-1] or empty: not in use).
    std::span<const std::int32_t> materialIndex, normalIndex, textureCoordIndex;
};

/// The arrays in scope and how they bind.
struct VertexAttributes {
    std::span<const glm::vec3> points;
    std::span<const glm::vec3> normals;
    Binding normalBinding = Binding::PerVertexIndexed;
    /// Diffuse colour and alpha (1 - transparency) of each material; empty or one entry with an
    /// OVERALL binding: no per-corner colours (the shape's material applies whole).
    std::span<const glm::vec4> colors;
    Binding materialBinding = Binding::Overall;
    std::span<const glm::vec2> textureCoords;
    Binding textureCoordBinding = Binding::PerVertexIndexed;
    /// Generated normals: faces meeting at a point share a smoothed normal where their normals
    /// are at most this far apart (radians); 0 gives flat faces (SoShapeHints creaseAngle).
    float creaseAngle = 0.0f;
    bool clockwise = false;  ///< SoShapeHints CLOCKWISE: generated normals face the other way
    bool convexFaces = true; ///< SoShapeHints CONVEX (fans); false: concave polygons are cut
                             ///< into triangles by ear clipping on their own plane
    /// When there are no texture coordinates but a texture is in scope: each corner takes the
    /// default mapping of its point (SoTextureCoordinateDefault over the shape's box).
    bool defaultTextureCoords = false;
    /// SoTextureCoordinatePlane: each corner takes (planeS . p, planeT . p) of its point p.
    bool planeTextureCoords = false;
    glm::vec3 planeS{1.0f, 0.0f, 0.0f}, planeT{0.0f, 1.0f, 0.0f};
};

/// Topologies. Corners that name a point out of range, and faces with fewer corners than their
/// primitive needs, are left out silently (Inventor draws the rest of the shape); counts and
/// indices that would read beyond the points stop the shape there. startIndex < 0 counts as 0.
ShapeTopology makeFaceSetTopology(std::span<const std::int32_t> numVertices,
                                  std::int32_t startIndex, std::size_t pointCount);
ShapeTopology makeIndexedFaceSetTopology(std::span<const std::int32_t> coordIndex,
                                         std::size_t pointCount);
ShapeTopology makeTriangleStripSetTopology(std::span<const std::int32_t> numVertices,
                                           std::int32_t startIndex, std::size_t pointCount);
ShapeTopology makeIndexedTriangleStripSetTopology(std::span<const std::int32_t> coordIndex,
                                                  std::size_t pointCount);
ShapeTopology makeQuadMeshTopology(std::int32_t verticesPerRow, std::int32_t verticesPerColumn,
                                   std::int32_t startIndex, std::size_t pointCount);
ShapeTopology makeLineSetTopology(std::span<const std::int32_t> numVertices,
                                  std::int32_t startIndex, std::size_t pointCount);
ShapeTopology makeIndexedLineSetTopology(std::span<const std::int32_t> coordIndex,
                                         std::size_t pointCount);
ShapeTopology makePointSetTopology(std::int32_t numPoints, std::int32_t startIndex,
                                   std::size_t pointCount);

/// The mesh: every corner its own vertex (so flat and smooth normals, per-face and per-vertex
/// colours mix freely), polygons fanned (or ear-clipped), lines as segments, points as points.
///
/// Normals (triangles only): given normals by their binding when there are enough of them for
/// every corner (an index or count beyond them makes the whole shape generate its normals);
/// else generated: each face's normal by Newell's method, smoothed across faces that share a
/// point position within the crease angle. Colours and texture coordinates likewise by their
/// bindings; an index beyond the array takes the last entry, as Coin does, so a short material
/// list never drops geometry. PER_VERTEX_INDEXED with the index field not in use ([-1])
/// indexes by coordIndex.
void buildVertexShapeMesh(const ShapeTopology& topology, const VertexAttributes& attributes,
                          Mesh& out);

/// Coin's default texture coordinates for a box: s and t run 0..1 along the two axes other than
/// the smallest, the longer one first (on a tie the higher axis first: a cube's s runs along z).
/// The Inventor Mentor scales t by the longest side instead; Coin, the reference here, does not.
glm::vec2 defaultTextureCoord(const glm::vec3& point, const glm::vec3& boxMin,
                              const glm::vec3& boxSize);

} // namespace volsg
