#include <volsg/shearwarp/ShearWarpRenderer.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <utility>

#include <volsg/shearwarp/FrameStages.h>

namespace volsg {

namespace {

using namespace shearwarp;

// Bands of intermediate rows per thread. Measured (sphere, 2 threads, alternating runs): with 3
// the frame costs about 2% more on idle cores than with 1, and 10-35% less when one core is
// slowed by other load.
constexpr int kBandsPerThread = 3;

bool isClipped(const ShearWarpObject& o, const glm::dvec3& p) {
    for (const glm::dvec4& plane : o.clipPlanes)
        if (glm::dot(glm::dvec3(plane), p) < plane.w) return true;
    if (o.box) {
        const glm::dvec3 q = glm::dvec3(o.box->localToBox * glm::dvec4(p, 1.0));
        const glm::dvec3 lo = o.box->origin, hi = o.box->origin + o.box->extent;
        if (q.x < lo.x || q.y < lo.y || q.z < lo.z || q.x > hi.x || q.y > hi.y || q.z > hi.z)
            return true;
    }
    return false;
}

/// Stage 6, pure DVR and two-level frames: bands of intermediate rows taken from a counter,
/// kBandsPerThread per thread (a thread whose core is slowed by other load takes fewer; each
/// band boundary splats one voxel row twice per slice). Returns per band the intermediate
/// pixels composited, (u0, v0, u1, v1); all others stay empty.
std::vector<glm::ivec4> compositeFrame(WorkerPool& pool, const BandJob& job, FrameScratch& scratch,
                                       int threads) {
    std::vector<glm::ivec4> touched(std::size_t(job.bandCount),
                                    glm::ivec4(job.factorisation->W, job.factorisation->H, 0, 0));
    std::atomic<int> nextBand{0};
    parallelFor(pool, threads, [&](int t) {
        compositeBands(job, nextBand, scratch.bands[std::size_t(t)], touched.data());
    });
    return touched;
}

/// Stage 6, pure MIP: the value-sorted voxels of each object drawn by runs (one per thread)
/// and merged into the global buffer. Returns the whole intermediate image as composited.
std::vector<glm::ivec4> drawValueSortedMip(WorkerPool& pool, const BandJob& job,
                                           const FramePaths& paths, FrameScratch& scratch,
                                           int threads, ShearWarpStats& stats) {
    const Factorisation& f = *job.factorisation;
    parallelFor(pool, threads,
                [&](int t) { initRows(job, f.H * t / threads, f.H * (t + 1) / threads); });
    scratch.mipValue.resize(std::size_t(threads));
    scratch.mipSlice.resize(std::size_t(threads));
    for (int oi = 0; oi < job.objectCount; ++oi) {
        const FrameObject& object = job.objects[oi];
        const ValueSortedVoxels& sorted = *paths.sorted[std::size_t(oi)];
        const std::vector<std::int64_t> sliceOffset = valueSortedOffsets(f, object);
        const ValueSortedRun run{&job,
                                 oi,
                                 &sorted,
                                 sliceOffset.data(),
                                 firstShownVoxel(object, sorted),
                                 sorted.start[4096],
                                 threads,
                                 &scratch};
        parallelFor(pool, threads, [&](int t) {
            scratch.bands[std::size_t(t)].voxels = drawValueSortedRun(run, t);
        });
        for (BandScratch& s : scratch.bands)
            stats.voxelsTouched += std::exchange(s.voxels, 0);
        parallelFor(pool, threads, [&](int t) { mergeValueSortedRows(run, t); });
    }
    for (BandScratch& s : scratch.bands)
        s.hidden = s.entries = 0; // (voxels counted above)
    return {glm::ivec4(0, 0, f.W, f.H)};
}

/// Stage 7: the warp of the output rows, by threads; the output rectangle drawn to the frame.
/// Only output pixels whose bilinear footprint meets the composited part of the intermediate
/// image (the union of `touched`) can differ from 0 (and depth 1): the others are skipped.
void warpFrame(WorkerPool& pool, const Factorisation& f, const FrameBuffers& buffers,
               bool anySurface, const std::vector<glm::ivec4>& touched, int threads,
               const StaleOutput& stale, SimdLevel simd, ShearWarpFrame& frame) {
    glm::ivec4 box(f.W, f.H, 0, 0);
    for (const glm::ivec4& b : touched)
        box = glm::ivec4(glm::min(glm::ivec2(box), glm::ivec2(b)),
                         glm::max(glm::ivec2(box.z, box.w), glm::ivec2(b.z, b.w)));
    // Between the outermost voxel centres and the box faces the data is clamped to the edge
    // (docs/SCENE-FORMAT.md section 4). Along an unsheared intermediate axis the rays are parallel
    // to the box's side faces: a ray within half a voxel outside the outermost voxel column sees
    // that column's values all along, so the warp clamps to it (exact). Along a sheared axis the
    // silhouette is slanted and clamping would smear it; there the warp blends towards empty
    // pixels (an error confined to the half-voxel border, measured in README.md).
    const WarpJob job{&f,
                      buffers.global,
                      buffers.hitDepth,
                      anySurface,
                      std::abs(f.sa) < 1e-9,
                      std::abs(f.sb) < 1e-9,
                      glm::dvec4(box.x - 2.0, box.y - 2.0, box.z + 1.0, box.w + 1.0),
                      frame.image.pixels.data(),
                      frame.windowDepth.data(),
                      stale,
                      simd};
    const int outThreads = std::clamp(threads, 1, std::max(1, f.height / 8));
    std::vector<glm::ivec4> drawnRows(std::size_t(outThreads), glm::ivec4(f.width, f.height, 0, 0));
    if (box.x < box.z && box.y < box.w)
        parallelFor(pool, outThreads, [&](int t) {
            drawnRows[std::size_t(t)] =
                warpRows(job, f.height * t / outThreads, f.height * (t + 1) / outThreads);
        });
    else
        clearStaleRows(stale, frame, 0, f.height);
    frame.drawn = glm::ivec4(f.width, f.height, 0, 0);
    for (const glm::ivec4& d : drawnRows)
        frame.drawn =
            glm::ivec4(glm::min(glm::ivec2(frame.drawn), glm::ivec2(d)),
                       glm::max(glm::ivec2(frame.drawn.z, frame.drawn.w), glm::ivec2(d.z, d.w)));
    if (frame.drawn.x >= frame.drawn.z || frame.drawn.y >= frame.drawn.w)
        frame.drawn = glm::ivec4(0);
    frame.wroteDepth = anySurface && frame.drawn.x < frame.drawn.z;
}

/// What every band of the frame reads.
BandJob bandJob(const Factorisation& f, const std::vector<FrameObject>& objects,
                const std::vector<TwoLevelObject>& twoLevel, const FramePaths& paths,
                const FrameBuffers& buffers, const ShearWarpView& view, int threads) {
    BandJob job{};
    job.factorisation = &f;
    job.objects = objects.data();
    job.objectCount = int(objects.size());
    job.twoLevelObjects = twoLevel.data();
    job.pureDvr = paths.pureDvr;
    job.twoLevel = paths.twoLevel;
    job.anySurface = paths.anySurface;
    job.hasLimit = paths.hasLimit;
    job.inter = view.interObject;
    job.simd = view.simd;
    job.opaqueWindowDepth = paths.hasLimit ? view.opaqueWindowDepth.data() : nullptr;
    job.buffers = buffers;
    job.bandCount =
        paths.pureMip ? 0 : std::clamp(threads * kBandsPerThread, 1, std::max(1, f.H / 4));
    return job;
}

void addVoxelCounts(const std::vector<BandScratch>& bands, ShearWarpStats& stats) {
    for (const BandScratch& s : bands) {
        stats.voxelsTouched += s.voxels;
        stats.voxelsHidden += s.hidden;
        stats.entriesDrawn += s.entries;
    }
}

/// What a run of each object needs at its merge (two-level frames).
std::vector<TwoLevelObject> twoLevelObjects(const std::vector<FrameObject>& objects) {
    std::vector<TwoLevelObject> o;
    for (const FrameObject& f : objects)
        o.push_back({f.source->compositing, f.mipTable.empty() ? nullptr : f.mipTable.data()});
    return o;
}

} // namespace

void ShearWarpRenderer::prepare(ShearWarpObject& o, RenderList& list) {
    if (list.clipKey != o.clipKey) {
        const glm::dmat4 toLocal = indexToLocalMatrix(*o.object);
        for (RenderListEntry& e : list.entries) {
            list.sortByPosition(e.first, e.lastInSlice);
            std::uint32_t split = e.lastInSlice;
            if (o.clipKey != 0)
                split = list.partition(e.first, e.lastInSlice, [&](std::uint32_t i) {
                    const glm::dvec3 p =
                        glm::dvec3(toLocal * glm::dvec4(glm::dvec3(list.position(e, i)), 1.0));
                    return !isClipped(o, p);
                });
            e.firstClipped = split;
            e.last = split;
            e.lastClipped = e.lastInSlice;
            e.optimized = false;
        }
        list.clipKey = o.clipKey;
        list.tableKey = 0; // re-derive and re-optimise below
    }
    const PackedLayout wantUnclipped = VoxelTables::layoutFor(o.unclipped.mode);
    const PackedLayout wantClipped = VoxelTables::layoutFor(o.clipped.mode);
    if (list.tableKey != o.tableKey) {
        for (RenderListEntry& e : list.entries) {
            list.sortByPosition(e.first, e.firstClipped);
            list.sortByPosition(e.firstClipped, e.lastInSlice);
            list.derivePacked(e.first, e.firstClipped, wantUnclipped);
            list.derivePacked(e.firstClipped, e.lastInSlice, wantClipped);
            e.last = e.firstClipped;
            e.lastClipped = e.lastInSlice;
            e.optimized = false;
        }
        list.unclippedLayout = wantUnclipped;
        list.clippedLayout = wantClipped;
        list.contributesUnclipped = VoxelTables::contributionMask(o, o.unclipped);
        list.contributesClipped = VoxelTables::contributionMask(o, o.clipped);
        list.tableKey = o.tableKey;
    }
}

ShearWarpFrame ShearWarpRenderer::render(std::vector<ShearWarpObject>& objects,
                                         const ShearWarpView& view) {
    const auto wallStart = std::chrono::steady_clock::now();
    const std::int64_t cpuStart = threadCpuNs();
    const std::int64_t helperStart = helperCpuNs.load();
    ShearWarpFrame frame = renderFrame(objects, view);
    frame.stats.engineMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wallStart)
            .count();
    // helperCpuNs is shared by every renderer: concurrent renders may count each other's.
    frame.stats.engineCpuMs =
        double(threadCpuNs() - cpuStart + (helperCpuNs.load() - helperStart)) * 1e-6;
    return frame;
}

