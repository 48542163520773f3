#pragma once
// Cuts view-aligned proxy polygons out of a box, back to front: the geometry of 3D-texture
// slicing (Cabral et al.; the Inventor Volume node of the seed paper).

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace volsg {

/// The slices of one box for one view.
struct ProxySlices {
    std::vector<glm::vec3> vertices;   ///< box-local positions, triangles (3 per triangle)
    std::vector<std::uint32_t> firsts; ///< index of each slice's first vertex, back to front
    double spacing = 0.0;              ///< distance between neighbouring planes, eye units
    int count() const { return int(firsts.size()); }
};

/// Lays out planes perpendicular to the eye's viewing axis and cuts them out of boxes.
///
/// Depth is the distance in front of the eye along its axis (-z in eye coordinates). Over a
/// depth range [near, far] the layout has n = ceil((far - near) / wantedSpacing) planes at
/// depths near + (k + 0.5) * spacing with spacing = (far - near) / n, so each plane stands for
/// a slab of exactly `spacing` and the slabs tile the range (midpoint rule).
struct PlaneLayout {
    double nearDepth = 0.0;
    double spacing = 1.0;
    int count = 0;
    double depth(int k) const { return nearDepth + (k + 0.5) * spacing; }

    /// The layout for a depth range at a wanted spacing (> 0); at least one plane.
    static PlaneLayout over(const glm::dvec2& depthRange, double wantedSpacing);
};

class ProxyPlaneCutter {
public:
    /// The polygons of `layout`'s planes inside the box, back to front, as triangles in
    /// box-local coordinates. `modelView` maps box-local to eye coordinates (eye at the origin
    /// looking down -Z). Planes closer than `minDepth` are left out (the eye's near plane, so
    /// a camera inside the box sees only what is in front of it). Bricks of one volume share
    /// one layout, so their planes line up and no seam appears.
    static ProxySlices cut(const glm::dvec3& boxMin, const glm::dvec3& boxMax,
                           const glm::dmat4& modelView, const PlaneLayout& layout,
                           double minDepth = 0.0);
    /// As cut(), into `out` (cleared first), reusing its memory: no allocation per frame once
    /// warm.
    static void cutInto(const glm::dvec3& boxMin, const glm::dvec3& boxMax,
                        const glm::dmat4& modelView, const PlaneLayout& layout, double minDepth,
                        ProxySlices& out);

    /// The polygon where the plane n . p = d crosses the box, as triangles appended to `out`
    /// (nothing when it misses). Used for the faces that bound a volume's visible part.
    static void appendPlanePolygon(const glm::dvec3& boxMin, const glm::dvec3& boxMax,
                                   const glm::dvec3& normal, double distance,
                                   std::vector<glm::vec3>& out);

    /// The eye depth range [nearest, farthest] (as positive distances along -Z) of the box's
    /// corners.
    static glm::dvec2 depthRange(const glm::dvec3& boxMin, const glm::dvec3& boxMax,
                                 const glm::dmat4& modelView);
};

} // namespace volsg
