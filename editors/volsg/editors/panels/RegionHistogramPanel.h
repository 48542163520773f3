#pragma once
// The Dear ImGui panel of the cursor readout: the voxel under the viewer's cursor, its data
// value, and the histogram of the k^3 region around it (RegionHistogram).

#include <optional>

#include <volsg/editors/RegionHistogram.h>

namespace volsg {

struct RegionHistogramPanelState {
    int regionSize = 5; ///< k, edited by the panel's slider (1 .. kMaxRegionSize)
    bool logScale = false;
    static constexpr int kMaxRegionSize = 33;
};

/// Draws the panel's contents into the current window; returns whether k changed (the caller
/// recomputes the histogram). `region` empty: no volume under the cursor yet.
bool drawRegionHistogramPanel(const std::optional<RegionHistogram>& region,
                              RegionHistogramPanelState& state);

} // namespace volsg
