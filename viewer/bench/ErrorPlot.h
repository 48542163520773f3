#pragma once
// The speed-versus-error chart of the benchmark: RMSE against milliseconds per frame, both on
// log scales, one panel per scene and one line per rendering path.

#include <string>
#include <vector>

namespace volsg::bench {

struct PlotPoint {
    double ms = 0.0;   ///< milliseconds per frame
    double rmse = 0.0; ///< error against the reference; points <= 0 or not finite are left out
    std::string label; ///< short text beside the point ("2": planes per voxel)
};

/// One path at several settings, drawn as markers joined in the given order.
struct PlotSeries {
    std::string name;
    std::vector<PlotPoint> points;
};

struct PlotPanel {
    std::string title;
    std::vector<PlotSeries> series;
};

/// Writes the chart as SVG: panels side by side (two per row) on shared log axes so they
/// compare at a glance, decade grid lines and labels, and one legend in which each series name
/// has the same colour and marker in every panel. Throws Error when the file cannot be written.
/// `note` is a smaller line under the title (what the point labels mean, ...).
void writeErrorPlot(const std::string& path, const std::string& title,
                    const std::vector<PlotPanel>& panels, const std::string& note = {});

} // namespace volsg::bench
