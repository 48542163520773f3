#include <volsg/shearwarp/ShearWarpRenderer.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <limits>
#include <mutex>
#include <set>
#include <thread>
#include <type_traits>
#include <utility>

#include <volsg/core/Error.h>
#include <volsg/shearwarp/Lanes4.h>
#include <volsg/shearwarp/PackedVoxel.h>
#include <volsg/shearwarp/UnderComposite.h>
#include <volsg/shearwarp/VoxelTables.h>

namespace volsg {

namespace {

constexpr float kPickAlpha =
    UnderComposite::kPickAlpha;             // a sample this opaque is what a click hits
constexpr float kSurfaceAlpha = 0.5f;       // a Surface run this opaque is drawn opaque
constexpr float kSurfaceDepthAlpha = 0.25f; // a Surface sample this opaque may give the depth
// Bands of intermediate rows per thread. Measured (sphere, 2 threads, alternating runs): with 3
// the frame costs about 2% more on idle cores than with 1, and 10-35% less when one core is
// slowed by other load.
constexpr int kBandsPerThread = 3;

/// CPU time of the calling thread in ns.
std::int64_t threadCpuNs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return std::int64_t(t.tv_sec) * 1000000000 + std::int64_t(t.tv_nsec);
}

/// CPU time the pool's workers spent in renderer jobs (the calling thread measures its own).
std::atomic<std::int64_t> helperCpuNs{0};

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

using lanes::loadV4;
using lanes::storeV4;
using lanes::toVec4;
using lanes::V4;

bool isOrthographic(const glm::dmat4& p) {
    return p[0][3] == 0.0 && p[1][3] == 0.0 && p[2][3] == 0.0 && p[3][3] == 1.0;
}

glm::dmat4 indexToLocalMatrix(const VoxelObject& object) {
    const glm::dvec3 s = object.spacing();
    const glm::dvec3 origin = -0.5 * glm::dvec3(object.dimensions()) * s + 0.5 * s;
    glm::dmat4 m(1.0);
    m[0][0] = s.x;
    m[1][1] = s.y;
    m[2][2] = s.z;
    m[3] = glm::dvec4(origin, 1.0);
    return m;
}

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

/// One object part's drawing data for a frame.
struct Part {
    VoxelTables tables;
    bool draw = false;
};

struct FrameObject {
    ShearWarpObject* source = nullptr;
    RenderList* list = nullptr;
    Part parts[2];                         // unclipped, clipped
    std::vector<std::uint32_t> sliceStart; // entries of slice k: [sliceStart[k], sliceStart[k+1])
    std::vector<glm::vec4> mipTable;       // value (4096) -> premultiplied colour, MIP
    int sliceStep = 1;                     // draws slices k with k % sliceStep == slicePhase
    int slicePhase = 0;
};

/// First index in [begin, end) whose packed b is >= b (voxels sorted by b). (A branch-free
/// halving measured 10% slower frames on the sphere: the predicted branches let loads run ahead.)
std::uint32_t lowerRow(const std::uint32_t* packed, std::uint32_t begin, std::uint32_t end, int b) {
    if (b <= 0) return begin;
    return std::uint32_t(
        std::partition_point(packed + begin, packed + end,
                             [b](std::uint32_t v) { return int(PackedVoxel::b(v)) < b; }) -
        packed);
}

/// The end of voxel row b that starts at `begin` (voxels sorted by b; the row ends by
/// `limit`; empty when the voxel at `begin` is of a later row). Neighbouring rows are mostly about
/// as long: the end is looked for a few voxels either side of `guess` (the previous row's length)
/// before a search.
std::uint32_t rowEnd(const std::uint32_t* packed, std::uint32_t begin, std::uint32_t limit,
                     unsigned b, std::uint32_t guess) {
    constexpr std::uint32_t kNear = 8;
    if (PackedVoxel::b(packed[begin]) != b) return begin;          // this part has no row b
    std::uint32_t e = std::clamp(begin + guess, begin + 1, limit); // the row has a voxel
    if (PackedVoxel::b(packed[e - 1]) == b) {                      // the row reaches e
        for (const std::uint32_t far = std::min(limit, e + kNear); e < far; ++e)
            if (PackedVoxel::b(packed[e]) != b) return e;
        return e == limit ? e : lowerRow(packed, e, limit, int(b) + 1);
    }
    for (const std::uint32_t near = std::max(begin + 1, e > kNear ? e - kNear : 0); e > near;)
        if (PackedVoxel::b(packed[--e - 1]) == b) return e;
    return lowerRow(packed, begin + 1, e, int(b) + 1);
}

glm::vec4 mipLookup(const std::vector<glm::vec4>& table, float value) {
    const float x = std::clamp(value, 0.0f, 1.0f) * 4095.0f;
    const int i = std::min(int(x), 4094);
    const float f = x - float(i);
    return table[std::size_t(i)] * (1.0f - f) + table[std::size_t(i) + 1] * f;
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
    if (!isOrthographic(view.projection))
        throw Error("ShearWarpVolume renders parallel projections only: use an "
                    "OrthographicCamera (a perspective camera is not supported)");
    if (view.width <= 0 || view.height <= 0) throw Error("shear-warp: empty output size");
    // The buffers of a recycled frame: its image is 0 and its depth 1 outside the rectangle
    // it drew, so only that is cleared (no allocation, no page faults, no full clear).
    ShearWarpFrame frame;
    const std::size_t outPixels = std::size_t(view.width) * std::size_t(view.height);
    if (spare_.image.width == view.width && spare_.image.height == view.height &&
        spare_.image.pixels.size() == outPixels && spare_.windowDepth.size() == outPixels) {
        frame.image = std::move(spare_.image);
        frame.windowDepth = std::move(spare_.windowDepth);
        const glm::ivec4 d = spare_.drawn;
        const std::size_t from = std::size_t(d.y) * std::size_t(view.width);
        const std::size_t to = std::size_t(d.w) * std::size_t(view.width);
        if (d.x < d.z && d.y < d.w) {
            std::fill(frame.image.pixels.begin() + std::ptrdiff_t(from),
                      frame.image.pixels.begin() + std::ptrdiff_t(to), glm::vec4(0.0f));
            if (spare_.wroteDepth)
                std::fill(frame.windowDepth.begin() + std::ptrdiff_t(from),
                          frame.windowDepth.begin() + std::ptrdiff_t(to), 1.0f);
        }
    } else {
        frame.image = Image(view.width, view.height);
        frame.windowDepth.assign(outPixels, 1.0f);
    }
    frame.pickObject = std::move(spare_.pickObject); // refilled below (capacity kept)
    frame.pickSlice = std::move(spare_.pickSlice);
    spare_ = ShearWarpFrame();
    if (objects.empty()) {
        frame.pickObject.clear();
        frame.pickSlice.clear();
        return frame;
    }
    for (const auto& o : objects)
        if (!o.object) throw Error("shear-warp: object without voxels");
    const VoxelObject& first = *objects.front().object;
    for (const auto& o : objects)
        if (o.object->dimensions() != first.dimensions())
            throw Error("shear-warp: the objects of one frame must come from one volume");

    // --- Factorisation -----------------------------------------------------------------------
    const glm::dmat4 toLocal = indexToLocalMatrix(first);
    const glm::dmat4 E = view.modelView * toLocal; // index -> eye
    const glm::dvec3 D = glm::inverse(glm::dmat3(E)) * glm::dvec3(0.0, 0.0, -1.0);
    int c = 0;
    for (int axis = 1; axis < 3; ++axis)
        if (std::abs(D[axis]) > std::abs(D[c])) c = axis;
    const int a = (c + 1) % 3, b = (c + 2) % 3;
    const glm::ivec3 n = first.dimensions();
    const int na = n[a], nb = n[b], nc = n[c];
    const double sa = D[a] / D[c], sb = D[b] / D[c];
    const double ua0 = std::max(0.0, sa * (nc - 1)) + 1.0;
    const double vb0 = std::max(0.0, sb * (nc - 1)) + 1.0;
    const int W = na + int(std::ceil(std::abs(sa) * (nc - 1))) + 3;
    const int H = nb + int(std::ceil(std::abs(sb) * (nc - 1))) + 3;
    const bool ascending = D[c] < 0.0; // back to front: the far end of c first

    auto indexPoint = [&](double u, double v, double k) {
        glm::dvec3 g;
        g[a] = u - ua0 + sa * k;
        g[b] = v - vb0 + sb * k;
        g[c] = k;
        return g;
    };
    auto eyeOf = [&](const glm::dvec3& g) { return glm::dvec3(E * glm::dvec4(g, 1.0)); };
    const glm::dmat4& P = view.projection;
    auto pixelOf = [&](const glm::dvec3& eye) {
        const glm::dvec4 clip = P * glm::dvec4(eye, 1.0);
        return glm::dvec2((clip.x * 0.5 + 0.5) * view.width - 0.5,
                          (0.5 - clip.y * 0.5) * view.height - 0.5);
    };
    const glm::dvec2 p00 = pixelOf(eyeOf(indexPoint(0, 0, 0)));
    const glm::dvec2 p10 = pixelOf(eyeOf(indexPoint(1, 0, 0)));
    const glm::dvec2 p01 = pixelOf(eyeOf(indexPoint(0, 1, 0)));
    glm::dmat3 warp(1.0); // (u, v, 1) -> pixel
    warp[0] = glm::dvec3(p10 - p00, 0.0);
    warp[1] = glm::dvec3(p01 - p00, 0.0);
    warp[2] = glm::dvec3(p00, 1.0);
    const glm::dmat3 unwarp = glm::inverse(warp);
    const double z0 = eyeOf(indexPoint(0, 0, 0)).z;
    const double zu = eyeOf(indexPoint(1, 0, 0)).z - z0;
    const double zv = eyeOf(indexPoint(0, 1, 0)).z - z0;
    const double zk = eyeOf(indexPoint(0, 0, 1)).z - z0;
    auto windowDepthOf = [&](double zEye) { return float(0.5 * (P[2][2] * zEye + P[3][2]) + 0.5); };
    glm::dvec3 step(0.0);
    step[a] = sa;
    step[b] = sb;
    step[c] = 1.0;
    const double ds = glm::length(step * first.spacing());
    const double stepRatio =
        ds / (std::min({first.spacing().x, first.spacing().y, first.spacing().z}));

    frame.outputToIntermediate = unwarp;
    frame.indexToLocal = toLocal;
    frame.axisA = a;
    frame.axisB = b;
    frame.axisC = c;
    frame.shearA = sa;
    frame.shearB = sb;
    frame.originA = ua0;
    frame.originB = vb0;
    frame.stats.principalAxis = c;
    frame.stats.intermediateSize = {W, H};
    const int sliceStep = std::clamp(view.sliceStep, 1, std::max(1, nc));
    frame.stats.sliceStep = sliceStep;
    // --- Objects: lists, clip split, tables ------------------------------------------------
    std::vector<FrameObject> fo(objects.size());
    std::set<RenderList*> lists;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        fo[i].source = &objects[i];
        fo[i].list = &objects[i].object->renderList(c);
        if (!lists.insert(fo[i].list).second)
            throw Error("shear-warp: two objects of a frame share one voxel list");
    }
    std::vector<std::unique_lock<std::mutex>> locks;
    for (RenderList* list : lists)
        locks.emplace_back(list->mutex);

