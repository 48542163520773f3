#include <volsg/volume/TransferFunction1D.h>

#include <algorithm>
#include <cmath>

#include <volsg/core/Error.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

TransferFunction1D::TransferFunction1D() {
    for (auto& c : channels_)
        c = PiecewiseLinear({{0.0, 0.0}, {1.0, 1.0}});
}

void TransferFunction1D::setChannel(Channel channel, std::vector<PiecewiseLinear::Point> points) {
    if (points.empty()) throw Error("a transfer function channel needs at least one point");
    PiecewiseLinear checked(std::move(points)); // validates before anything is clamped
    std::vector<PiecewiseLinear::Point> clamped = checked.points();
    for (auto& p : clamped)
        p.y = std::clamp(p.y, 0.0, 1.0);
    channels_[channel] = PiecewiseLinear(std::move(clamped));
}

void TransferFunction1D::setDataRange(double lo, double hi) {
    if (!std::isfinite(lo) || !std::isfinite(hi))
        throw Error("transfer function dataRange must be finite");
    dataRange_ = glm::dvec2(lo, hi);
}

glm::dvec2 TransferFunction1D::resolvedDataRange(const VolumeGrid& grid) const {
    if (dataRange_) return *dataRange_;
    const auto [lo, hi] = grid.naturalRange();
    return {lo, hi};
}

glm::dvec4 TransferFunction1D::evaluate(double v) const {
    return {channels_[Red](v), channels_[Green](v), channels_[Blue](v), channels_[Alpha](v)};
}

} // namespace volsg
