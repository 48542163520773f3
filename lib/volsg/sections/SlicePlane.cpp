#include <volsg/sections/SlicePlane.h>

#include <algorithm>
#include <cmath>

#include <volsg/slicing/ProxyPlaneCutter.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

SlicePlane SlicePlane::orthogonal(const VolumeGrid& grid, int axis, int sliceNumber) {
    axis = std::clamp(axis, 0, 2);
    const int n = grid.dimensions()[axis];
    const int index = std::clamp(sliceNumber, 0, n - 1);
    SlicePlane plane;
    plane.normal = glm::dvec3(0.0);
    plane.normal[axis] = 1.0;
    // Voxel centres: -extent/2 + (i + 0.5) * spacing (VolumeGrid).
    plane.distance = -0.5 * grid.extent()[axis] + (index + 0.5) * grid.spacing()[axis];
    return plane;
}

std::optional<SlicePlane> SlicePlane::fromPlane(const glm::dvec3& normal, double distance) {
    const double length = glm::length(normal);
    if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(distance)) return std::nullopt;
    return SlicePlane{normal / length, distance / length};
}

std::vector<glm::vec3> SlicePlane::polygon(const glm::dvec3& halfExtent) const {
    std::vector<glm::vec3> triangles;
    ProxyPlaneCutter::appendPlanePolygon(-halfExtent, halfExtent, normal, distance, triangles);
    return triangles;
}

Box3 SlicePlane::polygonBounds(const glm::dvec3& halfExtent) const {
    Box3 box;
    for (const glm::vec3& p : polygon(halfExtent))
        box.extendBy(glm::dvec3(p));
    return box;
}

std::optional<double> SlicePlane::intersect(const Ray& localRay,
                                            const glm::dvec3& halfExtent) const {
    const double rate = glm::dot(normal, localRay.direction);
    if (rate == 0.0 || !std::isfinite(rate)) return std::nullopt;
    const double t = (distance - glm::dot(normal, localRay.origin)) / rate;
    if (!(t >= 0.0) || !std::isfinite(t)) return std::nullopt;
    const glm::dvec3 p = localRay.at(t);
    // A relative tolerance, so a hit on a box face is not lost to rounding.
    for (int a = 0; a < 3; ++a)
        if (std::abs(p[a]) > halfExtent[a] * (1.0 + 1e-9)) return std::nullopt;
    return t;
}

} // namespace volsg
