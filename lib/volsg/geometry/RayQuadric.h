#pragma once
// A ray against Inventor's round primitives exactly (not their tessellation), as Coin picks
// them: the sphere, and the sides and caps of the cylinder and cone, in their own coordinates
// (axis y, centred on the origin). Every crossing of the ray's line is reported, behind the
// origin too; the caller keeps those in its range.

#include <vector>

#include <glm/glm.hpp>

#include <volsg/math/Ray.h>

namespace volsg {

/// Where the line meets a surface: the ray parameter, the point and the outward unit normal.
struct QuadricHit {
    double t = 0.0;
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0.0};
};

/// The sphere of `radius` about the origin (at most two crossings).
std::vector<QuadricHit> intersectSphere(const Ray& ray, double radius);
/// The side of the cylinder about the y axis, |y| <= height / 2.
std::vector<QuadricHit> intersectCylinderSide(const Ray& ray, double radius, double height);
/// The disc of `radius` in the plane y = `y`, its normal along `normalY` (+1 or -1) times y.
std::vector<QuadricHit> intersectDisc(const Ray& ray, double radius, double y, double normalY);
/// The side of the cone with its apex at y = height / 2 and its base of `bottomRadius` at
/// y = -height / 2.
std::vector<QuadricHit> intersectConeSide(const Ray& ray, double bottomRadius, double height);

} // namespace volsg
