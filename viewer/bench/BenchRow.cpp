#include "BenchRow.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <unistd.h>

#include "ErrorPlot.h"
#include "ImageError.h"
#include <volsg/core/Error.h>
#include <volsg/io/AtomicFile.h>

namespace volsg::bench {

void BenchRow::setError(const std::vector<Image>& images, const std::vector<Image>& reference) {
    ImageError error;
    for (std::size_t i = 0; i < images.size(); ++i)
        error.add(images[i], reference[i]);
    hasError = !images.empty();
    rmse = error.rmse();
    psnr = error.psnr();
    maxAbs = error.maxAbs();
    errorFrames = int(images.size());
}

namespace {

std::string memoryText(const BenchRow& row) {
    if (row.memoryKind.empty()) return "-";
    char buffer[48];
    const double bytes = double(row.memoryBytes);
    if (bytes >= 1e6)
        std::snprintf(buffer, sizeof buffer, "%.2f MB", bytes / 1e6);
    else if (bytes >= 1e3)
        std::snprintf(buffer, sizeof buffer, "%.1f kB", bytes / 1e3);
    else
        std::snprintf(buffer, sizeof buffer, "%.0f B", bytes);
    return std::string(buffer) + " " + row.memoryKind;
}

std::string csvCell(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

std::string number(double v, const char* format = "%.6g") {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, format, v);
    return buffer;
}

} // namespace

void printHeader() {
    std::printf("%-26s %-10s %-44s %10s %10s %9s %10s  %s\n", "scene", "path", "setting",
                "ms/frame", "RMSE", "PSNR dB", "max abs", "memory");
    std::fflush(stdout);
}

void printRow(const BenchRow& row) {
    if (!row.available) {
        std::printf("%-26s %-10s %-44s %10s %10s %9s %10s  %s  (%s)\n", row.scene.c_str(),
                    row.path.c_str(), row.setting.c_str(), "n/a", "n/a", "n/a", "n/a", "-",
                    row.note.c_str());
    } else if (row.hasError) {
        std::printf("%-26s %-10s %-44s %10.2f %10.3e %9.2f %10.3e  %s%s%s\n", row.scene.c_str(),
                    row.path.c_str(), row.setting.c_str(), row.ms, row.rmse, row.psnr, row.maxAbs,
                    memoryText(row).c_str(), row.note.empty() ? "" : "  ", row.note.c_str());
    } else {
        std::printf("%-26s %-10s %-44s %10.2f %10s %9s %10s  %s%s%s\n", row.scene.c_str(),
                    row.path.c_str(), row.setting.c_str(), row.ms, "-", "-", "-",
                    memoryText(row).c_str(), row.note.empty() ? "" : "  ", row.note.c_str());
    }
    std::fflush(stdout);
}

static void writeCsvRows(std::ostream& out, const std::vector<BenchRow>& rows) {
    out << "scene,path,setting,available,ms_per_frame,frames,rmse,psnr_db,max_abs_error,"
           "error_frames,memory_bytes,memory_kind,note\n";
    for (const BenchRow& r : rows) {
        out << csvCell(r.scene) << ',' << csvCell(r.path) << ',' << csvCell(r.setting) << ','
            << (r.available ? "yes" : "no") << ',';
        if (r.available)
            out << number(r.ms) << ',' << r.frames;
        else
            out << ',';
        out << ',';
        if (r.available && r.hasError)
            out << number(r.rmse) << ',' << number(r.psnr) << ',' << number(r.maxAbs) << ','
                << r.errorFrames;
        else
            out << ",,,";
        out << ',';
        if (!r.memoryKind.empty()) out << r.memoryBytes;
        out << ',' << csvCell(r.memoryKind) << ',' << csvCell(r.note) << '\n';
    }
}

void writeCsv(const std::string& path, const std::vector<BenchRow>& rows) {
    // Through a temporary file: a failed run never destroys the previous CSV.
    writeFileAtomically(path, [&rows](std::ostream& out) { writeCsvRows(out, rows); });
}

void writeRowsPlot(const std::string& path, const std::string& title,
                   const std::vector<BenchRow>& rows, const std::string& note) {
    std::vector<PlotPanel> panels;
    for (const BenchRow& r : rows) {
        if (!r.available || !r.hasError || r.series.empty()) continue;
        PlotPanel* panel = nullptr;
        for (auto& p : panels)
            if (p.title == r.scene) panel = &p;
        if (!panel) panel = &panels.emplace_back(PlotPanel{r.scene, {}});
        PlotSeries* series = nullptr;
        for (auto& s : panel->series)
            if (s.name == r.series) series = &s;
        if (!series) series = &panel->series.emplace_back(PlotSeries{r.series, {}});
        series->points.push_back({r.ms, r.rmse, r.pointLabel});
    }
    writeErrorPlot(path, title, panels, note);
}

std::size_t residentBytes() {
    std::ifstream statm("/proc/self/statm");
    std::size_t size = 0, resident = 0;
    if (!(statm >> size >> resident)) return 0;
    return resident * std::size_t(sysconf(_SC_PAGESIZE));
}

} // namespace volsg::bench
