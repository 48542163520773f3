#pragma once
// The error-target sweep of volsg-bench (--sweep in --suite volumes and --suite node): per
// case, a grid of fixed Volume settings timed and measured against the reference, the fastest
// of them that meets each target, and the node's default at that target (chosen from the
// error model), with the model's predicted error next to the measured one.

#include <string>
#include <vector>

#include "BenchRow.h"
#include "ReferenceViews.h"
#include <volsg/nodes/Volume.h>
#include <volsg/render/Renderer.h>

namespace volsg::bench {

/// One case: a scene whose Volume node the sweep sets, its views and their reference images.
struct SweepCase {
    std::string name;
    ref_ptr<Node> root;
    Volume* volume = nullptr;
    OrbitViews views;
    RenderOptions options;        ///< size, background, debug switches
    std::vector<Image> reference; ///< of views.errorIndices
    double diagonalL0 = 0.0;      ///< the volume box's diagonal in L0 (fixed plane counts)
};

struct SweepSettings {
    std::vector<double> targets{0.5, 0.25, 2.0}; ///< in 1/255; the first is the default's
    /// A coarser grid of fixed settings: samples per plane 4 and 16, at most 2 samples per L0.
    bool quick = false;
    /// Only the old fixed rule (errorTarget 0: 2 samples per voxel, one per plane) and the
    /// defaults at the targets, no grid: the before and after of the defaults.
    bool beforeAfter = false;
};

/// One compared frame of a default: its view, what the node drew there (chosenSettingText),
/// the predicted and the measured RMSE (1/255).
struct SweepFrame {
    int view = 0;
    std::string setting;
    double predicted = 0.0, measured = 0.0;
};

/// A line of the summary: one case at one target.
struct SweepLine {
    std::string scene;
    double target = 0.0;        ///< 1/255
    std::string defaultSetting; ///< what the node chose (view 0)
    double defaultMs = 0.0, defaultRmse = 0.0, defaultPredicted = 0.0; ///< RMSE in 1/255
    /// Of the compared views, how many of the default's frames are within the target and
    /// within twice it (the bar: 95% and all).
    int viewsCompared = 0, viewsWithin = 0, viewsWithinTwice = 0;
    std::vector<SweepFrame> frames; ///< the default's compared frames
    std::string bestSetting;        ///< "" when no fixed setting met the target
    double bestMs = 0.0, bestRmse = 0.0;
};

/// A line of the model's validation: one fixed setting, predicted and measured RMSE.
struct ValidationLine {
    std::string scene, setting;
    double predicted = 0.0, measured = 0.0; ///< 1/255
};

/// Runs the grid and the defaults on one case; prints each row as it is measured.
std::vector<BenchRow> runTargetSweep(SweepCase& c, const SweepSettings& st,
                                     std::vector<SweepLine>& lines,
                                     std::vector<ValidationLine>& validation);

/// The summary table (markdown) and the validation table, on stdout.
void printSweepTables(const std::vector<SweepLine>& lines,
                      const std::vector<ValidationLine>& validation);

/// A one-line description of what the node last drew (SlicingStats): samples per plane, plane
/// spacing, pre-integration or peaks, and the predicted error against the target.
std::string chosenSettingText(const Volume& volume);

} // namespace volsg::bench
