#pragma once
// What the 3D-texture slicer did for one Volume: bricks, uploads, planes. Tests and the
// benchmark read it to check that memory follows what is shown and caches are not rebuilt.

#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include <volsg/paging/PagingStats.h>

namespace volsg {

/// Counters of one volume's slicing renderer. The "last frame" values are overwritten by each
/// render; the cumulative ones count since the volume's GPU cache was created (a new Renderer
/// or new data starts a new cache and resets them).
struct SlicingStats {
    // Last frame.
    int bricksTotal = 0;            ///< bricks the volume is split into (1 when it fits whole)
    int bricksDrawn = 0;            ///< bricks sliced and drawn
    int bricksSkipped = 0;          ///< bricks empty under the current transfer functions
    int bricksTrimmed = 0;          ///< paged bricks whose slices were cut to their emitting cells
    int bricksResident = 0;         ///< bricks whose textures are on the GPU after the frame
    std::size_t textureBytes = 0;   ///< bytes of the resident 3D textures (data and tags)
    glm::ivec3 brickGrid{0};        ///< bricks along x, y, z
    glm::ivec3 brickTexels{0};      ///< texels of the largest brick texture
    int planes = 0;                 ///< proxy planes of the layout (over the whole volume box)
    double planeSpacing = 0.0;      ///< eye units between neighbouring planes
    std::size_t sliceTriangles = 0; ///< triangles drawn, all bricks together
    /// Share of the 8^3-voxel cells whose samples are skipped as empty (0 when not skipping:
    /// MINIP, AVERAGE, tagged DVR, pre-integration).
    double emptyCells = 0.0;
    /// Rows of cells cut and drawn instead of whole bricks (lib/volsg/slicing/CellRows.h): the
    /// empty space around them makes no fragment. 0: whole bricks were cut.
    int cellRows = 0;
    int cellRowGroup = 1; ///< rows were this many cells across (each way)
    /// Per-frame CPU work of the node, on a steady clock: the Volume node gathering its state
    /// (data, transfer functions, clips) and the slicer's work before any draw is issued (plane
    /// layout, brick order and emptiness, cutting, vertex assembly, and table rebuilds when a
    /// transfer function changed). No GL execution: no draw, no readback, no glFinish.
    double cpuMilliseconds = 0.0;
    /// Wall time of issuing the GL work: brick uploads, uniforms, draws (including any wait
    /// in the driver; llvmpipe may block here on earlier rendering).
    double submitMilliseconds = 0.0;
    /// The frame's quality: what was drawn (chosen from the error target where the fields
    /// left it automatic) and the error the model predicts for it against the reference
    /// (lib/volsg/slicing/SlabErrorModel.h). predictedRmse < 0: not predicted (AVERAGE,
    /// NEAREST, no target).
    int samplesPerPlane = 1;
    bool preIntegrated = false;
    bool mipPeaks = false;
    double planeSpacingL0 = 0.0; ///< plane spacing along the view, in L0
    double errorTarget = 0.0;    ///< the target this frame was chosen for (0..1 units)
    double predictedRmse = -1.0; ///< per channel, 0..1 units
    /// The quadrature's part of it (the same but for a paged volume, whose prediction adds
    /// the level of detail's: PagingStats::lodRmse).
    double quadratureRmse = -1.0;
    bool meetsTarget = true;          ///< the prediction is within the target
    double coverage = 0.0;            ///< share of the image's pixels whose rays cross the box
    double qualityMilliseconds = 0.0; ///< CPU time of the choice (part of cpuMilliseconds)
    /// View directions the error model has cast its rays for so far (each costs more than most
    /// frames; an interactive frame reuses a near one: VolumeSlicer.cpp).
    int modelDirections = 0;
    /// Sort-last (FrameContext::partition): where this process's part lies in the front-to-back
    /// order of the parts for this view (0: in front), and the voxels it spans.
    int partPosition = 0;
    glm::ivec3 partFirstVoxel{0};
    glm::ivec3 partLastVoxel{-1};

    // Cumulative.
    std::uint64_t frames = 0;
    std::uint64_t brickUploads = 0;  ///< brick textures sent to the GPU
    std::uint64_t uploadedBytes = 0; ///< their bytes
    /// Of brickUploads, those read from a buffer staged before the grid was shown
    /// (VolumeSlicer::stage: a VolumeSeries' next step).
    std::uint64_t stagedUploads = 0;
    /// Of brickUploads, those written into the previous grid's texture of the same size (a
    /// series' step change) instead of a new one.
    std::uint64_t refilledTextures = 0;
    std::uint64_t transferTableBuilds = 0;  ///< transfer tables (and tag maps) baked and uploaded
    std::uint64_t preIntegrationBuilds = 0; ///< pre-integration tables baked and uploaded

    /// A paged volume's level of detail, residency and I/O (paging.paged false otherwise).
    PagingStats paging;
};

} // namespace volsg
