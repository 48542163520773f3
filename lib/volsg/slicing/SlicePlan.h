#pragma once
// The plain data one frame of the Volume slicer hands from stage to stage.

#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/slicing/ProxyPlaneCutter.h>
#include <volsg/slicing/SliceShared.h>

namespace volsg::slicing {

/// How this frame draws the volume: decided from its mode, the settings and the volume, and
/// what the volume's textures were prepared for.
struct SliceMethod {
    Mode mode = kDvr;
    bool lighting = false;        ///< DVR with SlicingSettings::lighting
    bool tagged = false;          ///< label textures and a row per tagged transfer function
    bool preIntegrated = false;   ///< DVR without tagged functions, SlicingSettings::preIntegrated
    bool skipCells = false;       ///< empty cells left out (where that is exact)
    bool hasPlaneOpacity = false; ///< DVR with a planeOpacity that is not 1 everywhere
    int slabSamples = 1;          ///< samples along a ray in each plane's slab
    bool lean = false;            ///< the lean program: every sample of a slab counts alike
    bool leanPeaks = false;       ///< its MIP/MINIP variant with the voxel-centre crossings
};

/// The view in the volume's local coordinates (the volume box is [-halfExtent, halfExtent]).
struct LocalView {
    glm::dmat4 model{1.0};
    glm::dmat4 modelView{1.0};
    glm::dmat4 eyeToLocal{1.0};
    glm::dmat3 eyeToLocal3{1.0};
    glm::dvec3 halfExtent{0.0};
    glm::dvec2 boxDepth{0.0};  ///< eye depths of the box's nearest and farthest corners
    glm::dvec2 clipDepth{0.0}; ///< eye depths of the camera's near and far planes
    double L0 = 1.0;           ///< the grid's smallest spacing
    /// The eye (perspective) or the viewing direction (orthographic), local coordinates.
    glm::dvec3 viewer{0.0};
    bool orthographic = false;
};

/// The most samples a fragment takes for which its plane is cut into rows. Rows leave out the
/// fragments of empty cells, but they cut each plane into many small polygons, and llvmpipe
/// shades a partly covered 4x4 block whole: that waste grows with a fragment's samples, while a
/// slab of several samples trims its own empty ends (the lean loop's cell walks). Chest CT,
/// 512 x 512, DVR, the sum of 8 orbit views' frames, rows against none: 60 x 1 820 against 983
/// ms, 100 x 2 1303 against 1377, 40 x 8 902 against 895, 80 x 4 1401 against 1365, 20 x 16
/// 968 against 774, 10 x 32 995 against 672; lit 5 x 64 6160 against 4386; MIP with peaks, 5 x
/// 32, up to 199 against 74 ms a view (lib/volsg/slicing/README.md, session 20).
constexpr int kMaxRowSamples = 2;

/// How the bricks are cut into rows of empty-space cells (CellRows).
struct RowPlan {
    int reach = -1; ///< how far (cells) a fragment's samples reach; -1: whole bricks, no rows
    int axis = 0;   ///< the axis rows run along
    int group = 1;  ///< cells across a row, each way
    /// A paged volume: how far (local units) a fragment's samples reach beyond its point when
    /// its bricks' slices are cut to their emitting cells (cutBricks); < 0: not cut.
    double pagedReach = -1.0;
};

/// One frame's plan, filled stage by stage before anything is drawn.
struct SlicePlan {
    SliceMethod method;
    LocalView local;
    PlaneLayout layout;
    std::vector<glm::dvec4> clipPlanes; ///< the clip planes in local coordinates (n, d)
    RowPlan rows;
    /// Sort-last (FrameContext::partition): the part of the volume box this process draws,
    /// local coordinates; each brick draws where its own part meets it. Unbounded: all of it.
    glm::dvec3 partMin{-HUGE_VAL};
    glm::dvec3 partMax{HUGE_VAL};
    /// Slabs end at the faces of their brick, whose front faces are drawn at seams too: the
    /// slab's samples then stay in the brick's texture (slabsEndAtBricks).
    bool slabsEndAtBricks = false;
    /// Sort-last with the process holding only its part (VolumePartition::ownDataOnly): the
    /// part's faces are seams too (slabs end there, and the faces facing the eye are drawn).
    bool slabsEndAtPart = false;
};

/// Whether slabs end at brick faces: where the volume has several bricks, a fragment samples
/// beyond its plane point (several samples per plane, pre-integration, MIP's crossings, tags)
/// and planes lie more than `L0` apart (`spacingLocal`, local units), so that half a slab
/// reaches past a seam by more than half a voxel and would read texels the brick clamps.
/// Elsewhere slabs run between planes across seams as in one brick (at most a quarter voxel
/// past a seam at the fixed rules' two planes per voxel: within 1/255 of one brick).
inline bool slabsEndAtBricks(const SliceMethod& method, std::size_t bricks, double spacingLocal,
                             double L0) {
    const bool samplesOnlyItsPoint =
        method.mode == kDvr && method.slabSamples <= 1 && !method.preIntegrated && !method.tagged;
    return bricks > 1 && !samplesOnlyItsPoint && spacingLocal > L0;
}

} // namespace volsg::slicing
