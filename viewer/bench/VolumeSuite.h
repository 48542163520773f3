#pragma once
// The built-in volume suite of volsg-bench: generated volume scenes, each rendered by every
// volume path at each of its settings, with time, error against the reference, and memory.

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "BenchRow.h"
#include <volsg/context/Context.h>
#include <volsg/render/FrameContext.h>

namespace volsg::bench {

/// One generated scene: Inventor text with one Volume node named SUITE_VOLUME, whose fields
/// the suite sets per row. Every volume box spans about [-1, 1]^3 and the camera sees it whole
/// from every orbit angle.
struct SuiteScene {
    std::string name;
    std::string text;
};

/// The suite's scenes for volumes of `side`^3 voxels: Marschner-Lobb with a smooth transfer
/// function, Marschner-Lobb with a spiky one (an alpha peak 0.05 wide in v), the 16-bit ramp
/// seen through a narrow data window, and the labelled volume with one transfer function per
/// tag. Opacities are given for side 64 and converted (1 - (1 - A)^(64 / side)) so that every
/// side shows the same optical depth.
std::vector<SuiteScene> volumeSuiteScenes(int side);

struct VolumeSuiteSettings {
    int width = 128, height = 128;
    int frames = 12;     ///< rotating views timed per row
    int errorFrames = 4; ///< of them compared with the reference
    int side = 64;       ///< voxels per side of the generated volumes
    glm::vec3 background{0.0f};
    Backend backend = Backend::OSMesa;
    RenderDebug debug;   ///< volsg-bench's debug switches (--no-empty-cells ...)
    std::string keepDir; ///< when set, the scene files are written there
};

/// Runs the suite; each row is printed as soon as it is measured, and all are returned.
///
/// Rows per scene:
/// - `reference` at tolerance 1e-4 (the truth the others are measured against: its time, no
///   error), and at 1e-3 and 1e-2 (their error against the truth);
/// - `slicing` (the Volume node) at 0.5, 1, 2 and 4 planes per voxel (numPlanes = p times
///   the box diagonal in voxels, so every view has at least p planes per voxel), with
///   preIntegrated off and on, still and interactive (RenderOptions::interactive: the node's
///   interactivePlanes, by default numPlanes / 4). A setting the node rejects (an Error) or
///   ignores (preIntegrated giving exactly the image without it) is printed as n/a.
/// - `shear-warp` (the ShearWarpVolume node) on the same scene seen by an orthographic camera
///   (shear-warp renders parallel projections only; same place, view height of the
///   perspective frustum at the focal distance), against the reference of those views (its
///   own truth row): 1 and 2 threads, with and without the idle-time optimizer (which runs
///   between frames, untimed), after a warm-up pass over all views (extraction, lists).
/// Memory: the Volume's resident 3D texture bytes (SlicingStats) for slicing, "texture"; the
/// growth of the process's resident memory for the reference, "rss"; the voxel lists of the
/// objects (extracted voxels and RenderLists of every axis built), "voxel lists".
std::vector<BenchRow> runVolumeSuite(const VolumeSuiteSettings& settings);

} // namespace volsg::bench