    const glm::dmat3 localToEye(view.modelView);
    bool pureDvr = view.interObject == InterObjectCompositing::DVR;
    for (FrameObject& f : fo) {
        ShearWarpObject& o = *f.source;
        prepare(o, *f.list);
        // Skipped slices: the kept ones sit in the middle of their group of sliceStep (so the
        // pattern is symmetric in the volume) and each stands for sliceStep slices.
        f.sliceStep = o.thinLayer ? 1 : sliceStep;
        f.slicePhase = ((nc - 1) % f.sliceStep) / 2;
        const VoxelLook looks[2] = {o.unclipped, o.clipped};
        for (int part = 0; part < 2; ++part) {
            f.parts[part].draw = looks[part].opacity > 0.0f;
            if (f.parts[part].draw)
                f.parts[part].tables = VoxelTables::build(o, looks[part], stepRatio * f.sliceStep,
                                                          localToEye, view.lightDirection);
        }
        if (o.compositing != ObjectCompositing::DVR) pureDvr = false;
        if (o.compositing == ObjectCompositing::MIP) {
            f.mipTable.resize(4096);
            for (int m = 0; m < 4096; ++m) {
                const double v = double(m) / 4095.0;
                const float alpha =
                    float(std::clamp(o.transferFunction.evaluate(TransferFunction1D::Alpha, v) *
                                         double(o.unclipped.opacity),
                                     0.0, 1.0));
                const glm::vec3 colour(o.transferFunction.evaluate(TransferFunction1D::Red, v),
                                       o.transferFunction.evaluate(TransferFunction1D::Green, v),
                                       o.transferFunction.evaluate(TransferFunction1D::Blue, v));
                f.mipTable[std::size_t(m)] = glm::vec4(colour * alpha, alpha);
            }
        }
        f.sliceStart.assign(std::size_t(nc) + 1, 0);
        const auto& entries = f.list->entries;
        std::size_t e = 0;
        for (int k = 0; k <= nc; ++k) {
            while (e < entries.size() && entries[e].slice() < k)
                ++e;
            f.sliceStart[std::size_t(k)] = std::uint32_t(e);
        }
    }
    frame.stats.fastPath = pureDvr;
    // Pure MIP: every object MIP (and MIP between them), no clipped voxels (they would need
    // their own look), no opaque geometry to test against; the value-sorted voxels exist.
    bool pureMip = view.interObject == InterObjectCompositing::MIP || fo.size() == 1;
    for (FrameObject& f : fo) {
        if (!pureMip) break;
        pureMip = f.source->compositing == ObjectCompositing::MIP && f.parts[0].draw;
        for (const RenderListEntry& e : f.list->entries)
            pureMip = pureMip && e.firstClipped == e.lastInSlice;
    }
    pureMip = pureMip && view.valueSortedMip && view.opaqueWindowDepth.empty();
    std::vector<const ValueSortedVoxels*> sortedVoxels;
    for (FrameObject& f : fo)
        if (pureMip) {
            sortedVoxels.push_back(f.source->object->valueSorted());
            pureMip = sortedVoxels.back() != nullptr;
        }
    frame.stats.valueSortedMip = pureMip;
    // --- Buffers ---------------------------------------------------------------------------
    // Sized here (never shrunk, so a size change fills nothing serially); each band's thread
    // clears its own rows (initRows), in parallel and into its own cache.
    const std::size_t pixels = std::size_t(W) * std::size_t(H);
    const bool twoLevel = !pureDvr && !pureMip; // the value-sorted MIP has its own buffers
    bool anySurface = false;                    // depth is written only by Surface objects
    for (const FrameObject& f : fo)
        anySurface = anySurface || f.source->compositing == ObjectCompositing::Surface;
    const bool hasLimit = !view.opaqueWindowDepth.empty();
    if (hasLimit &&
        view.opaqueWindowDepth.size() != std::size_t(view.width) * std::size_t(view.height))
        throw Error("shear-warp: opaque depth buffer of the wrong size");
    auto ensure = [pixels](auto& buffer) {
        if (buffer.size() < pixels) buffer.resize(pixels);
    };
    ensure(global_);
    if (twoLevel) {
        ensure(local_);
        ensure(localValue_);
        ensure(localDepth_);
        ensure(localObject_);
    }
    if (anySurface) ensure(hitDepth_);
    if (pureDvr) {
        ensure(nextOpen_);
        opaqueCount_.assign(std::size_t(H), 0);
    }
    if (hasLimit) ensure(limit_);
    frame.pickObject.resize(pixels);
    frame.pickSlice.resize(pixels);
    auto initRows = [&](int r0, int r1) {
        const auto p0 = std::ptrdiff_t(r0) * W, p1 = std::ptrdiff_t(r1) * W;
        std::fill(global_.begin() + p0, global_.begin() + p1, glm::vec4(0.0f));
        if (twoLevel) {
            std::fill(local_.begin() + p0, local_.begin() + p1, glm::vec4(0.0f));
            std::fill(localValue_.begin() + p0, localValue_.begin() + p1, -1.0f);
            std::fill(localDepth_.begin() + p0, localDepth_.begin() + p1, 1.0f);
            std::fill(localObject_.begin() + p0, localObject_.begin() + p1, std::int16_t(-1));
        }
        if (anySurface) std::fill(hitDepth_.begin() + p0, hitDepth_.begin() + p1, 1.0f);
        std::fill(frame.pickObject.begin() + p0, frame.pickObject.begin() + p1, std::int16_t(-1));
        std::fill(frame.pickSlice.begin() + p0, frame.pickSlice.begin() + p1, 0.0f);
        for (int v = r0; v < r1; ++v) {
            const std::size_t row = std::size_t(v) * std::size_t(W);
            if (pureDvr)
                for (int u = 0; u < W; ++u)
                    nextOpen_[row + std::size_t(u)] = u;
            if (!hasLimit) continue;
            // Per intermediate pixel: a sample at slice k is in front of the opaque surface
            // when zk * k > limit (eye z grows towards the viewer).
            for (int u = 0; u < W; ++u) {
                float& limit = limit_[row + std::size_t(u)];
                limit = -std::numeric_limits<float>::infinity();
                const glm::dvec3 px = warp * glm::dvec3(u, v, 1.0);
                const int x = int(std::lround(px.x)), y = int(std::lround(px.y));
                if (x < 0 || y < 0 || x >= view.width || y >= view.height) continue;
                const float d = view.opaqueWindowDepth[std::size_t(y) * std::size_t(view.width) +
                                                       std::size_t(x)];
                if (d >= 1.0f) continue;
                const double zOpaque = ((2.0 * d - 1.0) - P[3][2]) / P[2][2];
                limit = float(zOpaque - (z0 + zu * u + zv * v));
            }
        }
    };

