#include <volsg/geometry/RayIntersect.h>

#include <cmath>

namespace volsg {

std::optional<TriangleHit> intersectTriangle(const Ray& ray, const glm::dvec3& a,
                                             const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a;
    const glm::dvec3 e2 = c - a;
    const glm::dvec3 p = glm::cross(ray.direction, e2);
    const double det = glm::dot(e1, p);
    // Relative test: a determinant this small against the edge and direction lengths means
    // the ray runs (numerically) in the triangle's plane, where t would be meaningless.
    const double scale = glm::length(e1) * glm::length(e2) * glm::length(ray.direction) + 1e-300;
    if (!(std::abs(det) > 1e-14 * scale)) return std::nullopt;
    const double invDet = 1.0 / det;
    const glm::dvec3 s = ray.origin - a;
    const double u = glm::dot(s, p) * invDet;
    if (u < 0.0 || u > 1.0) return std::nullopt;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(ray.direction, q) * invDet;
    if (v < 0.0 || u + v > 1.0) return std::nullopt;
    const double t = glm::dot(e2, q) * invDet;
    if (!(t >= 0.0)) return std::nullopt;
    return TriangleHit{t, u, v};
}

} // namespace volsg
