#pragma once
// `volsg-bench --suite series`: playing a generated time series through the step cache
// (lib/volsg/series) with a memory budget smaller than the series.

#include <volsg/context/Context.h>
#include <volsg/render/FrameContext.h>

namespace volsg::bench {

struct SeriesSuiteSettings {
    int side = 256;  ///< MOVING_SPHERE volumes side^3
    int steps = 100; ///< time steps
    int width = 256, height = 256;
    double budgetMegabytes = 0; ///< cache budget; 0: about a quarter of the series' lists
    double playPeriodMs = 100;  ///< a played frame lasts at least this long (10 steps/s)
    int prefetch = 2;
    bool shearWarp = true, volume = true; ///< which nodes' runs to make
    Backend backend = Backend::OSMesa;
    RenderDebug debug; ///< volsg-bench's debug switches (--no-empty-cells ...)
};

/// Runs the series four times in one sitting, each from an empty cache: ShearWarpVolume with
/// spill files of the extracted arrays only (read-backs sort again: "before") and with the
/// RenderLists spilled too ("after"), then the Volume node (3D textures) uploading each new
/// step directly ("before") and from a pixel buffer staged while the previous step was shown
/// ("after"). For each it prints: the cold-step latency (first view of a step nobody
/// prepared, jumping while paused), per-frame times (median, 95th percentile, max) of a first
/// and a second play-through at the play period and of a third as fast as frames go, the
/// render thread's CPU time per frame and the process's CPU time per phase (the machine may
/// be loaded: CPU time is what the work cost), the longest stall on cached steps (largest
/// frame of the second and third passes minus their median, and whether it stays below one
/// median frame), cache traffic (extractions, spills, disk reads, sorts, waits; staged
/// uploads for the Volume node), and the memory high-water mark of the voxel lists against
/// the budget (plus grids and the process's peak RSS). Returns 0.
int runSeriesSuite(const SeriesSuiteSettings& settings);

} // namespace volsg::bench