    const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
    const int threads =
        std::clamp(view.threads > 0 ? view.threads : int(hardware), 1, std::max(1, H / 4));
    bands_.resize(std::size_t(threads));
    const SimdLevel simd = bestSimdLevel();
    // --- Compositing, one band of intermediate rows per thread ------------------------------
    const InterObjectCompositing inter = view.interObject;
    auto flush = [&](std::size_t p) {
        const int oi = localObject_[p];
        if (oi < 0) return;
        const FrameObject& f = fo[std::size_t(oi)];
        glm::vec4 layer = local_[p];
        if (f.source->compositing == ObjectCompositing::MIP)
            layer =
                localValue_[p] >= 0.0f ? mipLookup(f.mipTable, localValue_[p]) : glm::vec4(0.0f);
        if (f.source->compositing == ObjectCompositing::Surface && layer.w >= kSurfaceAlpha) {
            layer = glm::vec4(glm::vec3(layer) / layer.w, 1.0f);
            if (localDepth_[p] < 1.0f) hitDepth_[p] = localDepth_[p];
        }
        glm::vec4& g = global_[p];
        if (inter == InterObjectCompositing::DVR)
            g = layer + (1.0f - layer.w) * g;
        else
            g = glm::max(g, layer);
        localObject_[p] = -1;
        local_[p] = glm::vec4(0.0f);
        localValue_[p] = -1.0f;
        localDepth_[p] = 1.0f;
    };