ShearWarpFrame ShearWarpRenderer::renderFrame(std::vector<ShearWarpObject>& objects,
                                              const ShearWarpView& view) {
    // 1. The output image and depth.
    checkView(view);
    StaleOutput stale;
    ShearWarpFrame frame = takeOutputBuffers(spare_, view, stale);
    if (objects.empty()) {
        clearStaleRows(stale, frame, 0, view.height);
        frame.pickObject.clear();
        frame.pickSlice.clear();
        return frame;
    }
    checkObjects(objects);
    // 2. Factorisation.
    const Factorisation f = factorise(*objects.front().object, view);
    describeFactorisation(f, frame);
    const int sliceStep = std::clamp(view.sliceStep, 1, std::max(1, f.nc));
    frame.stats.sliceStep = sliceStep;
    // 3. Objects: lists (locked for the frame), clip split, tables.
    std::vector<FrameObject> objectsOfFrame = frameObjects(objects, f.c);
    std::vector<std::unique_lock<std::mutex>> locks = lockLists(objectsOfFrame);
    prepareObjects(objectsOfFrame, f, view, sliceStep);
    // 4. Paths.
    const FramePaths paths = choosePaths(objectsOfFrame, view);
    frame.stats.fastPath = paths.pureDvr;
    frame.stats.valueSortedMip = paths.pureMip;
    // 5. Buffers and threads.
    const FrameBuffers buffers = sizeBuffers(scratch_, frame, f, paths);
    const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
    // Never more threads than cores (a thread per core is the most that can help, and a huge
    // count would only exhaust stacks), nor than bands of four rows.
    const int threads = std::clamp(view.threads > 0 ? view.threads : int(hardware), 1,
                                   std::max(1, std::min(int(hardware), f.H / 4)));
    scratch_.bands.resize(std::size_t(threads));
    // 6. Compositing: pure DVR and two-level frames by bands of rows, pure MIP by value.
    const std::vector<TwoLevelObject> twoLevel = twoLevelObjects(objectsOfFrame);
    const BandJob job = bandJob(f, objectsOfFrame, twoLevel, paths, buffers, view, threads);
    const std::vector<glm::ivec4> touched =
        paths.pureMip ? drawValueSortedMip(*pool_, job, paths, scratch_, threads, frame.stats)
                      : compositeFrame(*pool_, job, scratch_, threads);
    addVoxelCounts(scratch_.bands, frame.stats);
    locks.clear(); // the lists are not read after compositing
    // 7. Warp. (Picking reads the pick arrays filled while compositing and the factorisation.)
    warpFrame(*pool_, f, buffers, paths.anySurface, touched, threads, stale, view.simd, frame);
    return frame;
}

