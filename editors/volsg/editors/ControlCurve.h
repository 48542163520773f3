#pragma once
// A piecewise linear curve of control points (x in [0, 1], y in [yMin, yMax]), sorted by x, as
// transfer-function channels and plane-opacity curves are; and the edits an editor makes to it.

#include <vector>

#include <glm/glm.hpp>

namespace volsg {

class ControlCurve {
public:
    /// Points closer than this in x are the same x (a new point there replaces the old one).
    static constexpr float minimumGap = 1e-4f;

    ControlCurve(std::vector<glm::vec2> points = {}, float yMin = 0.0f, float yMax = 1.0f);

    const std::vector<glm::vec2>& points() const { return points_; }
    float yMin() const { return yMin_; }
    float yMax() const { return yMax_; }
    /// The curve at x: linear between points, constant beyond the end points (docs/SCENE-FORMAT.md
    /// 3).
    float valueAt(float x) const;

    /// Adds a point (clamped into the range); a point within minimumGap in x is replaced.
    /// Returns its index.
    int add(glm::vec2 p);
    /// Moves point i, clamped into the range and kept strictly between its neighbours in x, so
    /// the order never changes under a drag. Returns i.
    int move(int i, glm::vec2 p);
    /// Removes point i; the last remaining point is kept (a channel needs one). Returns whether
    /// a point was removed.
    bool remove(int i);
    /// The point nearest `p` within `radius`, distances measured after scaling x and y by
    /// `scale` (pixels per unit, so a hit radius is in pixels); -1 when none is that close.
    int nearest(glm::vec2 p, float radius, glm::vec2 scale = glm::vec2(1.0f)) const;

    /// A straight segment from a to b: points strictly between their x are replaced by the two
    /// end points.
    void drawLine(glm::vec2 a, glm::vec2 b);
    /// A freehand stroke (points in drawing order, any direction) becomes a function of x (the
    /// last stroke value drawn at an x wins), simplified within `tolerance` in y, and replaces
    /// the curve's points over the stroke's x span.
    void drawFreehand(const std::vector<glm::vec2>& stroke, float tolerance);
    /// Replaces every point.
    void setPoints(std::vector<glm::vec2> points);

    /// Douglas-Peucker on a function polyline (sorted by x) with the vertical distance: the
    /// result is a subset (end points kept) whose linear interpolation is within `tolerance`
    /// of every input point.
    static std::vector<glm::vec2> simplify(const std::vector<glm::vec2>& polyline, float tolerance);

private:
    glm::vec2 clampPoint(glm::vec2 p) const;
    std::vector<glm::vec2> points_;
    float yMin_, yMax_;
};

} // namespace volsg