    // Per band: the intermediate pixels composited, (u0, v0, u1, v1); all others stay empty.
    std::vector<glm::ivec4> touchedBoxes(std::size_t(threads), glm::ivec4(W, H, 0, 0)); // empty
    if (pureMip) {
        // Nearest intermediate pixel of voxel (a, b) of slice k: a + round(tu), b + round(tv),
        // as one offset per slice; slices left out while interacting have none.
        constexpr std::int64_t kSkip = std::numeric_limits<std::int64_t>::min();
        std::vector<std::int64_t> sliceOffset(static_cast<std::size_t>(nc));
        const int bits[3] = {0, ValueSortedVoxels::kBitsI,
                             ValueSortedVoxels::kBitsI + ValueSortedVoxels::kBitsJ};
        const std::uint32_t masks[3] = {(1u << ValueSortedVoxels::kBitsI) - 1,
                                        (1u << ValueSortedVoxels::kBitsJ) - 1,
                                        (1u << ValueSortedVoxels::kBitsK) - 1};
        parallelFor(*pool_, threads,
                    [&](int t) { initRows(H * t / threads, H * (t + 1) / threads); });
        mipValue_.resize(std::size_t(threads));
        mipSlice_.resize(std::size_t(threads));
        for (std::size_t oi = 0; oi < fo.size(); ++oi) {
            const FrameObject& f = fo[oi];
            const ValueSortedVoxels& sorted = *sortedVoxels[oi];
            for (int k = 0; k < nc; ++k)
                sliceOffset[std::size_t(k)] = k % f.sliceStep != f.slicePhase
                                                  ? kSkip
                                                  : std::int64_t(std::lround(vb0 - sb * k)) * W +
                                                        std::int64_t(std::lround(ua0 - sa * k));
            // Values below the first one the table shows cannot be a shown maximum.
            int firstShown = 0;
            while (firstShown < 4096 && !(f.mipTable[std::size_t(firstShown)].w > 0.0f))
                ++firstShown;
            const std::uint32_t begin = sorted.start[std::size_t(firstShown)];
            const std::uint32_t end = sorted.start[4096];
            // Each thread a run of the order, into its own buffers: later runs hold larger
            // values, so the merge takes the last thread that wrote a pixel.
            parallelFor(*pool_, threads, [&](int t) {
                std::vector<std::uint16_t>& value = mipValue_[std::size_t(t)];
                std::vector<std::uint16_t>& slice = mipSlice_[std::size_t(t)];
                value.assign(pixels, 0);
                slice.resize(pixels);
                const std::uint32_t from =
                    begin + std::uint32_t(std::uint64_t(end - begin) * std::uint64_t(t) /
                                          std::uint64_t(threads));
                const std::uint32_t to =
                    begin + std::uint32_t(std::uint64_t(end - begin) * std::uint64_t(t + 1) /
                                          std::uint64_t(threads));
                const std::uint32_t* position = sorted.position.data();
                std::uint64_t drawn = 0;
                const int shiftA = bits[a], shiftB = bits[b], shiftC = bits[c];
                const std::uint32_t maskA = masks[a], maskB = masks[b], maskC = masks[c];
                int m = int(std::upper_bound(sorted.start.begin(), sorted.start.end(), from) -
                            sorted.start.begin()) -
                        1;
                for (std::uint32_t i = from; i < to;) {
                    while (sorted.start[std::size_t(m) + 1] <= i)
                        ++m;
                    const std::uint32_t stop = std::min(to, sorted.start[std::size_t(m) + 1]);
                    const auto stored = std::uint16_t(m + 1);
                    for (; i < stop; ++i) {
                        const std::uint32_t pos = position[i];
                        const unsigned kc = (pos >> shiftC) & maskC;
                        const std::int64_t offset = sliceOffset[kc];
                        if (offset == kSkip) continue;
                        ++drawn;
                        const std::size_t p =
                            std::size_t(std::int64_t((pos >> shiftB) & maskB) * W +
                                        std::int64_t((pos >> shiftA) & maskA) + offset);
                        value[p] = stored;
                        slice[p] = std::uint16_t(kc);
                    }
                }
                bands_[std::size_t(t)].voxels = drawn;
            });
            for (BandScratch& s : bands_)
                frame.stats.voxelsTouched += std::exchange(s.voxels, 0);
            // Merge by rows: the object's layer C(v) A(v), MIP with what is there.
            parallelFor(*pool_, threads, [&](int t) {
                const std::size_t p0 = std::size_t(H * t / threads) * std::size_t(W);
                const std::size_t p1 = std::size_t(H * (t + 1) / threads) * std::size_t(W);
                for (std::size_t p = p0; p < p1; ++p) {
                    int best = 0, bestSlice = 0;
                    for (int u = threads - 1; u >= 0 && best == 0; --u)
                        if (const std::uint16_t v = mipValue_[std::size_t(u)][p]; v != 0) {
                            best = v;
                            bestSlice = mipSlice_[std::size_t(u)][p];
                        }
                    if (best == 0) continue;
                    const glm::vec4 layer = f.mipTable[std::size_t(best - 1)];
                    glm::vec4& g = global_[p];
                    if (layer.w >= kPickAlpha && layer.w > g.w) {
                        frame.pickObject[p] = std::int16_t(oi);
                        frame.pickSlice[p] = float(bestSlice);
                    }
                    g = glm::max(g, layer);
                }
            });
        }
        touchedBoxes.assign(1, glm::ivec4(0, 0, W, H));
        for (BandScratch& s : bands_)
            s.hidden = s.entries = 0; // (voxels counted above)
    }
    // Bands are taken from a counter, kBandsPerThread per thread: a thread whose core is slowed
    // (a shared machine) takes fewer. Each band boundary splats one voxel row twice per slice.
    const int bandCount =
        pureMip ? 0 : std::clamp(threads * kBandsPerThread, 1, std::max(1, H / 4));
    std::atomic<int> nextBand{0};
    if (!pureMip) touchedBoxes.assign(std::size_t(bandCount), glm::ivec4(W, H, 0, 0));
    parallelFor(*pool_, pureMip ? 1 : threads, [&](int t) {
        if (pureMip) return; // drawn above
        BandScratch& s = bands_[std::size_t(t)];
        s.lines[0].assign(std::size_t(W) + 1, glm::vec4(0.0f));
        s.lines[1].assign(std::size_t(W) + 1, glm::vec4(0.0f));
        s.voxels = 0;
        s.hidden = 0;
        s.entries = 0;
        for (int band = nextBand++; band < bandCount; band = nextBand++) {
            const int r0 = H * band / bandCount, r1 = H * (band + 1) / bandCount;
            const int bandRows = r1 - r0;
            initRows(r0, r1);
            glm::ivec4 touched(W, H, 0, 0);
            auto touch = [&touched](int row, int lo, int hi) {
                touched = glm::ivec4(std::min(touched.x, lo), std::min(touched.y, row),
                                     std::max(touched.z, hi), std::max(touched.w, row + 1));
            };

            for (int stepIndex = 0; stepIndex < nc; ++stepIndex) {
                // Back to front; pure DVR runs front to back for early ray termination.
                const int k = (ascending != pureDvr) ? stepIndex : nc - 1 - stepIndex;
                const double tu = ua0 - sa * k, tv = vb0 - sb * k;
                const int iu0 = int(std::floor(tu)), iv0 = int(std::floor(tv));
                const float fu = float(tu - iu0), fv = float(tv - iv0);
                const float zSlice = float(zk * k);
                const float sliceDepth = windowDepthOf(z0 + zk * k); // plus zu*u + zv*v per pixel

                for (std::size_t oi = 0; oi < fo.size(); ++oi) {
                    FrameObject& f = fo[oi];
                    if (k % f.sliceStep != f.slicePhase) continue;
                    const std::uint32_t e0 = f.sliceStart[std::size_t(k)];
                    const std::uint32_t e1 = f.sliceStart[std::size_t(k) + 1];
                    if (e0 == e1) continue;
                    const bool mip = f.source->compositing == ObjectCompositing::MIP;
                    const RenderList& list = *f.list;
                    const std::uint32_t* packed = list.packed.data();
                    const std::uint16_t* values = list.value12.data();

                    // One resampled sample of this object's slice composited at band pixel p
                    // (two-level compositing; pure DVR has UnderComposite).
                    auto compositePixel = [&](std::size_t p, const glm::vec4& sample) {
                        if (hasLimit && !(zSlice > limit_[p])) return; // behind opaque geometry
                        if (localObject_[p] != std::int16_t(oi)) {
                            flush(p);
                            localObject_[p] = std::int16_t(oi);
                        }
                        switch (f.source->compositing) {
                        case ObjectCompositing::DVR:
                            local_[p] = sample + (1.0f - sample.w) * local_[p];
                            if (sample.w >= kPickAlpha) {
                                frame.pickObject[p] = std::int16_t(oi);
                                frame.pickSlice[p] = float(k);
                            }
                            break;
                        case ObjectCompositing::MIP:
                            if (sample.x > localValue_[p]) {
                                localValue_[p] = sample.x;
                                if (mipLookup(f.mipTable, sample.x).w >= kPickAlpha) {
                                    frame.pickObject[p] = std::int16_t(oi);
                                    frame.pickSlice[p] = float(k);
                                }
                            }
                            break;
                        case ObjectCompositing::Surface:
                            // Accumulated like DVR within the run; opaque at the flush when the
                            // run's alpha reaches kSurfaceAlpha. Its depth: the front-most sample
                            // that is substantially opaque.
                            local_[p] = sample + (1.0f - sample.w) * local_[p];
                            if (sample.w >= kPickAlpha) {
                                frame.pickObject[p] = std::int16_t(oi);
                                frame.pickSlice[p] = float(k);
                            }
                            if (sample.w >= kSurfaceDepthAlpha) {
                                const std::size_t u = p % std::size_t(W), vv = p / std::size_t(W);
                                localDepth_[p] =
                                    sliceDepth +
                                    float(0.5 * P[2][2] * (zu * double(u) + zv * double(vv)));
                            }
                            break;
                        }
                    };

                    // The first column >= c of band row `row` whose pixel is not yet opaque (W:
                    // none); rows outside the band count as opaque (another thread's). Opaque
                    // pixels link to the next column, followed with path halving (Lacroute's
                    // opaque-pixel links).
                    auto firstOpen = [&](int row, int c) -> int {
                        if (row < 0 || row >= bandRows) return W + 1;
                        std::int32_t* open = nextOpen_.data() +
                                             (std::size_t(row) + std::size_t(r0)) * std::size_t(W);
                        while (c < W && open[c] != c) {
                            const int next = open[c];
                            if (next < W) open[c] = open[next];
                            c = next;
                        }
                        return c;
                    };

                    for (std::uint32_t ei = e0; ei < e1; ++ei) {
                        const RenderListEntry& e = list.entries[ei];
                        const int rowBase = int(e.offset.y) + iv0 - r0; // band row of b = 0
                        const int colBase = int(e.offset.x) + iu0;
                        // In-piece coordinates of the volume's side faces (256: not in this piece).
                        // Data is clamped to the edge up to the box face, half a voxel out, and
                        // nothing lies beyond (docs/SCENE-FORMAT.md section 4): the pixel on a face voxel's
                        // outer side takes its full value inside the face, none outside.
                        const unsigned edgeA0 = e.offset.x == 0 ? 0u : 256u;
                        const unsigned edgeB0 = e.offset.y == 0 ? 0u : 256u;
                        const unsigned edgeA1 = unsigned(na - 1 - int(e.offset.x)) < 256u
                                                    ? unsigned(na - 1 - int(e.offset.x))
                                                    : 256u;
                        const unsigned edgeB1 = unsigned(nb - 1 - int(e.offset.y)) < 256u
                                                    ? unsigned(nb - 1 - int(e.offset.y))
                                                    : 256u;
                        const float edgeA0Weight = fu <= 0.5f ? 1.0f : 0.0f;
                        const float edgeA1Weight = fu >= 0.5f ? 1.0f : 0.0f;
                        // Weight of voxel row b's line in its own intermediate row and the next.
                        auto ownWeight = [&](unsigned b) {
                            return b == edgeB0 ? (fv <= 0.5f ? 1.0f : 0.0f) : 1.0f - fv;
                        };
                        auto nextWeight = [&](unsigned b) {
                            return b == edgeB1 ? (fv >= 0.5f ? 1.0f : 0.0f) : fv;
                        };

                        // The drawn parts, restricted to the voxel rows whose two intermediate
                        // rows (row, row + 1) meet the band.
                        std::uint32_t at[2] = {0, 0}, end[2] = {0, 0};
                        std::uint32_t rowLength[2] = {0, 0}; // of each part's last row drawn
                        const std::uint32_t ranges[2][2] = {{e.first, e.last},
                                                            {e.firstClipped, e.lastClipped}};
                        for (int part = 0; part < 2; ++part) {
                            if (!f.parts[part].draw || ranges[part][0] >= ranges[part][1]) continue;
                            at[part] =
                                lowerRow(packed, ranges[part][0], ranges[part][1], -1 - rowBase);
                            end[part] =
                                lowerRow(packed, at[part], ranges[part][1], bandRows - rowBase);
                            s.voxels += end[part] - at[part];
                        }
                        if (at[0] == end[0] && at[1] == end[1]) continue;
                        ++s.entries;

                        // Row by row: a voxel row b is resampled along a into a line buffer; the
                        // intermediate row b + rowBase blends line b and line b - 1 with the
                        // slice's weights. Lines keep the column range they touched.
                        struct LineState {
                            glm::vec4* px;
                            int lo, hi;
                        };
                        LineState cur{s.lines[0].data(), W, 0}, prev{s.lines[1].data(), W, 0};
                        int prevB = -2;
                        cur.lo = prev.lo = std::numeric_limits<int>::max();
                        // Composites intermediate band row `row` from line a (weight wa) and line b
                        // (weight wb; either may be absent) and clears line b: every caller is done
                        // with it.
                        auto compositeRow = [&](int row, const LineState* a, float wa, LineState* b,
                                                float wb) {
                            const int lo = std::min(a ? a->lo : W, b ? b->lo : W);
                            const int hi = std::max(a ? a->hi : 0, b ? b->hi : 0);
                            glm::vec4* pb = b ? b->px : nullptr;
                            // Line b is done with after this row: zeros where it was written
                            // (one memset, not a store per pixel), then empty.
                            auto clearB = [&] {
                                if (!b) return;
                                if (b->lo < b->hi)
                                    std::memset(static_cast<void*>(pb + b->lo), 0,
                                                std::size_t(b->hi - b->lo) * sizeof(glm::vec4));
                                b->lo = std::numeric_limits<int>::max();
                                b->hi = 0;
                            };
                            if (row < 0 || row >= bandRows || lo >= hi) {
                                clearB();
                                return;
                            }
                            touch(row + r0, lo, hi);
                            const std::size_t rowStart =
                                (std::size_t(row) + std::size_t(r0)) * std::size_t(W);
                            const glm::vec4* pa = a ? a->px : nullptr;
                            if (pureDvr) { // the hot path: front to back ("under")
                                const UnderRow target{global_.data() + rowStart,
                                                      frame.pickObject.data() + rowStart,
                                                      frame.pickSlice.data() + rowStart,
                                                      nextOpen_.data() + rowStart,
                                                      hasLimit ? limit_.data() + rowStart : nullptr,
                                                      &opaqueCount_[std::size_t(row + r0)],
                                                      std::int16_t(oi),
                                                      float(k),
                                                      zSlice};
                                UnderComposite::composite(simd, target, pa, wa, pb, wb, lo, hi);
                            } else {
                                // The resampled sample, as glm computes the sum of the weighted
                                // lines, component by component.
                                for (int c = lo; c < hi; ++c) {
                                    const V4 sample = pa && pb
                                                          ? wa * loadV4(pa[c]) + wb * loadV4(pb[c])
                                                      : pa ? wa * loadV4(pa[c])
                                                           : wb * loadV4(pb[c]);
                                    if (sample[3] <= 0.0f) continue;
                                    compositePixel(rowStart + std::size_t(c), toVec4(sample));
                                }
                            }
                            clearB();
                        };

                        while (at[0] < end[0] || at[1] < end[1]) {
                            unsigned b = 256;
                            for (int part = 0; part < 2; ++part)
                                if (at[part] < end[part])
                                    b = std::min(b, PackedVoxel::b(packed[at[part]]));
                            if (prevB >= 0 && prevB != int(b) - 1) { // a gap: prev's next row alone
                                compositeRow(prevB + 1 + rowBase, nullptr, 0.0f, &prev,
                                             nextWeight(unsigned(prevB)));
                                prevB = -2;
                            }
                            // Line b: every voxel of row b of both parts, split between its two
                            // columns (those whose 4 pixels are all opaque skipped).
                            int hiddenBefore = -1, visibleThrough = -1;
                            // Only rows that both have stopped pixels can hide a voxel.
                            const int rowA = int(b) + rowBase, rowB = rowA + 1;
                            const bool inA = rowA >= 0 && rowA < bandRows;
                            const bool inB = rowB >= 0 && rowB < bandRows;
                            const bool ertActive =
                                pureDvr && (!inA || opaqueCount_[std::size_t(rowA + r0)] > 0) &&
                                (!inB || opaqueCount_[std::size_t(rowB + r0)] > 0);
                            const std::int32_t* openA =
                                ertActive && inA
                                    ? nextOpen_.data() + std::size_t(rowA + r0) * std::size_t(W)
                                    : nullptr;
                            const std::int32_t* openB =
                                ertActive && inB
                                    ? nextOpen_.data() + std::size_t(rowB + r0) * std::size_t(W)
                                    : nullptr;
                            for (int part = 0; part < 2; ++part) {
                                if (at[part] >= end[part]) continue;
                                const VoxelTables& tables = f.parts[part].tables;
                                const glm::vec4* rgba = tables.rgba.data();
                                const std::uint8_t* lut2 = tables.lut2.data();
                                const bool direct = tables.kernel == VoxelTables::Kernel::Direct;
                                const std::uint32_t mask = tables.mask;
                                // Part 0 writes into the empty line: the share a voxel gives its
                                // right column waits in `pending` until the next voxel adds its own
                                // share (0 + x + y, as accumulating in the line would give) or a
                                // gap stores it; no voxel reloads what the previous one stored.
                                // Part 1 adds onto part 0's shares in the line. One loop per (part
                                // 0 or 1, early ray termination, lookup kind): the invariant
                                // branches leave the per-voxel loop and its values are locals the
                                // compiler keeps in registers.
                                auto splat = [&](auto freshTag, auto ertTag, auto kindTag) {
                                    constexpr bool fresh = decltype(freshTag)::value;
                                    constexpr bool ert = decltype(ertTag)::value;
                                    constexpr int kind =
                                        decltype(kindTag)::value; // 0 MIP, 1 direct
                                    const std::uint32_t* const pk = packed;
                                    glm::vec4* const line = cur.px;
                                    const int cb = colBase;
                                    const unsigned ea0 = edgeA0, ea1 = edgeA1;
                                    const float ew0 = edgeA0Weight,
                                                ew1 = edgeA1Weight; // broadcast:
                                    const V4 left = V4{} + (1.0f - fu), right = V4{} + fu;
                                    const V4 edge0 = V4{} + ew0, edge1 = V4{} + ew1;
                                    // Voxels with innerLo <= a <= innerLo + innerSpan are no
                                    // face's.
                                    const int lowest = ea0 == 0 ? 1 : 0;
                                    const int highest = ea1 < 256u ? int(ea1) - 1 : 255;
                                    const unsigned innerLo =
                                        highest >= lowest ? unsigned(lowest) : 512u;
                                    const unsigned innerSpan =
                                        highest >= lowest ? unsigned(highest - lowest) : 0u;
                                    V4 pending{};
                                    int pendingCol = -2;
                                    int firstCol = std::numeric_limits<int>::max(), lastCol = -1;
                                    std::uint32_t i = at[part];
                                    // Row b ends within 256 voxels (one per a): found once, not
                                    // tested per voxel; neighbouring rows are mostly as long.
                                    const std::uint32_t stop = rowEnd(
                                        pk, i, std::min(end[part], i + 256u), b, rowLength[part]);
                                    rowLength[part] = stop - i;
                                    for (; i < stop; ++i) {
                                        const std::uint32_t v = pk[i];
                                        V4 colour;
                                        if constexpr (kind == 0)
                                            colour = V4{float(values[i]) * (1.0f / 4095.0f), 0.0f,
                                                        0.0f, 1.0f};
                                        else if constexpr (kind == 1)
                                            colour =
                                                loadV4(rgba[PackedVoxel::attributes16(v) & mask]);
                                        else
                                            colour = loadV4(rgba[(PackedVoxel::second4(v) << 8) |
                                                                 lut2[PackedVoxel::main12(v)]]);
                                        // A transparent voxel adds zero shares: only the
                                        // accumulating part and hidden-voxel skipping (its range
                                        // must not grow) need to leave it out.
                                        if ((!fresh || ert) && colour[3] <= 0.0f) continue;
                                        const unsigned va = PackedVoxel::a(v);
                                        const int col = int(va) + cb;
                                        if constexpr (ert) { // skip hidden voxels
                                            if (col < hiddenBefore) {
                                                ++s.hidden;
                                                continue;
                                            }
                                            if (col > visibleThrough) {
                                                const bool anyOpen =
                                                    (openA && (openA[col] == col ||
                                                               openA[col + 1] == col + 1)) ||
                                                    (openB && (openB[col] == col ||
                                                               openB[col + 1] == col + 1));
                                                if (!anyOpen) {
                                                    ++s.hidden;
                                                    const int row = int(b) + rowBase;
                                                    hiddenBefore =
                                                        std::min(firstOpen(row, col),
                                                                 firstOpen(row + 1, col)) -
                                                        1;
                                                    continue;
                                                }
                                                visibleThrough = col;
                                            }
                                        }
                                        // Its shares of the two columns; face voxels (only
                                        // a row's first or last: sorted by a) weigh their own.
                                        V4 share0 = left * colour, share1 = right * colour;
                                        if (va - innerLo > innerSpan) [[unlikely]] {
                                            if (va == ea0) share0 = edge0 * colour;
                                            if (va == ea1) share1 = edge1 * colour;
                                        }
                                        if constexpr (fresh) {
                                            if (col == pendingCol) {
                                                storeV4(line[col], pending + share0);
                                            } else {
                                                if (pendingCol >= 0)
                                                    storeV4(line[pendingCol], pending);
                                                else
                                                    firstCol = col; // ascending: the row's first
                                                storeV4(line[col], share0);
                                            }
                                            pending = share1;
                                            pendingCol = col + 1;
                                        } else {
                                            firstCol = std::min(firstCol, col);
                                            lastCol = col;
                                            storeV4(line[col], loadV4(line[col]) + share0);
                                            storeV4(line[col + 1], loadV4(line[col + 1]) + share1);
                                        }
                                    }
                                    if (pendingCol >= 0) {
                                        storeV4(line[pendingCol], pending);
                                        lastCol = pendingCol - 1;
                                    }
                                    if (lastCol >= 0) {
                                        cur.lo = std::min(cur.lo, firstCol);
                                        cur.hi = std::max(cur.hi, lastCol + 2);
                                    }
                                    at[part] = i;
                                };
                                auto withKind = [&](auto freshTag, auto ertTag) {
                                    if (mip)
                                        splat(freshTag, ertTag, std::integral_constant<int, 0>{});
                                    else if (direct)
                                        splat(freshTag, ertTag, std::integral_constant<int, 1>{});
                                    else
                                        splat(freshTag, ertTag, std::integral_constant<int, 2>{});
                                };
                                auto withErt = [&](auto freshTag) {
                                    if (ertActive)
                                        withKind(freshTag, std::true_type{});
                                    else
                                        withKind(freshTag, std::false_type{});
                                };
                                if (part == 0)
                                    withErt(std::true_type{});
                                else
                                    withErt(std::false_type{});
                            }
                            compositeRow(int(b) + rowBase, &cur, ownWeight(b),
                                         prevB >= 0 ? &prev : nullptr,
                                         prevB >= 0 ? nextWeight(unsigned(prevB)) : 0.0f);
                            std::swap(cur, prev);
                            prevB = int(b);
                        }
                        if (prevB >= 0)
                            compositeRow(prevB + 1 + rowBase, nullptr, 0.0f, &prev,
                                         nextWeight(unsigned(prevB)));
                    }
                }
            }
            if (!pureDvr)
                for (std::size_t p = std::size_t(r0) * std::size_t(W);
                     p < std::size_t(r1) * std::size_t(W); ++p)
                    flush(p);
            touchedBoxes[std::size_t(band)] = touched;
        }
    });
    for (const BandScratch& s : bands_) {
        frame.stats.voxelsTouched += s.voxels;
        frame.stats.voxelsHidden += s.hidden;
        frame.stats.entriesDrawn += s.entries;
    }
    locks.clear();
    // --- Warp: bilinear from the intermediate image ------------------------------------------
    auto fetch = [&](int u, int v) {
        if (u < 0 || v < 0 || u >= W || v >= H) return glm::vec4(0.0f);
        return global_[std::size_t(v) * std::size_t(W) + std::size_t(u)];
    };
    // Between the outermost voxel centres and the box faces the data is clamped to the edge
    // (docs/SCENE-FORMAT.md section 4). Along an unsheared intermediate axis the rays are parallel to
    // the box's side faces: a ray within half a voxel outside the outermost voxel column sees
    // that column's values all along, so the warp clamps to it (exact). Along a sheared axis the
    // silhouette is slanted and clamping would smear it; there the warp blends towards empty
    // pixels (an error confined to the half-voxel border, measured in README.md).
    const bool clampU = std::abs(sa) < 1e-9, clampV = std::abs(sb) < 1e-9;
    const double uLo = ua0, uHi = ua0 + (na - 1), vLo = vb0, vHi = vb0 + (nb - 1);
    const int outThreads = std::clamp(threads, 1, std::max(1, view.height / 8));
    const glm::dvec2 perPixel(unwarp[0]); // (u, v) per output pixel along x
    // Only output pixels whose bilinear footprint meets the composited part of the intermediate
    // image can differ from 0 (and depth 1): per output row the warp visits the x range whose
    // (u, v) lies within that box, widened by 2 for the clamping above (it moves (u, v) by
    // half a pixel at most), the footprint and rounding. The pixels skipped would be 0 exactly.
    glm::ivec4 box(W, H, 0, 0);
    for (const glm::ivec4& b : touchedBoxes)
        box = glm::ivec4(glm::min(glm::ivec2(box), glm::ivec2(b)),
                         glm::max(glm::ivec2(box.z, box.w), glm::ivec2(b.z, b.w)));
    const glm::dvec4 near(box.x - 2.0, box.y - 2.0, box.z + 1.0, box.w + 1.0);
    std::vector<glm::ivec4> drawnRows(std::size_t(outThreads),
                                      glm::ivec4(view.width, view.height, 0, 0));
    if (box.x < box.z && box.y < box.w)
        parallelFor(*pool_, outThreads, [&](int t) {
            const int y0 = view.height * t / outThreads, y1 = view.height * (t + 1) / outThreads;
            const glm::vec4* image = global_.data();
            glm::ivec4& drawn = drawnRows[std::size_t(t)];
            for (int y = y0; y < y1; ++y) {
                const glm::dvec2 rowStart(unwarp * glm::dvec3(0.0, y, 1.0));
                double xFrom = 0.0, xTo = view.width;
                for (int i = 0; i < 2; ++i) { // lo <= rowStart[i] + x perPixel[i] <= hi
                    const double lo = near[i], hi = near[i + 2];
                    if (std::abs(perPixel[i]) < 1e-12) {
                        if (rowStart[i] < lo || rowStart[i] > hi) xTo = -1.0;
                        continue;
                    }
                    double a0 = (lo - rowStart[i]) / perPixel[i],
                           a1 = (hi - rowStart[i]) / perPixel[i];
                    if (a0 > a1) std::swap(a0, a1);
                    xFrom = std::max(xFrom, a0);
                    xTo = std::min(xTo, a1);
                }
                if (xFrom > xTo) continue;
                const int xBegin = std::max(0, int(std::floor(xFrom)) - 1);
                const int xEnd = std::min(view.width, int(std::ceil(xTo)) + 2);
                if (xBegin >= xEnd) continue;
                drawn = glm::ivec4(std::min(drawn.x, xBegin), std::min(drawn.y, y),
                                   std::max(drawn.z, xEnd), std::max(drawn.w, y + 1));
                glm::vec4* out =
                    frame.image.pixels.data() + std::size_t(y) * std::size_t(view.width);
                for (int x = xBegin; x < xEnd; ++x) {
                    glm::dvec2 uv = rowStart + double(x) * perPixel;
                    if (clampU) {
                        if (uv.x < uLo - 0.5 || uv.x > uHi + 0.5) continue;
                        uv.x = std::clamp(uv.x, uLo, uHi);
                    }
                    if (clampV) {
                        if (uv.y < vLo - 0.5 || uv.y > vHi + 0.5) continue;
                        uv.y = std::clamp(uv.y, vLo, vHi);
                    }
                    if (uv.x <= -1.0 || uv.y <= -1.0 || uv.x >= W || uv.y >= H) continue;
                    const int u = int(uv.x + 1.0) - 1, v = int(uv.y + 1.0) - 1; // floor, uv > -1
                    const float wu = float(uv.x - u), wv = float(uv.y - v);
                    if (u >= 0 && v >= 0 && u + 1 < W && v + 1 < H) { // inside: no bounds checks
                        const glm::vec4* p =
                            image + std::size_t(v) * std::size_t(W) + std::size_t(u);
                        storeV4(out[x], (loadV4(p[0]) * (1 - wu) + loadV4(p[1]) * wu) * (1 - wv) +
                                            (loadV4(p[W]) * (1 - wu) + loadV4(p[W + 1]) * wu) * wv);
                    } else {
                        out[x] = (fetch(u, v) * (1 - wu) + fetch(u + 1, v) * wu) * (1 - wv) +
                                 (fetch(u, v + 1) * (1 - wu) + fetch(u + 1, v + 1) * wu) * wv;
                    }
                    if (anySurface) {
                        const int nu = int(std::lround(uv.x)), nv = int(std::lround(uv.y));
                        if (nu >= 0 && nv >= 0 && nu < W && nv < H)
                            frame.windowDepth[std::size_t(y) * std::size_t(view.width) +
                                              std::size_t(x)] =
                                hitDepth_[std::size_t(nv) * std::size_t(W) + std::size_t(nu)];
                    }
                }
            }
        });
    frame.drawn = glm::ivec4(view.width, view.height, 0, 0);
    for (const glm::ivec4& d : drawnRows)
        frame.drawn =
            glm::ivec4(glm::min(glm::ivec2(frame.drawn), glm::ivec2(d)),
                       glm::max(glm::ivec2(frame.drawn.z, frame.drawn.w), glm::ivec2(d.z, d.w)));
    if (frame.drawn.x >= frame.drawn.z || frame.drawn.y >= frame.drawn.w)
        frame.drawn = glm::ivec4(0);
    frame.wroteDepth = anySurface && frame.drawn.x < frame.drawn.z;
    return frame;
}

void ShearWarpRenderer::recycle(ShearWarpFrame&& frame) {
    spare_ = std::move(frame);
}

std::optional<ShearWarpPick> ShearWarpRenderer::pick(const ShearWarpFrame& frame, int x, int y) {
    const glm::ivec2 size = frame.stats.intermediateSize;
    if (size.x <= 0) return std::nullopt;
    const glm::dvec3 uv = frame.outputToIntermediate * glm::dvec3(x, y, 1.0);
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
