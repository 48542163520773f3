#pragma once
// One line of a speed-versus-error table: a path at a setting on a scene, its time, its error
// against the reference and its memory; printed, written as CSV and plotted.

#include <cstddef>
#include <string>
#include <vector>

#include <volsg/image/Image.h>

namespace volsg::bench {

struct BenchRow {
    std::string scene;
    std::string path;      ///< "reference", "slicing", "gl" (a scene's own renderer)
    std::string setting;   ///< human-readable: "2 planes/voxel, still, pre-integrated"
    bool available = true; ///< false: the path does not support this setting ("n/a")
    double ms = 0.0;       ///< median milliseconds per frame over the rotating views
    int frames = 0;        ///< frames timed
    bool hasError = false; ///< false for the reference that the others are measured against
    double rmse = 0.0, psnr = 0.0, maxAbs = 0.0;
    int errorFrames = 0;         ///< views compared with the reference
    std::size_t memoryBytes = 0; ///< see memoryKind
    std::string memoryKind;      ///< "texture" (GL 3D textures the renderer reports) or "rss"
    std::string note;            ///< why n/a, convergence of the reference, ...
    std::string series;          ///< plot line this row belongs to ("" = not plotted)
    std::string pointLabel;      ///< text beside its plot point

    /// The error of `images` against the reference images of the same views (pairwise):
    /// rmse, psnr, maxAbs, errorFrames; hasError when there is at least one pair.
    void setError(const std::vector<Image>& images, const std::vector<Image>& reference);
};

/// The table's heading and rows as fixed-width text on stdout.
void printHeader();
void printRow(const BenchRow& row);

/// CSV with a header line: scene,path,setting,available,ms_per_frame,frames,rmse,psnr_db,
/// max_abs_error,error_frames,memory_bytes,memory_kind,note. Empty cells where a value does
/// not apply. Throws Error when the file cannot be written.
void writeCsv(const std::string& path, const std::vector<BenchRow>& rows);

/// The SVG chart of RMSE against ms/frame: one panel per scene, one line per series.
void writeRowsPlot(const std::string& path, const std::string& title,
                   const std::vector<BenchRow>& rows, const std::string& note = {});

/// Resident memory of this process in bytes (from /proc/self/statm; 0 where unavailable).
std::size_t residentBytes();

} // namespace volsg::bench
