#include <volsg/editors/panels/RegionHistogramPanel.h>

#include <algorithm>
#include <vector>

#include <imgui.h>

#include <volsg/editors/Histogram.h>

namespace volsg {

bool drawRegionHistogramPanel(const std::optional<RegionHistogram>& region,
                              RegionHistogramPanelState& state) {
    bool changed = ImGui::SliderInt("region k", &state.regionSize, 1,
                                    RegionHistogramPanelState::kMaxRegionSize, "%d^3");
    state.regionSize = std::clamp(state.regionSize, 1, RegionHistogramPanelState::kMaxRegionSize);
    ImGui::SameLine();
    ImGui::Checkbox("log", &state.logScale);
    if (!region) {
        ImGui::TextWrapped("Click a section view or the volume to place the cursor.");
        return changed;
    }
    const RegionHistogram& r = *region;
    ImGui::Text("voxel (%d, %d, %d)  value %.6g", r.center.x, r.center.y, r.center.z, r.value);
    ImGui::Text("%llu voxels: min %.6g  max %.6g  mean %.6g",
                static_cast<unsigned long long>(r.samples), r.minimum, r.maximum, r.mean);
    const std::vector<float> heights = Histogram{r.counts, r.samples}.heights(state.logScale);
    ImGui::PlotHistogram("##region", heights.data(), int(heights.size()), 0, nullptr, 0.0f, 1.0f,
                         ImVec2(ImGui::GetContentRegionAvail().x, 90.0f));
    ImGui::Text("data %.6g .. %.6g", r.dataRange.x, r.dataRange.y);
    return changed;
}

} // namespace volsg
