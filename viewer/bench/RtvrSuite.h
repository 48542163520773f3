#pragma once
// The RTVR paper's table 1 as a volsg-bench suite (`--suite rtvr`): its three scenes rebuilt
// for the ShearWarpVolume node (viewer/bench/scenes/rtvr-*.iv), each rendered in the paper's
// four modes, with the paper's times (400 MHz Pentium II, Java 1.3) beside ours.

#include <string>
#include <vector>

#include "BenchRow.h"
#include <volsg/context/Context.h>
#include <volsg/render/FrameContext.h>

namespace volsg::bench {

/// One scene of table 1: its file and the paper's figures.
struct RtvrScene {
    std::string file;       ///< under the scenes folder
    std::string paperName;  ///< the paper's data set
    int paperVoxelsK = 0;   ///< the paper's scene voxels, thousands
    double paperMs[4] = {}; ///< MIP, DVR, DVR/mono, mixed MIP/DVR (ms per 512^2 frame)
    /// Object names (DEF) drawn by MIP in the mixed mode; the others stay DVR.
    std::vector<std::string> mixedMipObjects;
};

/// The paper's rows: hand & vessels (380k), head & vessels (640k), attractor & basin (1M).
std::vector<RtvrScene> rtvrScenes();

/// The rendering modes of table 1. The scene files are written in Dvr.
/// MipGeneral: MIP through the general two-buffer path (ShearWarpVolume.valueSortedMip FALSE),
/// beside the value-sorted one.
enum class RtvrMode { Mip, MipGeneral, Dvr, DvrMono, MixedMipDvr };
const char* rtvrModeName(RtvrMode mode);

struct RtvrSuiteSettings {
    int width = 512, height = 512;
    int frames = 20; ///< rotating views timed per row, after one warm-up frame
    Backend backend = Backend::OSMesa;
    std::string keepDir; ///< when set, frame 0 of every row is written there as PNG
    /// Folder of the rtvr-*.iv files; empty: VOLSG_RTVR_SCENE_DIR (compiled in), or the
    /// environment variable of that name when set.
    std::string sceneDir;
    RenderDebug debug; ///< volsg-bench's debug switches (--no-empty-cells ...)
};

/// Renders every scene in every mode and prints one row per scene and mode: the scene's
/// voxels (extracted by the scene's VolumeObjects), the median and minimum ms/frame over the
/// rotating orthographic views (after the warm-up frame and after the optimizer has
/// finished), the median process CPU ms/frame (all threads), the paper's ms and the speed-up
/// (paper / our median). Modes are made by changing fields of the
/// scene's DEF'd nodes (RTVR_VOLUME, the VolumeObjects and their <NAME>_TF transfer
/// functions):
/// - MIP: every object MIP with its transfer function (renderMode TF), MIP between objects;
///   each MIP object's `opacity` (its alpha multiplier in MIP) is 1 / the largest alpha of its
///   transfer function, so its brightest value shows at full colour, not at a DVR opacity;
/// - DVR: the file as written;
/// - DVR mono: DVR with every transfer function's colour replaced by its luminance
///   (0.299 R + 0.587 G + 0.114 B at every control point of any channel);
/// - mixed MIP/DVR: the scene's mixedMipObjects by MIP (TF, opacity as in MIP), the others DVR
///   as written, DVR
///   between objects (two-level volume rendering).
/// Returns the rows (path "shearwarp", setting = mode, note = the paper's ms).
std::vector<BenchRow> runRtvrSuite(const RtvrSuiteSettings& settings);

} // namespace volsg::bench
