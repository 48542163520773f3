#pragma once
// volsg-bench --suite node: the Volume node on the two volumes of issue 4 (Marschner-Lobb
// 256^3 and the chest CT) at 512x512, its error against the reference, and the side-by-side
// with VTK's volume mappers (viewer/vtk/vtk_volume_bench.py renders the exported views).

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "BenchRow.h"
#include "TargetSweep.h"
#include <volsg/context/Context.h>
#include <volsg/render/FrameContext.h>

namespace volsg::bench {

struct NodeSuiteSettings {
    int width = 512, height = 512;
    int frames = 8;      ///< rotating views timed per row
    int errorFrames = 2; ///< of them compared with the reference
    /// The reference's convergence tolerance. 1e-3 rather than its default 1e-4: a 512x512
    /// reference of a 256^3 volume takes minutes per view at 1e-4 (see README.md, Speed).
    double tolerance = 1e-4;
    std::vector<double> planesPerVoxel{0.25}; ///< extra still settings besides the automatic
    glm::vec3 background{0.0f};
    Backend backend = Backend::OSMesa;
    RenderDebug debug;              ///< volsg-bench's debug switches (--no-empty-cells ...)
    std::string scenesDir;          ///< holds node-*.iv
    std::vector<std::string> cases; ///< case names to run; empty = all
    std::vector<std::string> kinds; ///< "dvr", "dvr-lit", "mip"; empty = all
    bool planesOnly = false;        ///< only the planesPerVoxel rows (no automatic ones)
    int samplesPerPlane = 1;        ///< the Volume node's samplesPerPlane for every row
    bool mipPeaks = true;           ///< the Volume node's mipPeaks for the MIP rows
    std::string referenceDir;       ///< reference images are kept there and reused (PFM)
    std::string keepDir;            ///< the Volume node's error frames are written there (PFM)
    std::string compareDir;         ///< VTK's results (vtk-results.tsv and PFM frames) to compare
    /// When set, the Volume node's rows are read from this CSV of an earlier run (--csv)
    /// instead of being measured again (with compareDir: compare without timing again).
    std::string rowsCsv;
};

/// Rows (and their settings) per case:
/// - DVR without lighting: automatic planes (2 per voxel along the view) still, a quarter of
///   them interactive (also pre-integrated), and `planesPerVoxel` still (numPlanes = p * box
///   diagonal / L0, so at least p planes per voxel in every view);
/// - DVR with lighting: the same but pre-integrated (compared with the unshaded reference
///   only for sanity: the reference does not shade);
/// - MIP: still, interactive and `planesPerVoxel`.
/// Each row: median wall ms/frame over the rotating views, median process CPU ms/frame (all
/// threads, llvmpipe's included: less sensitive to other load than wall time), the node's own
/// per-frame CPU time (SlicingStats::cpuMilliseconds: state, layout, cutting, tables), bricks
/// drawn and skipped, texture memory, and RMSE/PSNR/max against the reference on
/// `errorFrames` of the views. With compareDir, VTK's rows and the equal-error table follow.
std::vector<BenchRow> runNodeSuite(const NodeSuiteSettings& settings);

/// The error-target sweep (TargetSweep.h) on the suite's cases, DVR and MIP (`kinds`: "dvr",
/// "mip"), with the reference images of referenceOf (kept in referenceDir).
std::vector<BenchRow> runNodeSweep(const NodeSuiteSettings& settings, const SweepSettings& sweep,
                                   std::vector<SweepLine>& lines,
                                   std::vector<ValidationLine>& validation);

/// Writes what viewer/vtk/vtk_volume_bench.py needs to render the same frames into `dir`:
/// views.json (image size, background, and per case the volume's raw file, dimensions,
/// spacing, transfer function in data units, L0, lighting, the orbit cameras and which of them
/// are compared) and one <case>.raw per case.
void exportNodeSuiteViews(const NodeSuiteSettings& settings, const std::string& dir);

} // namespace volsg::bench
