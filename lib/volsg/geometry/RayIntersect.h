#pragma once
// Ray against triangles, in double precision: the geometry behind picking.

#include <optional>

#include <glm/glm.hpp>

#include <volsg/math/Ray.h>

namespace volsg {

/// Where a ray meets a triangle: the ray parameter and the barycentric weights of the second
/// and third corners (the point is (1-u-v)*a + u*b + v*c).
struct TriangleHit {
    double t = 0.0;
    double u = 0.0;
    double v = 0.0;
};

/// Möller–Trumbore. Both faces count (no culling); edges are inclusive, so a ray through the
/// shared edge of two triangles hits at least one of them. Hits with t < 0 are not reported;
/// a ray parallel to the triangle's plane (or a degenerate triangle) never hits.
std::optional<TriangleHit> intersectTriangle(const Ray& ray, const glm::dvec3& a,
                                             const glm::dvec3& b, const glm::dvec3& c);

} // namespace volsg
