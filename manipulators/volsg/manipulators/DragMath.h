#pragma once
// The UI-free geometry behind manipulators and the examiner: rays against planes, boxes and
// spheres, and the projection of a mouse ray onto the line, plane or sphere a handle moves on.

#include <optional>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <volsg/fields/Values.h>
#include <volsg/math/Box3.h>
#include <volsg/math/Ray.h>

namespace volsg {

/// The ray parameter t >= 0 where the ray meets the plane n . p = d; none when the ray is
/// parallel to the plane (|n . dir| below 1e-12 |n||dir|) or the plane is behind the origin.
std::optional<double> intersectRayPlane(const Ray& ray, const glm::dvec3& normal, double distance);

/// Where a ray enters an axis-aligned box (or leaves it, when it starts inside).
struct BoxHit {
    double t = 0.0;
    /// The face hit: 0 -x, 1 +x, 2 -y, 3 +y, 4 -z, 5 +z.
    int face = 0;
};
std::optional<BoxHit> intersectRayBox(const Ray& ray, const Box3& box);

/// The nearest t >= 0 where the ray meets the sphere (the exit point when it starts inside).
std::optional<double> intersectRaySphere(const Ray& ray, const glm::dvec3& center, double radius);

/// The parameter s of the point `linePoint + s * lineDirection` nearest to the ray: how far a
/// handle constrained to that line follows the mouse. None when the ray is parallel to the line
/// (within 1e-9 of parallel, after normalisation), where the drag is undefined.
std::optional<double> closestLineParameter(const Ray& ray, const glm::dvec3& linePoint,
                                           const glm::dvec3& lineDirection);

/// A point on the sphere for a virtual trackball: where the ray hits the sphere (the near side);
/// a ray that misses gives the point of the sphere nearest to the ray, on the silhouette, so a
/// drag past the rim keeps rotating instead of jumping.
glm::dvec3 trackballPoint(const Ray& ray, const glm::dvec3& center, double radius);

/// The shortest rotation that turns direction `from` into direction `to` (neither need be unit
/// length). Opposite directions give a half turn about an axis perpendicular to both.
glm::dquat rotationBetween(const glm::dvec3& from, const glm::dvec3& to);

/// The axis-angle Rotation of a quaternion (normalised first, the shorter way round; identity
/// for a zero turn).
Rotation rotationFromQuat(const glm::dquat& q);

} // namespace volsg
