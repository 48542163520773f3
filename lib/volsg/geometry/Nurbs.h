#pragma once
// Rational B-spline (NURBS) curves and surfaces as Inventor's SoNurbsCurve, SoNurbsSurface and
// their trimming profiles describe them, evaluated exactly (Cox-de Boor basis functions and
// their derivatives, in double precision) and tessellated the way Coin drives GLU: each
// non-empty knot span cut into equal parameter steps (GLU_DOMAIN_DISTANCE) at Coin's step
// counts for a Complexity value. Trim loops cut the parameter domain: a point is kept where
// the loops wind around it a positive number of times (GLU's rule: the region to the left of
// each loop, so a counter-clockwise loop keeps its inside and a clockwise loop inside it cuts
// a hole; without trim loops the whole domain is kept). No scene graph: the node types gather
// control points and loops from the state (nodes/volsg/nodes/NurbsShapes.cpp).
//
// Why not GLU's own NURBS tessellator (gluNurbsSurface in GLU_NURBS_TESSELLATOR mode, as Coin
// uses it): Mesa's GLU still calls glPushAttrib and glPopAttrib around every surface in that
// mode, which are errors in the 3.3 core contexts volsg draws with, and reach whatever
// context is current through libOpenGL while a mesh is built during a render. The sampling
// and the trimming rule here are GLU's; only its polygon tessellator is used (no GL calls).

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/geometry/Mesh.h>

namespace volsg {

/// Highest order (degree + 1) drawn; GLU's own limit is 24, more is never meaningful.
inline constexpr int kMaxNurbsOrder = 24;

/// Why `numControlPoints` control points over `knots` make no B-spline, or an empty string when
/// they do: the order (knots - control points) must be 2 to kMaxNurbsOrder, the knots finite
/// and non-decreasing, and the domain [knots[order-1], knots[numControlPoints]] not empty.
std::string nurbsKnotProblem(std::int64_t numControlPoints, std::span<const float> knots);

/// A B-spline curve or one direction of a surface: `order`, the knots, homogeneous control
/// points (x, y, z, w): the point is (x, y, z) / w, as Inventor's Coordinate4 (w = 1 for
/// Coordinate3).
struct NurbsCurveData {
    int order = 2;
    std::span<const float> knots;
    std::span<const glm::dvec4> points;
};

/// A tensor-product surface: countU x countV control points, u running fastest (point (i, j)
/// is points[j * countU + i]).
struct NurbsSurfaceData {
    int orderU = 2, orderV = 2;
    int countU = 0, countV = 0;
    std::span<const float> knotsU, knotsV;
    std::span<const glm::dvec4> points;
};

/// The curve's homogeneous point at u (clamped to the domain); divide by w for the point.
glm::dvec4 evaluateNurbsCurve(const NurbsCurveData& curve, double u);

/// A surface point with its unit normal dS/du x dS/dv (zero where the surface degenerates,
/// e.g. at a pole where a row of control points coincides).
struct NurbsSurfacePoint {
    glm::dvec3 position{0.0};
    glm::dvec3 normal{0.0};
    double w = 1.0; ///< the homogeneous weight there; not > 0: no finite point
};
NurbsSurfacePoint evaluateNurbsSurface(const NurbsSurfaceData& surface, double u, double v);

/// Coin's sampling for a Complexity value in [0, 1] (SoComplexity OBJECT_SPACE, its "new"
/// NURBS complexity): the rate, in steps per unit of parameter, given to GLU_U_STEP and
/// GLU_V_STEP. A surface direction with `count` control points over `numKnots` knots takes
/// (count < 4 ? 1 : count - 3) * s + 1 steps over the whole knot range (s = 5 at complexity
/// 0.5), 1 when linear (order 2, 2 points) and 4 s when closed (first and last control point
/// equal); a curve (count < 4 ? 1 : count - 3) * c (c = 10 at 0.5), 4 s - 1 when closed.
double nurbsSurfaceRate(int count, int numKnots, bool closed, double knotRange, float complexity);
double nurbsCurveRate(int count, bool closed, double knotRange, float complexity);

/// The parameters a direction is sampled at: the domain's non-empty knot spans each cut into
/// ceil(rate * span) equal steps (at least one), span ends included once, increasing. Throws
/// Error past `limit` values (before allocating them).
std::vector<double> nurbsSampleParameters(std::span<const float> knots, int order, double rate,
                                          std::size_t limit);

/// The tessellation of a surface (Mesh::Primitive::Triangles, one vertex per parameter sample,
/// counter-clockwise in (u, v), exact positions and normals).
struct NurbsSurfaceMeshOptions {
    double rateU = 1.0, rateV = 1.0;
    /// Closed loops in (u, v) (the last point joins the first); empty: untrimmed.
    std::span<const std::vector<glm::dvec2>> trimLoops;
    /// Texture coordinates: none, the default (u and v over the knot range of each direction,
    /// 0 to 1, as Coin), or `texture` evaluated at the parameters mapped linearly from the
    /// surface's domain to the texture surface's.
    enum class TexCoords { None, Default, Surface } texCoords = TexCoords::None;
    const NurbsSurfaceData* texture = nullptr;
    std::size_t maxSamples = std::size_t(1) << 21; ///< grid samples (Error past it)
};
/// Builds the mesh; a surface that is trimmed away, or whose weights are not all positive
/// where it is sampled, gives an empty mesh. Throws Error past the limits.
void buildNurbsSurfaceMesh(const NurbsSurfaceData& surface, const NurbsSurfaceMeshOptions& options,
                           Mesh& out);

/// A curve as a polyline (Mesh::Primitive::Lines, no normals): its points at the sample
/// parameters. Empty where a weight is not positive.
void buildNurbsCurveMesh(const NurbsCurveData& curve, double rate, std::size_t maxSamples,
                         Mesh& out);

/// A curve in the plane (trim curves, Text3 profiles): the 2D points (x, y) / w of `curve`'s
/// (x, y, 0, w) control points at its sample parameters.
std::vector<glm::dvec2> sampleNurbsCurve2D(const NurbsCurveData& curve, double rate,
                                           std::size_t maxSamples);

} // namespace volsg
