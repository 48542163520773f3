#pragma once
// The plane of a planar section in the volume's local coordinates: where it cuts the volume
// box, and where a ray meets it.

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/math/Box3.h>
#include <volsg/math/Ray.h>

namespace volsg {

class VolumeGrid;

/// normal . p = distance, unit normal, local coordinates of the volume.
struct SlicePlane {
    glm::dvec3 normal{0.0, 0.0, 1.0};
    double distance = 0.0;

    /// The plane through the voxel centres of slice `sliceNumber` (clamped to the data)
    /// across `axis` (0 x, 1 y, 2 z), normal +axis.
    static SlicePlane orthogonal(const VolumeGrid& grid, int axis, int sliceNumber);
    /// A plane from any normal and distance (normalised); nothing for a zero or non-finite
    /// normal.
    static std::optional<SlicePlane> fromPlane(const glm::dvec3& normal, double distance);

    /// The polygon where the plane cuts the box [-halfExtent, halfExtent], as triangles
    /// (empty when it misses the box).
    std::vector<glm::vec3> polygon(const glm::dvec3& halfExtent) const;
    /// The local bounding box of polygon() (empty when the plane misses the box).
    Box3 polygonBounds(const glm::dvec3& halfExtent) const;
    /// Where a local ray meets the plane inside the box, as the ray parameter t >= 0, or
    /// nothing (parallel, behind the origin, or outside the box).
    std::optional<double> intersect(const Ray& localRay, const glm::dvec3& halfExtent) const;
};

} // namespace volsg
