#pragma once
// The stages of a shear-warp frame and the plain data passed between them (internal to
// lib/volsg/shearwarp; ShearWarpRenderer::renderFrame runs them in this order):
//
//   1. takeOutputBuffers   the output image and depth (a recycled frame's: what it drew is
//                          cleared by the warp, row by row, where the new frame does not write)
//   2. factorise           principal axis, shear, intermediate size, warp and depth maps
//   3. frameObjects, lockLists, prepareObjects
//                          each object's list for the axis, locked; clip split, tables, slices
//   4. choosePaths         pure DVR (one buffer, front to back), value-sorted MIP or two-level
//   5. sizeBuffers         the intermediate buffers and pick data for the paths
//   6. compositing         compositeBands (pure DVR, two-level; bands of rows, BandCompositing.cpp)
//                          or the value-sorted MIP (ValueSortedMip.cpp)
//   7. warpRows            the output image (and Surface depth) from the intermediate image,
//                          and the rectangle drawn
//
// Picking (ShearWarpRenderer::pick) reads the pick arrays filled while compositing and the
// factorisation recorded by describeFactorisation.

#include <atomic>
#include <cstdint>
#include <ctime>
#include <limits>
#include <mutex>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/core/WorkerPool.h>
#include <volsg/shearwarp/RenderList.h>
#include <volsg/shearwarp/ShearWarpRenderer.h>
#include <volsg/shearwarp/TwoLevelComposite.h>
#include <volsg/shearwarp/VoxelTables.h>

namespace volsg::shearwarp {

// --- Threads ---------------------------------------------------------------------------------

/// CPU time of the calling thread in ns.
inline std::int64_t threadCpuNs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return std::int64_t(t.tv_sec) * 1000000000 + std::int64_t(t.tv_nsec);
}

/// CPU time the pool's workers spent in renderer jobs (the calling thread measures its own).
inline std::atomic<std::int64_t> helperCpuNs{0};

/// body(i) for i in [0, count) on the pool's threads (0 on the caller's).
template <class F> void parallelFor(WorkerPool& pool, int count, F body) {
    pool.run(count, [&body](int i) {
        if (i == 0) {
            body(0);
            return;
        }
        const std::int64_t start = threadCpuNs();
        body(i);
        helperCpuNs += threadCpuNs() - start;
    });
}

// --- 1. Output buffers -----------------------------------------------------------------------

/// Throws Error for a perspective projection or an empty output size.
void checkView(const ShearWarpView& view);
/// What a recycled frame drew and is not cleared yet: its image outside `rect` is 0, its depth 1
/// (everywhere unless `depth`).
struct StaleOutput {
    glm::ivec4 rect{0}; ///< (x0, y0, x1, y1), exclusive; empty: nothing
    bool depth = false;
};
/// A frame with the output image and depth of the view's size: the recycled frame's buffers
/// when they fit, with what they drew in `stale` (cleared by the warp, or clearStaleRows), else
/// new ones (0 and 1); and its pick arrays.
ShearWarpFrame takeOutputBuffers(ShearWarpFrame& spare, const ShearWarpView& view,
                                 StaleOutput& stale);
/// Clears output rows [y0, y1) of the stale rectangle (image 0, depth 1).
void clearStaleRows(const StaleOutput& stale, ShearWarpFrame& frame, int y0, int y1);
/// Throws Error unless every object has voxels and all come from one volume.
void checkObjects(const std::vector<ShearWarpObject>& objects);

// --- 2. Factorisation ------------------------------------------------------------------------

/// Index (i, j, k) -> the volume's local coordinates (voxel centres, box centred on 0).
glm::dmat4 indexToLocalMatrix(const VoxelObject& object);

