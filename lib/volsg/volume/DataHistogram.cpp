#include <volsg/volume/DataHistogram.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <tuple>

#include <volsg/volume/VolumeGrid.h>

namespace volsg {

namespace {

/// Opacities (per reference length, docs/SCENE-FORMAT.md section 4) at the ramp's points, at
/// the 50th and 97th percentiles of the voxels beyond the background: the typical structure
/// (soft tissue, hundreds of voxels deep) faint, the rare densest solid enough to hide what is
/// behind it.
constexpr double typicalOpacity = 0.01, denseOpacity = 0.6;
constexpr double typicalShare = 0.5, denseShare = 0.97;

/// A bin belongs to the background peak while it holds at least this share of the peak's count.
constexpr double peakShoulder = 0.05;

// The value below which `fraction` of the counts in [first, last] (bin indices, either order)
// lie, walking from `first` towards `last`.
double percentileValue(const DataHistogram& h, std::size_t first, std::size_t last,
                       double fraction) {
    const int step = last >= first ? 1 : -1;
    std::uint64_t total = 0;
    for (std::size_t b = first;; b += std::size_t(step)) {
        total += h.counts[b];
        if (b == last) break;
    }
    const double wanted = fraction * double(total);
    std::uint64_t running = 0;
    for (std::size_t b = first;; b += std::size_t(step)) {
        running += h.counts[b];
        if (double(running) >= wanted || b == last) return h.binCentre(b);
    }
}

} // namespace

namespace {

template <class T> void countValues(std::span<const T> values, DataHistogram& h) {
    const std::size_t bins = h.counts.size();
    const double scale = h.hi > h.lo ? double(bins) / (h.hi - h.lo) : 0.0;
    for (const T x : values) {
        const double d = double(x);
        if (!std::isfinite(d)) continue;
        const double position = (d - h.lo) * scale;
        ++h.counts[position <= 0.0 ? 0 : std::min(bins - 1, std::size_t(position))];
        ++h.total;
    }
}

} // namespace

DataHistogram histogramOf(const VolumeGrid& grid, std::size_t maxBins) {
    DataHistogram h;
    std::tie(h.minimum, h.maximum) = grid.minMax();
    h.lo = h.minimum;
    h.hi = h.maximum;
    std::size_t bins = std::max<std::size_t>(1, maxBins);
    // One bin per integer value when they are few: [min - 0.5, max + 0.5] split evenly.
    if (grid.type() != VoxelType::Float && h.maximum - h.minimum + 1.0 <= double(bins)) {
        bins = std::size_t(h.maximum - h.minimum + 1.0);
        h.lo = h.minimum - 0.5;
        h.hi = h.maximum + 0.5;
    }
    if (!(h.hi > h.lo)) bins = 1;
    h.counts.assign(bins, 0);
    switch (grid.type()) {
    case VoxelType::UByte:
        countValues(grid.data<std::uint8_t>(), h);
        break;
    case VoxelType::UShort:
        countValues(grid.data<std::uint16_t>(), h);
        break;
    case VoxelType::Short:
        countValues(grid.data<std::int16_t>(), h);
        break;
    case VoxelType::Float:
        countValues(grid.data<float>(), h);
        break;
    }
    return h;
}

TransferFunction1D transferFunctionFromHistogram(const DataHistogram& h) {
    TransferFunction1D tf;
    const std::size_t bins = h.counts.size();
    if (bins < 2 || h.total == 0 || !(h.maximum > h.minimum)) {
        // One value (or none): nothing to tell apart; show it half transparent.
        tf.setDataRange(h.minimum, h.maximum);
        tf.setChannel(TransferFunction1D::Alpha, {{0.0, 0.3}, {1.0, 0.3}});
        return tf;
    }
    const std::size_t peak =
        std::size_t(std::max_element(h.counts.begin(), h.counts.end()) - h.counts.begin());
    const double shoulder = peakShoulder * double(h.counts[peak]);
    // The peak's extent: outwards while the bins stay high and keep falling.
    std::size_t left = peak, right = peak;
    while (left > 0 && double(h.counts[left - 1]) >= shoulder &&
           h.counts[left - 1] <= h.counts[left])
        --left;
    while (right + 1 < bins && double(h.counts[right + 1]) >= shoulder &&
           h.counts[right + 1] <= h.counts[right])
        ++right;
    std::uint64_t below = 0, above = 0;
    for (std::size_t b = 0; b < left; ++b)
        below += h.counts[b];
    for (std::size_t b = right + 1; b < bins; ++b)
        above += h.counts[b];

    const auto v = [&](double value) {
        return std::clamp((value - h.minimum) / (h.maximum - h.minimum), 0.0, 1.0);
    };
    std::vector<PiecewiseLinear::Point> alpha;
    if (above >= below && right + 1 < bins) {
        // Background dark (air): transparent up to the peak's end, then rising.
        const double start = v(h.lo + double(right + 1) * h.binWidth());
        const double typical =
            std::max(start, v(percentileValue(h, right + 1, bins - 1, typicalShare)));
        const double dense =
            std::max(typical, v(percentileValue(h, right + 1, bins - 1, denseShare)));
        alpha = {{0.0, 0.0},
                 {start, 0.0},
                 {typical, typicalOpacity},
                 {dense, denseOpacity},
                 {1.0, denseOpacity}};
    } else if (left > 0) {
        // Background bright: the same, mirrored.
        const double start = v(h.lo + double(left) * h.binWidth());
        const double typical = std::min(start, v(percentileValue(h, left - 1, 0, typicalShare)));
        const double dense = std::min(typical, v(percentileValue(h, left - 1, 0, denseShare)));
        alpha = {{0.0, denseOpacity},
                 {dense, denseOpacity},
                 {typical, typicalOpacity},
                 {start, 0.0},
                 {1.0, 0.0}};
    } else {
        // The peak spans everything: a plain ramp.
        alpha = {{0.0, 0.0}, {1.0, denseOpacity}};
    }
    tf.setDataRange(h.minimum, h.maximum);
    tf.setChannel(TransferFunction1D::Alpha, alpha);
    tf.setChannel(TransferFunction1D::Red, {{0.0, 0.55}, {0.5, 0.95}, {1.0, 1.0}});
    tf.setChannel(TransferFunction1D::Green, {{0.0, 0.15}, {0.5, 0.6}, {1.0, 0.97}});
    tf.setChannel(TransferFunction1D::Blue, {{0.0, 0.08}, {0.5, 0.4}, {1.0, 0.9}});
    return tf;
}

} // namespace volsg
