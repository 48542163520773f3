#include <volsg/editors/ControlCurve.h>

#include <algorithm>
#include <cmath>

namespace volsg {

ControlCurve::ControlCurve(std::vector<glm::vec2> points, float yMin, float yMax)
    : yMin_(yMin), yMax_(yMax) {
    setPoints(std::move(points));
}

glm::vec2 ControlCurve::clampPoint(glm::vec2 p) const {
    return {std::clamp(p.x, 0.0f, 1.0f), std::clamp(p.y, yMin_, yMax_)};
}

void ControlCurve::setPoints(std::vector<glm::vec2> points) {
    for (glm::vec2& p : points)
        p = clampPoint(p);
    std::stable_sort(points.begin(), points.end(),
                     [](const glm::vec2& a, const glm::vec2& b) { return a.x < b.x; });
    points_ = std::move(points);
}

float ControlCurve::valueAt(float x) const {
    if (points_.empty()) return yMin_;
    if (x <= points_.front().x) return points_.front().y;
    if (x >= points_.back().x) return points_.back().y;
    const auto hi = std::upper_bound(points_.begin(), points_.end(), x,
                                     [](float v, const glm::vec2& p) { return v < p.x; });
    const glm::vec2 b = *hi, a = *(hi - 1);
    if (b.x <= a.x) return b.y;
    return a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
}

int ControlCurve::add(glm::vec2 p) {
    p = clampPoint(p);
    for (std::size_t i = 0; i < points_.size(); ++i)
        if (std::abs(points_[i].x - p.x) < minimumGap) {
            points_[i].y = p.y;
            return int(i);
        }
    const auto at = std::upper_bound(points_.begin(), points_.end(), p.x,
                                     [](float v, const glm::vec2& q) { return v < q.x; });
    const auto index = at - points_.begin(); // before the insert, which may reallocate
    points_.insert(at, p);
    return int(index);
}

int ControlCurve::move(int i, glm::vec2 p) {
    if (i < 0 || std::size_t(i) >= points_.size()) return i;
    p = clampPoint(p);
    const std::size_t k = std::size_t(i);
    if (k > 0) p.x = std::max(p.x, points_[k - 1].x + minimumGap);
    if (k + 1 < points_.size()) p.x = std::min(p.x, points_[k + 1].x - minimumGap);
    points_[k] = p;
    return i;
}

bool ControlCurve::remove(int i) {
    if (points_.size() <= 1 || i < 0 || std::size_t(i) >= points_.size()) return false;
    points_.erase(points_.begin() + i);
    return true;
}

int ControlCurve::nearest(glm::vec2 p, float radius, glm::vec2 scale) const {
    int best = -1;
    float bestDistance = radius;
    for (std::size_t i = 0; i < points_.size(); ++i) {
        const float d = glm::length((points_[i] - p) * scale);
        if (d <= bestDistance) {
            bestDistance = d;
            best = int(i);
        }
    }
    return best;
}

void ControlCurve::drawLine(glm::vec2 a, glm::vec2 b) {
    a = clampPoint(a);
    b = clampPoint(b);
    if (a.x > b.x) std::swap(a, b);
    std::erase_if(points_, [&](const glm::vec2& p) {
        return p.x >= a.x - minimumGap && p.x <= b.x + minimumGap;
    });
    add(a);
    if (b.x - a.x >= minimumGap) add(b);
}

std::vector<glm::vec2> ControlCurve::simplify(const std::vector<glm::vec2>& line, float tolerance) {
    if (line.size() <= 2) return line;
    std::vector<char> keep(line.size(), 0);
    keep.front() = keep.back() = 1;
    // Iterative Douglas-Peucker: split a span at its worst point until every span is close.
    std::vector<std::pair<std::size_t, std::size_t>> spans{{0, line.size() - 1}};
    while (!spans.empty()) {
        const auto [first, last] = spans.back();
        spans.pop_back();
        const glm::vec2 a = line[first], b = line[last];
        float worst = -1.0f;
        std::size_t worstAt = first;
        for (std::size_t i = first + 1; i < last; ++i) {
            const float t = b.x > a.x ? (line[i].x - a.x) / (b.x - a.x) : 0.0f;
            const float d = std::abs(line[i].y - (a.y + (b.y - a.y) * t));
            if (d > worst) {
                worst = d;
                worstAt = i;
            }
        }
        if (worst > tolerance) {
            keep[worstAt] = 1;
            spans.push_back({first, worstAt});
            spans.push_back({worstAt, last});
        }
    }
    std::vector<glm::vec2> out;
    for (std::size_t i = 0; i < line.size(); ++i)
        if (keep[i]) out.push_back(line[i]);
    return out;
}

void ControlCurve::drawFreehand(const std::vector<glm::vec2>& stroke, float tolerance) {
    if (stroke.empty()) return;
    // As a function of x: bucket the stroke at minimumGap resolution, later samples winning.
    std::vector<glm::vec2> samples;
    samples.reserve(stroke.size());
    for (const glm::vec2& raw : stroke)
        samples.push_back(clampPoint(raw));
    std::vector<glm::vec2> function;
    {
        std::vector<std::size_t> order(samples.size());
        for (std::size_t i = 0; i < order.size(); ++i)
            order[i] = i;
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t a, std::size_t b) { return samples[a].x < samples[b].x; });
        for (std::size_t k = 0; k < order.size();) {
            // A run of samples at the same x: the one drawn last (highest index) wins.
            std::size_t end = k, last = order[k];
            while (end < order.size() && samples[order[end]].x - samples[order[k]].x < minimumGap) {
                last = std::max(last, order[end]);
                ++end;
            }
            function.push_back({samples[order[k]].x, samples[last].y});
            k = end;
        }
    }
    const std::vector<glm::vec2> simplified = simplify(function, tolerance);
    const float lo = function.front().x, hi = function.back().x;
    std::erase_if(points_, [&](const glm::vec2& p) {
        return p.x >= lo - minimumGap && p.x <= hi + minimumGap;
    });
    for (const glm::vec2& p : simplified)
        add(p);
}

} // namespace volsg
