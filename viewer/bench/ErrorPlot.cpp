#include "ErrorPlot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "SvgWriter.h"

namespace volsg::bench {

namespace {

const char* const palette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                               "#9467bd", "#8c564b", "#e377c2", "#17becf"};
constexpr int paletteSize = int(sizeof palette / sizeof palette[0]);

bool plottable(const PlotPoint& p) {
    return std::isfinite(p.ms) && p.ms > 0.0 && std::isfinite(p.rmse) && p.rmse > 0.0;
}

/// A decade range [lo, hi] of exponents covering the values (at least one decade).
struct DecadeRange {
    int lo = 0, hi = 1;
    void cover(double minValue, double maxValue) {
        lo = int(std::floor(std::log10(minValue)));
        hi = int(std::ceil(std::log10(maxValue)));
        if (hi <= lo) hi = lo + 1;
    }
    double fraction(double v) const { return (std::log10(v) - lo) / double(hi - lo); }
};

std::string decadeLabel(int exponent) {
    char buffer[32];
    if (exponent >= -3 && exponent <= 4)
        std::snprintf(buffer, sizeof buffer, "%g", std::pow(10.0, exponent));
    else
        std::snprintf(buffer, sizeof buffer, "1e%d", exponent);
    return buffer;
}

} // namespace

void writeErrorPlot(const std::string& path, const std::string& title,
                    const std::vector<PlotPanel>& panels, const std::string& note) {
    // Series names in order of first appearance: each keeps one colour and marker everywhere.
    std::vector<std::string> names;
    double minMs = std::numeric_limits<double>::infinity(), maxMs = 0.0;
    double minErr = std::numeric_limits<double>::infinity(), maxErr = 0.0;
    for (const PlotPanel& panel : panels)
        for (const PlotSeries& s : panel.series) {
            if (std::find(names.begin(), names.end(), s.name) == names.end())
                names.push_back(s.name);
            for (const PlotPoint& p : s.points) {
                if (!plottable(p)) continue;
                minMs = std::min(minMs, p.ms);
                maxMs = std::max(maxMs, p.ms);
                minErr = std::min(minErr, p.rmse);
                maxErr = std::max(maxErr, p.rmse);
            }
        }
    DecadeRange xRange, yRange;
    if (maxMs > 0.0) {
        xRange.cover(minMs, maxMs);
        yRange.cover(minErr, maxErr);
    }

    const int columns = panels.size() > 1 ? 2 : 1;
    const int rows = int((panels.size() + std::size_t(columns) - 1) / std::size_t(columns));
    const double plotW = 360.0, plotH = 240.0;
    const double left = 70.0, right = 20.0, top = 40.0, bottom = 50.0;
    const double panelW = left + plotW + right, panelH = top + plotH + bottom;
    const double titleH = note.empty() ? 40.0 : 58.0;
    const double legendRowH = 20.0;
    const int legendColumns = 3;
    const std::size_t legendRows = (names.size() + legendColumns - 1) / legendColumns;
    const double legendH = 20.0 + legendRowH * double(legendRows);
    const double width = panelW * columns;
    const double height = titleH + panelH * std::max(rows, 1) + legendH;

    SvgWriter svg(width, height);
    svg.rect(0, 0, width, height, "white");
    svg.text(width / 2, 26, title, 16, "middle", "black", 0.0, true);
    if (!note.empty()) svg.text(width / 2, 46, note, 12, "middle", "#444444");

    for (std::size_t pi = 0; pi < panels.size(); ++pi) {
        const PlotPanel& panel = panels[pi];
        const double ox = panelW * double(pi % std::size_t(columns)) + left;
        const double oy = titleH + panelH * double(pi / std::size_t(columns)) + top;
        auto px = [&](double ms) { return ox + plotW * xRange.fraction(ms); };
        auto py = [&](double err) { return oy + plotH * (1.0 - yRange.fraction(err)); };

        svg.text(ox + plotW / 2, oy - 12, panel.title, 13, "middle", "black", 0.0, true);
        svg.rect(ox, oy, plotW, plotH, "#fafafa", "#444444");
        // Decade grid lines with labels; minor lines at 2..9 for reading values off.
        for (int e = xRange.lo; e <= xRange.hi; ++e) {
            const double x = px(std::pow(10.0, e));
            svg.line(x, oy, x, oy + plotH, "#bbbbbb", 1.0);
            svg.text(x, oy + plotH + 16, decadeLabel(e), 11, "middle");
            for (int m = 2; m <= 9 && e < xRange.hi; ++m) {
                const double xm = px(m * std::pow(10.0, e));
                svg.line(xm, oy, xm, oy + plotH, "#e4e4e4", 0.6);
            }
        }
        for (int e = yRange.lo; e <= yRange.hi; ++e) {
            const double y = py(std::pow(10.0, e));
            svg.line(ox, y, ox + plotW, y, "#bbbbbb", 1.0);
            svg.text(ox - 6, y + 4, decadeLabel(e), 11, "end");
            for (int m = 2; m <= 9 && e < yRange.hi; ++m) {
                const double ym = py(m * std::pow(10.0, e));
                svg.line(ox, ym, ox + plotW, ym, "#e4e4e4", 0.6);
            }
        }
        svg.text(ox + plotW / 2, oy + plotH + 36, "milliseconds per frame (log scale)", 12,
                 "middle");
        svg.text(ox - 52, oy + plotH / 2, "RMSE vs reference (log scale)", 12, "middle", "black",
                 -90.0);

        for (const PlotSeries& s : panel.series) {
            const int index = int(std::find(names.begin(), names.end(), s.name) - names.begin());
            const std::string colour = palette[index % paletteSize];
            std::vector<std::pair<double, double>> line;
            for (const PlotPoint& p : s.points)
                if (plottable(p)) line.push_back({px(p.ms), py(p.rmse)});
            if (line.size() > 1) svg.polyline(line, colour, 1.5);
            for (const PlotPoint& p : s.points) {
                if (!plottable(p)) continue;
                svg.marker(index % 4, px(p.ms), py(p.rmse), 8.0, colour, index < 4);
                if (!p.label.empty())
                    svg.text(px(p.ms) + 6, py(p.rmse) - 5, p.label, 9, "start", colour);
            }
        }
        if (panel.series.empty())
            svg.text(ox + plotW / 2, oy + plotH / 2, "no measurements", 12, "middle", "#888888");
    }

    // One legend for every panel, filled column by column.
    const double ly = titleH + panelH * std::max(rows, 1) + 10.0;
    for (std::size_t i = 0; i < names.size(); ++i) {
        const double x = 30.0 + (width - 60.0) / legendColumns * double(i / legendRows);
        const double y = ly + legendRowH * double(i % legendRows) + 10.0;
        const std::string colour = palette[int(i) % paletteSize];
        svg.line(x - 12, y, x + 12, y, colour, 1.5);
        svg.marker(int(i) % 4, x, y, 8.0, colour, i < 4);
        svg.text(x + 20, y + 4, names[i], 12);
    }
    svg.save(path);
}

} // namespace volsg::bench
