#pragma once
// A piecewise-linear function of one variable given by control points: the shape of a transfer
// function channel and of a plane-opacity curve.

#include <vector>

namespace volsg {

/// f(x) through control points (x, y), linear between neighbours and constant beyond the end
/// points. Points are sorted stably by x, so duplicate x values keep their given order and make
/// a step: at the shared x (and to its right) f takes the LAST duplicate's y; to its left
/// f approaches the first one's. Evaluated exactly in double.
class PiecewiseLinear {
public:
    struct Point {
        double x = 0.0;
        double y = 0.0;
        bool operator==(const Point&) const = default;
    };

    PiecewiseLinear() = default; ///< no points: f(x) = 0
    /// Throws Error when a coordinate is not finite.
    explicit PiecewiseLinear(std::vector<Point> points);

    const std::vector<Point>& points() const { return points_; }
    bool empty() const { return points_.empty(); }

    double operator()(double x) const;

    /// The straight line f follows around x (the segment operator() uses at x; a constant
    /// beyond the ends). Lets a caller that cuts its domain at the control points evaluate a
    /// piece's end points with the piece's own line, not with the neighbour's across a step.
    struct Line {
        double intercept = 0.0;
        double slope = 0.0;
        double operator()(double x) const { return intercept + slope * x; }
    };
    Line lineAt(double x) const;
    /// The largest / smallest f over [x0, x1] (either order): the end values and every control
    /// point inside (a step at x1 counts its left limit), so it bounds f on the interval.
    double maxOver(double x0, double x1) const;
    double minOver(double x0, double x1) const;

private:
    std::vector<Point> points_;
};

} // namespace volsg
