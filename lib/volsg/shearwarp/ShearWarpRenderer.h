#pragma once
// The shear-warp renderer of RenderLists (Lacroute & Levoy 1994; RTVR section 3.4).

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/core/WorkerPool.h>
#include <volsg/image/Image.h>
#include <volsg/shearwarp/ShearWarpScene.h>

namespace volsg {

namespace shearwarp {

/// The scratch of one band-compositing thread (internal to the renderer).
struct BandScratch {
    std::vector<glm::vec4> lines[2];       ///< one voxel row resampled along a, and the previous
    std::vector<std::uint64_t> written[2]; ///< the lines' written columns (ColumnMask.h)
    std::uint64_t voxels = 0, hidden = 0;
    std::uint64_t entries = 0;
};

/// The renderer's buffers kept from frame to frame (internal; sized per frame, never shrunk).
struct FrameScratch {
    std::vector<glm::vec4> global, local;
    std::vector<float> localValue, localDepth, limit, hitDepth;
    std::vector<std::int16_t> localObject;
    std::vector<std::int32_t> nextOpen; ///< per pixel: itself, or a later column once opaque
    std::vector<int> opaqueCount;       ///< per intermediate row: stopped pixels
    std::vector<BandScratch> bands;
    /// Pure MIP: per thread, the largest value + 1 (0: none) and its slice per pixel.
    std::vector<std::vector<std::uint16_t>> mipValue, mipSlice;
};

} // namespace shearwarp

/// The result of a frame: the premultiplied image (rgb = colour * coverage, a = 1 - total
/// transmittance; composite it over what lies behind), the window depth of opaque results
/// (Surface hits of objects with opacity 1; 1 elsewhere), and what picking needs.
struct ShearWarpFrame {
    Image image;
    std::vector<float> windowDepth;
    ShearWarpStats stats;
    /// The output pixels the warp wrote, (x0, y0, x1, y1) exclusive (all 0: none); outside
    /// them the image is 0 and the depth 1.
    glm::ivec4 drawn{0};
    bool wroteDepth = false; ///< windowDepth may hold values < 1 (Surface objects drawn)

    // Picking: per intermediate pixel the front-most object that contributed and its slice.
    std::vector<std::int16_t> pickObject;
    std::vector<float> pickSlice;
    glm::dmat3 outputToIntermediate{1.0}; ///< (x, y, 1) pixel centre -> (u, v, 1)
    glm::dmat4 indexToLocal{1.0};
    int axisA = 0, axisB = 1, axisC = 2;
    double shearA = 0.0, shearB = 0.0, originA = 0.0, originB = 0.0;
};

/// What is seen at a pixel: the index of the object in the frame's object list and the
/// position of the voxel slice hit, in the volume's local coordinates.
struct ShearWarpPick {
    int object = -1;
    glm::dvec3 localPosition{0.0};
};

/// Renders objects extracted from one volume with parallel projection in any orientation:
///
/// 1. Factorisation: the principal axis c is the index axis most parallel to the viewing
///    direction; moving one slice along c shifts a ray by (shearA, shearB) in (a, b). Slices are
///    composited back to front into the sheared intermediate image (one pixel per voxel).
/// 2. Resampling: all voxels of a slice share one fractional shift, so the slice is resampled
///    onto the pixel grid with fixed bilinear weights (as in Lacroute's renderer): each voxel
///    row is split between two columns into a line buffer, two consecutive lines blend into
///    an intermediate row, which is then composited. Voxels absent from the list count as
///    transparent. Alpha is opacity-corrected for the sample spacing ds along the ray.
/// 3. Warp: every output pixel samples the intermediate image bilinearly.
///
/// Compositing: pure DVR (every object DVR, DVR between them) takes the fast path with one
/// pixel buffer, front to back with early ray termination: a pixel stops at alpha 0.999
/// (so it differs from the full sum by less than 0.001) and voxels whose four pixels are all
/// stopped are skipped via per-row links to the next open pixel (Lacroute's opaque-pixel links).
/// Otherwise two buffers (two-level rendering): each ray segment inside one object is composited
/// with that object's mode (DVR; MIP of the resampled value; Surface: composited like DVR, then
/// drawn opaque (colour / alpha) when the run's alpha reaches 0.5, with the depth of its front-most
/// sample of alpha >= 0.25 - gap-free on one-voxel layers) and, when the ray enters another object
/// or ends, merged into the global buffer with the inter-object mode (DVR: over; MIP: per-channel
/// maximum of the premultiplied layers).
///
/// Pure MIP (every object MIP, MIP between them, nothing clipped, no opaque geometry) takes
/// RTVR's value-sorted path: each object's voxels ordered by value (VoxelObject::valueSorted)
/// are projected lowest first onto their nearest intermediate pixel, each simply overwriting
/// it, from the first value the transfer function shows; threads take runs of the order into
/// buffers of their own, merged by maximum. The resampling is nearest-pixel where the general
/// path interpolates each slice bilinearly (errors in README.md).
///
/// Threads take bands of intermediate rows from a counter, three bands per thread (voxels of a
/// drawn range are sorted by row, so a band is a binary search away), and then bands of output
/// rows; they are kept in a WorkerPool between jobs. The RenderLists are locked
/// for the frame. Throws Error for a perspective projection.
class ShearWarpRenderer {
public:
    ShearWarpFrame render(std::vector<ShearWarpObject>& objects, const ShearWarpView& view);

    /// Splits every object's RenderList for the view's principal axis by its clip state,
    /// derives the packed attributes for its modes and resets optimisation after a table
    /// change (done by render(); public for the optimizer's tests).
    static void prepare(ShearWarpObject& object, RenderList& list);

    /// Hands back a frame this renderer made and that is no longer needed: the next render()
    /// reuses its buffers (same output size: only the rectangle it drew is cleared).
    void recycle(ShearWarpFrame&& frame);

    static std::optional<ShearWarpPick> pick(const ShearWarpFrame& frame, int x, int y);

private:
    ShearWarpFrame renderFrame(std::vector<ShearWarpObject>& objects, const ShearWarpView& view);

    shearwarp::FrameScratch scratch_;                                   ///< kept between frames
    ShearWarpFrame spare_;                                              ///< recycled buffers
    std::unique_ptr<WorkerPool> pool_ = std::make_unique<WorkerPool>(); ///< the frame's threads
};

} // namespace volsg
