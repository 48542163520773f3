#pragma once
// Triangles, lines or points with per-vertex attributes: what every shape node turns into, for
// drawing, bounding boxes and picking alike.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/math/Box3.h>

namespace volsg {

struct Mesh {
    enum class Primitive { Triangles, Lines, Points };
    Primitive primitive = Primitive::Triangles;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;     ///< one per position (empty for lines and points)
    std::vector<glm::vec4> colors;      ///< optional, one per position (overrides diffuse)
    std::vector<glm::vec2> texCoords;   ///< optional, one per position
    std::vector<std::uint32_t> indices; ///< 3 per triangle, 2 per line segment, 1 per point
    /// Triangles only, optional: 2 per edge, the edges the LINES draw style shows, as Coin
    /// draws polygons in line mode (a face set's polygons and a cube's or a cylinder's quads
    /// without the diagonals of their triangulation). Empty: every triangle's edges.
    std::vector<std::uint32_t> outline;

    Box3 bounds() const {
        Box3 b;
        for (const auto& p : positions)
            b.extendBy(glm::dvec3(p));
        return b;
    }
    std::size_t primitiveCount() const { return indices.size() / verticesPerPrimitive(); }
    std::size_t verticesPerPrimitive() const {
        return primitive == Primitive::Triangles ? 3 : primitive == Primitive::Lines ? 2 : 1;
    }
};

/// A coarser tessellation of a curved shape than its mesh, with the largest distance of its
/// surface from the true one (the shape's own units): what lets a renderer draw it instead where
/// that distance projects below a fraction of a pixel (lib/volsg/render/ShapeDetail.h).
struct CoarserMesh {
    Mesh mesh;
    double deviation = 0.0;
};

/// The coarsest a CoarserMesh may be, as its deviation over the shape's radius. A quarter of a
/// pixel is a large share of a shape a pixel or two wide: its silhouette, which is most of its
/// pixels, then moves visibly (with 6 sides, a sphere 1.5 pixels wide loses a sixth of its
/// area). At a tenth of the radius (a sphere of 10 sides and 5 bands, a cylinder of 8 sides)
/// the silhouette keeps within a tenth of the shape's size as well.
constexpr double kCoarsestRelativeDeviation = 0.1;

} // namespace volsg
