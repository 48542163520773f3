#include <volsg/editors/WindowLevel.h>

#include <cmath>

namespace volsg {

WindowLevel WindowLevel::dragged(glm::dvec2 delta, glm::dvec2 viewPixels, double dataSpan) const {
    if (!std::isfinite(delta.x) || !std::isfinite(delta.y) || !std::isfinite(dataSpan) ||
        !(viewPixels.x >= 1.0) || !(viewPixels.y >= 1.0) || !(dataSpan > 0.0))
        return *this;
    const double sign = width < 0.0 ? -1.0 : 1.0;
    const double minimum = dataSpan / 1000.0;
    WindowLevel out = *this;
    out.width = sign * std::max(std::abs(width) + dataSpan * delta.x / viewPixels.x, minimum);
    out.level = level - dataSpan * delta.y / viewPixels.y;
    return out;
}

} // namespace volsg