void ShearWarpRenderer::recycle(ShearWarpFrame&& frame) {
    spare_ = std::move(frame);
}

std::optional<ShearWarpPick> ShearWarpRenderer::pick(const ShearWarpFrame& frame, int x, int y) {
    const glm::ivec2 size = frame.stats.intermediateSize;
    if (size.x <= 0) return std::nullopt;
    const glm::dvec3 uv = frame.outputToIntermediate * glm::dvec3(x, y, 1.0);
    // Tested before rounding, NaN-proof: lround of a huge or NaN value is undefined.
    if (!(uv.x > -0.5 && uv.y > -0.5 && uv.x < size.x - 0.5 && uv.y < size.y - 0.5))
        return std::nullopt;
    const int u = int(std::lround(uv.x)), v = int(std::lround(uv.y));
    if (u < 0 || v < 0 || u >= size.x || v >= size.y) return std::nullopt;
    const std::size_t p = std::size_t(v) * std::size_t(size.x) + std::size_t(u);
    if (frame.pickObject[p] < 0) return std::nullopt;
    const double k = frame.pickSlice[p];
    glm::dvec3 g;
    g[frame.axisA] = uv.x - frame.originA + frame.shearA * k;
    g[frame.axisB] = uv.y - frame.originB + frame.shearB * k;
    g[frame.axisC] = k;
    ShearWarpPick pick;
    pick.object = frame.pickObject[p];
    pick.localPosition = glm::dvec3(frame.indexToLocal * glm::dvec4(g, 1.0));
    return pick;
}

} // namespace volsg
