#include <volsg/volume/PiecewiseLinear.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <volsg/core/Error.h>

namespace volsg {

PiecewiseLinear::PiecewiseLinear(std::vector<Point> points) : points_(std::move(points)) {
    for (const Point& p : points_)
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            throw Error("control point (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                        ") is not finite");
    std::stable_sort(points_.begin(), points_.end(),
                     [](const Point& a, const Point& b) { return a.x < b.x; });
}

double PiecewiseLinear::operator()(double x) const {
    if (points_.empty()) return 0.0;
    // The first point strictly right of x: its left neighbour is the last point with p.x <= x,
    // so duplicates resolve to the last one (right-continuous step).
    const auto right = std::upper_bound(points_.begin(), points_.end(), x,
                                        [](double value, const Point& p) { return value < p.x; });
    if (right == points_.begin()) return points_.front().y;
    if (right == points_.end()) return points_.back().y;
    const Point& a = *(right - 1);
    const Point& b = *right; // b.x > x >= a.x, so b.x > a.x
    return a.y + (b.y - a.y) * ((x - a.x) / (b.x - a.x));
}

PiecewiseLinear::Line PiecewiseLinear::lineAt(double x) const {
    if (points_.empty()) return {};
    const auto right = std::upper_bound(points_.begin(), points_.end(), x,
                                        [](double value, const Point& p) { return value < p.x; });
    if (right == points_.begin()) return {points_.front().y, 0.0};
    if (right == points_.end()) return {points_.back().y, 0.0};
    const Point& a = *(right - 1);
    const Point& b = *right;
    const double slope = (b.y - a.y) / (b.x - a.x);
    return {a.y - slope * a.x, slope};
}

double PiecewiseLinear::maxOver(double x0, double x1) const {
    if (x1 < x0) std::swap(x0, x1);
    double m = std::max((*this)(x0), (*this)(x1));
    for (const Point& p : points_)
        if (p.x > x0 && p.x <= x1) m = std::max(m, p.y);
    return m;
}

double PiecewiseLinear::minOver(double x0, double x1) const {
    if (x1 < x0) std::swap(x0, x1);
    double m = std::min((*this)(x0), (*this)(x1));
    for (const Point& p : points_)
        if (p.x > x0 && p.x <= x1) m = std::min(m, p.y);
    return m;
}

} // namespace volsg
