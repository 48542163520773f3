#pragma once
// Triangulation of planar polygons with holes, overlaps and self-intersections: glyph outlines
// (Text3, AsciiText) and the trimmed cells of NURBS surfaces. It is GLU's polygon tessellator
// (gluNewTess; Debian's libglu1-mesa), the field's standard one: pure computation, no GL
// context and no GL call.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace volsg {

/// Which points are inside, by the winding number of the contours around them (GLU's rules;
/// counter-clockwise contours count +1, clockwise ones -1).
enum class WindingRule { Odd, NonZero, Positive, Negative, AbsGeqTwo };

/// Triangles over `points`: the input points in order (contour after contour), then the
/// points where edges cross (made by the tessellator).
struct Triangulation {
    std::vector<glm::dvec2> points;
    std::vector<std::uint32_t> triangles; ///< 3 per triangle, counter-clockwise
};

/// Triangulates the region inside `contours` (each closed: its last point joins its first) by
/// `rule`. Zero-area triangles are left out. Returns false (and an empty result) if a point is
/// not finite or the tessellator reports an error. Throws Error past `maxPoints` input points.
bool triangulatePolygons(std::span<const std::vector<glm::dvec2>> contours, WindingRule rule,
                         Triangulation& out, std::size_t maxPoints = std::size_t(1) << 22);

/// Twice the signed area of a closed polygon (positive when counter-clockwise).
double twiceSignedArea(std::span<const glm::dvec2> polygon);

} // namespace volsg
