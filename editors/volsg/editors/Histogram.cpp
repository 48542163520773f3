#include <volsg/editors/Histogram.h>

#include <algorithm>
#include <cmath>

#include <volsg/volume/VolumeGrid.h>

namespace volsg {

Histogram Histogram::of(const VolumeGrid& grid, glm::dvec2 range, int bins,
                        std::uint64_t maxSamples) {
    Histogram h;
    h.counts.assign(std::size_t(std::max(bins, 1)), 0);
    const std::size_t n = grid.voxelCount();
    if (n == 0) return h;
    const std::size_t stride =
        std::max<std::size_t>(1, (n + std::size_t(maxSamples) - 1) / std::size_t(maxSamples));
    const double width = range.y - range.x;
    const double scale = width != 0.0 ? 1.0 / width : 0.0;
    const double last = double(h.counts.size() - 1);
    for (std::size_t i = 0; i < n; i += stride) {
        const double d = grid.value(i);
        if (!std::isfinite(d)) continue;
        const double v =
            width != 0.0 ? std::clamp((d - range.x) * scale, 0.0, 1.0) : (d >= range.x ? 1.0 : 0.0);
        ++h.counts[std::size_t(std::lround(v * last))];
        ++h.samples;
    }
    return h;
}

std::vector<float> Histogram::heights(bool logScale) const {
    std::vector<float> out(counts.size(), 0.0f);
    const std::uint64_t largest =
        counts.empty() ? 0 : *std::max_element(counts.begin(), counts.end());
    if (largest == 0) return out;
    const double top = logScale ? std::log1p(double(largest)) : double(largest);
    for (std::size_t i = 0; i < counts.size(); ++i)
        out[i] = float((logScale ? std::log1p(double(counts[i])) : double(counts[i])) / top);
    return out;
}

} // namespace volsg
