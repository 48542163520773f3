#pragma once
// A transfer function: data value -> normalised value v -> colour and opacity.

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/volume/PiecewiseLinear.h>

namespace volsg {

class VolumeGrid;

/// docs/SCENE-FORMAT.md section 3/4: `v = clamp((d - lo) / (hi - lo), 0, 1)` with `dataRange lo hi`
/// (when unset, the data type's natural range of the grid it is applied to); four
/// piecewise-linear channels of (v, output) control points, constant beyond the end points.
/// Outputs are clamped to [0, 1] when set. A channel needs at least one point. The default is
/// the identity `[0 0, 1 1]` on every channel.
class TransferFunction1D {
public:
    enum Channel { Red = 0, Green = 1, Blue = 2, Alpha = 3 };

    TransferFunction1D();

    /// Sorted stably by v (see PiecewiseLinear). Throws Error for no points or non-finite ones.
    void setChannel(Channel channel, std::vector<PiecewiseLinear::Point> points);
    const PiecewiseLinear& channel(Channel channel) const { return channels_[channel]; }

    /// Any finite lo, hi; hi < lo inverts the mapping; hi == lo is a step at lo (see normalise).
    void setDataRange(double lo, double hi);
    void clearDataRange() { dataRange_.reset(); }
    const std::optional<glm::dvec2>& dataRange() const { return dataRange_; }
    /// The explicit range, or the grid's natural range (VolumeGrid::naturalRange()).
    glm::dvec2 resolvedDataRange(const VolumeGrid& grid) const;

    /// `clamp((d - lo) / (hi - lo), 0, 1)`; for hi == lo: 0 below lo, 1 at and above it.
    /// NaN gives 0; +-infinity give the clamped ends.
    static double normalise(double d, double lo, double hi) {
        if (std::isnan(d)) return 0.0; // NaN counts as the range minimum
        if (hi == lo) return d >= lo ? 1.0 : 0.0;
        return std::clamp((d - lo) / (hi - lo), 0.0, 1.0);
    }

    double evaluate(Channel channel, double v) const { return channels_[channel](v); }
    glm::dvec4 evaluate(double v) const; ///< (red, green, blue, alpha) at v

private:
    PiecewiseLinear channels_[4];
    std::optional<glm::dvec2> dataRange_;
};

} // namespace volsg