/// The shear-warp factorisation of a view: slices are planes of constant c; slice k lands on
/// the intermediate image shifted by (ua0 - sa k, vb0 - sb k), one pixel per voxel.
struct Factorisation {
    glm::dmat4 indexToLocal{1.0};
    int a = 0, b = 1, c = 2; ///< index axes: c principal, (a, b) the intermediate (u, v)
    int na = 0, nb = 0, nc = 0;
    double sa = 0.0, sb = 0.0;   ///< shear: (u, v) move by -(sa, sb) per slice
    double ua0 = 0.0, vb0 = 0.0; ///< (u, v) of voxel (a, b) = (0, 0) of slice 0
    int W = 0, H = 0;            ///< intermediate image size
    bool ascending = false;      ///< back to front is ascending k
    glm::dmat3 warp{1.0};        ///< (u, v, 1) -> output pixel
    glm::dmat3 unwarp{1.0};      ///< output pixel (x, y, 1) -> (u, v, 1)
    bool warpValid = true;       ///< false: not invertible in double precision (nothing shows)
    /// Eye z of intermediate pixel (u, v) at slice k: z0 + zu u + zv v + zk k.
    double z0 = 0.0, zu = 0.0, zv = 0.0, zk = 0.0;
    double stepRatio = 1.0; ///< ds / L0: the slab of one slice step over the smallest spacing
    glm::dmat4 projection{1.0};
    int width = 0, height = 0; ///< output size

    float windowDepthOf(double zEye) const {
        return float(0.5 * (projection[2][2] * zEye + projection[3][2]) + 0.5);
    }
};

Factorisation factorise(const VoxelObject& first, const ShearWarpView& view);
/// Records the factorisation in the frame (picking, stats).
void describeFactorisation(const Factorisation& f, ShearWarpFrame& frame);

// --- 3. Objects ------------------------------------------------------------------------------

/// One object part's drawing data for a frame.
struct Part {
    VoxelTables tables;
    bool draw = false;
};

struct FrameObject {
    ShearWarpObject* source = nullptr;
    RenderList* list = nullptr;
    Part parts[2];                         ///< unclipped, clipped
    std::vector<std::uint32_t> sliceStart; ///< entries of slice k: [sliceStart[k], sliceStart[k+1])
    std::vector<glm::vec4> mipTable;       ///< value (4096) -> premultiplied colour, MIP
    int sliceStep = 1;                     ///< draws slices k with k % sliceStep == slicePhase
    int slicePhase = 0;
};

/// The frame's objects with their lists for principal axis `axis`; throws Error when two
/// share a list.
std::vector<FrameObject> frameObjects(std::vector<ShearWarpObject>& objects, int axis);
/// Locks every object's list for the frame (in one order: the lists' addresses).
std::vector<std::unique_lock<std::mutex>> lockLists(const std::vector<FrameObject>& objects);
/// Prepares each list (clip split, packed attributes), builds the parts' tables, the MIP
/// tables and the slice starts; `sliceStep` is the view's, clamped.
void prepareObjects(std::vector<FrameObject>& objects, const Factorisation& f,
                    const ShearWarpView& view, int sliceStep);

// --- 4. Paths --------------------------------------------------------------------------------

struct FramePaths {
    bool pureDvr = false;    ///< every object DVR, DVR between them: one buffer, front to back
    bool pureMip = false;    ///< the value-sorted MIP
    bool twoLevel = false;   ///< otherwise: run and global buffers
    bool anySurface = false; ///< depth is written only by Surface objects
    bool hasLimit = false;   ///< opaque geometry in the frame
    std::vector<const ValueSortedVoxels*> sorted; ///< pureMip: per object
};

/// Chooses the paths (and throws Error for an opaque depth buffer of the wrong size).
FramePaths choosePaths(const std::vector<FrameObject>& objects, const ShearWarpView& view);

// --- 5. Buffers ------------------------------------------------------------------------------

