#pragma once
// What one shear-warp frame draws: objects with their looks, and the view.

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/core/Object.h>
#include <volsg/shearwarp/SimdLevel.h>
#include <volsg/shearwarp/VoxelObject.h>
#include <volsg/volume/TransferFunction1D.h>

namespace volsg {

/// How a voxel's 16 attribute bits become colour and opacity: the LUT1/LUT2/LUT3 patterns of
/// RTVR figure 5 (lib/volsg/shearwarp/README.md has the table).
enum class VoxelRenderMode { TF, Shaded, GradientOpacity, Contour, ColoredContour };
/// Compositing within an object along a ray.
enum class ObjectCompositing { DVR, MIP, Surface };
/// Compositing between objects along a ray (two-level volume rendering).
enum class InterObjectCompositing { DVR, MIP };

/// Colour and opacity of one part (unclipped or clipped) of an object.
struct VoxelLook {
    VoxelRenderMode mode = VoxelRenderMode::TF;
    float opacity = 1.0f; ///< multiplies extinction (DVR, Surface) or alpha (MIP); 0 removes
};

/// A box in some coordinates: a local point p is inside when `localToBox * p` lies in
/// [origin, origin + extent].
struct ShearWarpBox {
    glm::dmat4 localToBox{1.0};
    glm::dvec3 origin{-0.5};
    glm::dvec3 extent{1.0};
};

/// One object of a frame. All objects of a frame come from the same grid (dimensions,
/// spacing, model matrix).
struct ShearWarpObject {
    ref_ptr<VoxelObject> object;
    TransferFunction1D transferFunction;
    ObjectCompositing compositing = ObjectCompositing::DVR;
    VoxelLook unclipped;
    VoxelLook clipped{VoxelRenderMode::TF, 0.0f};
    glm::vec3 contourColor{1.0f, 1.0f, 0.0f}; ///< ColoredContour
    float contourSharpness = 4.0f;            ///< exponent of (1 - |n.v|)
    float shininess = 20.0f;                  ///< Phong exponent of the Shaded tables
    /// The voxels are one-voxel layers (a SURFACE selection): drawn at every slice even when
    /// the view skips slices, since a skipped slice would punch holes into the layer.
    bool thinLayer = false;
    /// Clipping in the volume's local coordinates: a voxel centre is clipped when it lies on
    /// the removed side of a plane (keeping a*x + b*y + c*z >= d) or outside the box.
    std::vector<glm::dvec4> clipPlanes;
    std::optional<ShearWarpBox> box;
    /// Changes whenever the clip state does: the RenderLists are re-split (0 = no clipping).
    std::uint64_t clipKey = 0;
    /// Changes whenever modes, opacities or the transfer function do: entries are marked for
    /// re-optimisation.
    std::uint64_t tableKey = 1;
};

/// The camera and settings of a frame.
struct ShearWarpView {
    glm::dmat4 modelView{1.0};  ///< the volume's local coordinates to eye
    glm::dmat4 projection{1.0}; ///< must be orthographic (parallel projection)
    int width = 64, height = 64;
    glm::dvec3 lightDirection{0.0, 0.0, 1.0}; ///< towards the light, eye coordinates
    /// Opaque geometry already drawn: window depth per output pixel (row 0 at the top, 1 =
    /// nothing); voxels behind it do not count. Empty: none.
    std::vector<float> opaqueWindowDepth;
    InterObjectCompositing interObject = InterObjectCompositing::DVR;
    int threads = 0; ///< 0: std::thread::hardware_concurrency()
    /// Composite every sliceStep-th slice, each standing for sliceStep slices of thickness
    /// (opacity-corrected): the fast setting while the user interacts, as fewer planes are for
    /// the slicer. Thin-layer objects keep every slice. 1: every slice (full quality).
    int sliceStep = 1;
    /// Pure MIP scenes take the value-sorted path (ShearWarpRenderer); false: the general
    /// two-buffer path with bilinear slices (comparisons, benchmarks).
    bool valueSortedMip = true;
    /// The vector instructions of the engine's kernels (SimdLevel.h). Every level gives the
    /// same image bit for bit, so this changes speed only: Scalar compares the kernels or
    /// measures without AVX2. A level this CPU does not run is taken as Scalar. Default: the
    /// widest level this CPU runs.
    SimdLevel simd = bestSimdLevel();
};

/// What a frame did.
struct ShearWarpStats {
    int principalAxis = 2;
    glm::ivec2 intermediateSize{0};
    std::uint64_t voxelsTouched = 0; ///< voxels read (in the drawn ranges of the rows drawn)
    std::uint64_t voxelsHidden = 0;  ///< of them skipped: all their pixels had stopped (pure DVR)
    std::uint64_t entriesDrawn = 0;
    bool fastPath = false;       ///< pure DVR: one pixel buffer
    bool valueSortedMip = false; ///< pure MIP: value-sorted voxels, nearest pixel, no search
    int sliceStep = 1;           ///< the view's slice step, as used (clamped to the volume)
    double engineMs = 0.0;       ///< wall time of ShearWarpRenderer::render
    /// CPU time of render() summed over the threads it ran on (its frame time on idle cores
    /// is between engineCpuMs / threads and engineCpuMs).
    double engineCpuMs = 0.0;
};

} // namespace volsg