/// The frame's intermediate buffers (W x H pixels, row-major): pointers into the renderer's
/// scratch and the frame's pick arrays; those the paths do not use may be null or short.
struct FrameBuffers {
    glm::vec4* global;
    glm::vec4* local;
    float* localValue;
    float* localDepth;
    std::int16_t* localObject;
    float* hitDepth;
    float* limit;
    std::int32_t* nextOpen;
    int* opaqueCount;
    std::int16_t* pickObject;
    float* pickSlice;
};

/// Sizes the buffers the paths need (never shrunk: a size change fills nothing serially; each
/// band's thread clears its own rows).
FrameBuffers sizeBuffers(FrameScratch& scratch, ShearWarpFrame& frame, const Factorisation& f,
                         const FramePaths& paths);

// --- 6. Compositing --------------------------------------------------------------------------

/// What every band (and every value-sorted MIP run) of a frame reads: shared by the threads.
struct BandJob {
    const Factorisation* factorisation;
    const FrameObject* objects;
    int objectCount;
    const TwoLevelObject* twoLevelObjects; ///< by object index
    bool pureDvr, twoLevel, anySurface, hasLimit;
    InterObjectCompositing inter;
    SimdLevel simd;
    const float* opaqueWindowDepth; ///< hasLimit: the view's, output pixels
    FrameBuffers buffers;
    int bandCount;
};

/// Clears intermediate rows [r0, r1) of every buffer the paths use (links open, opaque limits
/// from the view's depth).
void initRows(const BandJob& job, int r0, int r1);

/// One thread's share of the bands: bands taken from `nextBand` until none is left, each
/// composited over every slice and object; its composited pixels to touched[band].
void compositeBands(const BandJob& job, std::atomic<int>& nextBand, BandScratch& scratch,
                    glm::ivec4* touched);

/// The value-sorted MIP of object `object` (its runs drawn by thread t of `threads` into that
/// thread's buffers, then merged by rows).
struct ValueSortedRun {
    const BandJob* job;
    int object;
    const ValueSortedVoxels* sorted;
    const std::int64_t* sliceOffset; ///< per slice: intermediate offset, or kSkipSlice
    std::uint32_t begin, end;        ///< the voxels drawn: of the first value shown on
    int threads;
    FrameScratch* scratch;
};
inline constexpr std::int64_t kSkipSlice = std::numeric_limits<std::int64_t>::min();

/// Per slice the offset of voxel (a, b) = (0, 0) on the intermediate image (nearest pixel),
/// kSkipSlice for slices left out.
std::vector<std::int64_t> valueSortedOffsets(const Factorisation& f, const FrameObject& object);
/// The first voxel whose value the object's table shows (alpha > 0).
std::uint32_t firstShownVoxel(const FrameObject& object, const ValueSortedVoxels& sorted);
/// Thread t's run of the order into its buffers; returns the voxels drawn.
std::uint64_t drawValueSortedRun(const ValueSortedRun& run, int t);
/// Merges rows of thread t's share: the object's layer C(v) A(v), MIP with the global pixel.
void mergeValueSortedRows(const ValueSortedRun& run, int t);

// --- 7. Warp ---------------------------------------------------------------------------------

struct WarpJob {
    const Factorisation* factorisation;
    const glm::vec4* image; ///< the intermediate image
    const float* hitDepth;  ///< anySurface: intermediate depth
    bool anySurface;
    bool clampU, clampV; ///< unsheared axes: clamp to the outermost voxel column
    glm::dvec4 reach;    ///< (u0, v0, u1, v1): intermediate box whose output can be non-zero
    glm::vec4* out;      ///< output image
    float* windowDepth;  ///< output depth
    StaleOutput stale;   ///< cleared where the warp does not write
    SimdLevel simd;      ///< Avx2: four pixels' coordinates at once (the same pixels)
};

/// The warp of output rows [y0, y1) (and the clear of the stale pixels in them); returns the
/// rectangle it wrote (x0, y0, x1, y1).
glm::ivec4 warpRows(const WarpJob& job, int y0, int y1);

} // namespace volsg::shearwarp
