// The slicer's error on a sample of the volume's own rays (see SlabErrorModel.h).
#include <volsg/slicing/SlabErrorModel.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <thread>
#include <tuple>

#include <volsg/core/WorkerPool.h>
#include <volsg/slicing/EmptyCells.h>
#include <volsg/slicing/EmptyRuns.h>
#include <volsg/slicing/ProxyPlaneCutter.h>

namespace volsg {

bool SlabQuadrature::operator<(const SlabQuadrature& o) const {
    return std::tie(planeSpacingL0, samplesPerPlane, preIntegrated, peaks, refinePeaks) <
           std::tie(o.planeSpacingL0, o.samplesPerPlane, o.preIntegrated, o.peaks, o.refinePeaks);
}

namespace {

constexpr double kStopTransmittance = 1e-7; // as the reference
constexpr int kMaxFineSteps = 8192;         // per ray: the model's segments

/// The model's view directions: a Fibonacci lattice over the half sphere (a ray and its
/// reverse see the same signal), about 15 degrees apart, none on an axis or a diagonal (views
/// along them are special cases, where samples line up with the voxel layers).
glm::dvec3 directionOf(int i) {
    const double z = (i + 0.5) / SlabErrorModel::kDirections;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = i * 2.399963229728653; // the golden angle
    return {r * std::cos(phi), r * std::sin(phi), z};
}

/// Rays of a direction spread over a square of tangents (about 8 degrees), so each direction
/// stands for the views around it, not for its exact alignment with the grid; the wide sets
/// (direction index + kDirections) spread as a perspective view's pixels do (about 25 degrees),
/// which changes how slabs meet the rays near the box's faces.
constexpr double kConeTangent = 0.14;
constexpr double kWideConeTangent = 0.45;
/// Rays per direction: between kMinRaysAcross^2 and kMaxRaysAcross^2, as many as keep the
/// model's segments along them under kSampleBudget (its cost: about 100 ms at the budget on
/// llvmpipe's machine). A DVR view is predicted along kNearDirections narrow sets, which share
/// the budget (a view new to the model costs what one direction cost); a wide set, or MIP's and
/// MINIP's one direction, has it whole.
constexpr int kMinRaysAcross = 12;
constexpr int kMaxRaysAcross = 32;
constexpr double kSampleBudget = 1.0e6;

/// Trilinear data (and nearest tags) of a grid as the textures hold it: non-finite Float
/// voxels replaced by the finite extremes.
struct GridSampler {
    const VolumeGrid* grid = nullptr;
    const VolumeGrid* tags = nullptr;
    glm::ivec3 dims{1};
    glm::dvec3 spacing{1.0}, half{0.5};
    std::size_t strideY = 1, strideZ = 1;
    double lowest = 0.0, highest = 0.0;

    /// Samples `g` (its dimensions, spacing and finite extremes) over the box `half` keeps.
    void use(const VolumeGrid& g) {
        grid = &g;
        dims = g.dimensions();
        spacing = g.spacing();
        strideY = std::size_t(dims.x);
        strideZ = std::size_t(dims.x) * std::size_t(dims.y);
        if (g.type() == VoxelType::Float) std::tie(lowest, highest) = g.minMax();
    }

    template <class T> double voxel(std::size_t i) const {
        const double x = double(grid->data<T>()[i]);
        if constexpr (std::is_same_v<T, float>) {
            if (std::isnan(x) || x == -std::numeric_limits<double>::infinity()) return lowest;
            if (x == std::numeric_limits<double>::infinity()) return highest;
        }
        return x;
    }
    template <class T> double trilinear(const glm::dvec3& p) const {
        std::size_t base = 0, next[3];
        double f[3];
        const std::size_t stride[3] = {1, strideY, strideZ};
        for (int a = 0; a < 3; ++a) {
            const int n = dims[a];
            const double u = std::clamp((p[a] + half[a]) / spacing[a] - 0.5, 0.0, double(n - 1));
            const int i = std::min(int(u), std::max(n - 2, 0));
            f[a] = u - i;
            base += std::size_t(i) * stride[a];
            next[a] = n > 1 ? stride[a] : 0;
        }
        auto at = [&](std::size_t o) { return voxel<T>(base + o); };
        auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
        const double c00 = lerp(at(0), at(next[0]), f[0]);
        const double c10 = lerp(at(next[1]), at(next[1] + next[0]), f[0]);
        const double c01 = lerp(at(next[2]), at(next[2] + next[0]), f[0]);
        const double c11 = lerp(at(next[2] + next[1]), at(next[2] + next[1] + next[0]), f[0]);
        return lerp(lerp(c00, c10, f[1]), lerp(c01, c11, f[1]), f[2]);
    }
    /// f(at), where at(p) is the trilinear data of this grid's voxel type: the type chosen once
    /// per call of f, not per sample (most of the model's time is these samples).
    template <class F> auto withData(F&& f) const {
        switch (grid->type()) {
        case VoxelType::UShort:
            return f([this](const glm::dvec3& p) { return trilinear<std::uint16_t>(p); });
        case VoxelType::Short:
            return f([this](const glm::dvec3& p) { return trilinear<std::int16_t>(p); });
        case VoxelType::Float:
            return f([this](const glm::dvec3& p) { return trilinear<float>(p); });
        case VoxelType::UByte:
            break;
        }
        return f([this](const glm::dvec3& p) { return trilinear<std::uint8_t>(p); });
    }
    double data(const glm::dvec3& p) const {
        switch (grid->type()) {
        case VoxelType::UByte:
            return trilinear<std::uint8_t>(p);
        case VoxelType::UShort:
            return trilinear<std::uint16_t>(p);
        case VoxelType::Short:
            return trilinear<std::int16_t>(p);
        case VoxelType::Float:
            return trilinear<float>(p);
        }
        return 0.0;
    }
    glm::ivec3 cellOf(const glm::dvec3& p) const {
        glm::ivec3 c;
        for (int a = 0; a < 3; ++a)
            c[a] = std::clamp(int(std::floor((p[a] + half[a]) / spacing[a])), 0, dims[a] - 1);
        return c;
    }
    int tag(const glm::dvec3& p) const {
        const glm::ivec3 c = cellOf(p);
        return int(tags->value(std::size_t(c.x) + std::size_t(c.y) * strideY +
                               std::size_t(c.z) * strideZ));
    }
};

/// visit(t) at every t in [ta, tb] where the line u0 + t voxelsPerT (voxel coordinates) crosses
/// a voxel-centre plane (u = i + 1/2), per axis in turn: the trilinear field's kinks.
template <class Visit>
void forEachCrossing(const glm::dvec3& u0, const glm::dvec3& voxelsPerT, double ta, double tb,
                     Visit&& visit) {
    for (int k = 0; k < 3; ++k) {
        if (std::abs(voxelsPerT[k]) < 1e-15) continue;
        const double ua = u0[k] + ta * voxelsPerT[k], ub = u0[k] + tb * voxelsPerT[k];
        for (double c = std::ceil(std::min(ua, ub) - 0.5) + 0.5; c <= std::max(ua, ub); c += 1.0)
            visit((c - u0[k]) / voxelsPerT[k]);
    }
}

/// A ray's extreme sample (MIP/MINIP): the score v (MIP) or -v (MINIP), larger being more
/// extreme, and the sample's row.
struct Extreme {
    double score = -std::numeric_limits<double>::infinity();
    int row = 0;
    /// This, or `later` where it is more extreme (a tie keeps the earlier sample's row).
    Extreme over(const Extreme& later) const { return later.score > score ? later : *this; }
};

/// One ray through the box near a direction d: x(t) = origin + t dir (|dir| = 1), with
/// dot(origin, d) = 0, so the view depth along d is t * depthPerT.
struct ModelRay {
    glm::dvec3 origin{0.0};
    glm::dvec3 dir{0.0};
    double depthPerT = 1.0;
    double t0 = 0.0, t1 = 0.0;
    /// MIP/MINIP: the extreme of the ray's ends and voxel-centre crossings, which every slab
    /// layout with peaks and several samples a plane takes (found with the truth).
    Extreme crossing;
    bool hasCrossing = false;
    /// DVR without tags: where the ray crosses only cells that cannot emit (EmptyRuns.h).
    std::vector<glm::dvec2> emptyRuns;
    /// The layout's planes along this ray (depths become ray lengths).
    PlaneLayout along(const PlaneLayout& depthLayout) const {
        PlaneLayout l = depthLayout;
        l.nearDepth /= depthPerT;
        l.spacing /= depthPerT;
        return l;
    }
};

struct RaySet {
    glm::dvec3 dir{0.0};
    glm::dvec2 depthRange{0.0}; ///< of the box along dir
    std::vector<ModelRay> rays;
    std::vector<glm::dvec3> truth; ///< the model's pixel per ray (black behind)
};

/// A pixel's colour as the slicer composites it, front to back.
struct Composite {
    glm::dvec3 emitted{0.0};
    double T = 1.0;
    void add(const glm::dvec3& C, double D) {
        emitted += T * -std::expm1(-D) * C;
        T *= std::exp(-D);
    }
};

/// A slab of one ray: [a, b] in t, and the plane point (or, for a face's sliver, none).
struct Slab {
    double a, b, plane;
    int parts;
    bool face;
};

/// The slabs the slicer's planes cut from one ray (see the fragment shader: a plane stands
/// for half the way to each neighbour, or all the way to the ray's boundary where the
/// neighbour's point is beyond it; a ray no plane crosses is a face's sliver).
template <class Visit>
void forEachSlab(const ModelRay& ray, const PlaneLayout& layout, int parts, Visit&& visit) {
    const double ds = layout.spacing;
    const int first = std::max(0, int(std::ceil((ray.t0 - layout.nearDepth) / ds - 0.5)));
    const int last =
        std::min(layout.count - 1, int(std::floor((ray.t1 - layout.nearDepth) / ds - 0.5)));
    if (first > last) {
        const double len = ray.t1 - ray.t0;
        const int n = std::clamp(int(std::ceil(len * parts / ds - 1e-3)), 1, parts);
        visit(Slab{ray.t0, ray.t1, 0.5 * (ray.t0 + ray.t1), n, true});
        return;
    }
    for (int k = first; k <= last; ++k) {
        const double z = layout.depth(k);
        const double a = z - ray.t0 < ds ? ray.t0 : z - 0.5 * ds;
        const double b = ray.t1 - z < ds ? ray.t1 : z + 0.5 * ds;
        // As the shader: uSlabSamples per plane spacing, fewer on a slab cut shorter.
        const int n = std::clamp(int(std::ceil((b - a) * parts / ds - 1e-3)), 1, parts);
        visit(Slab{a, b, z, n, false});
    }
}

} // namespace

struct SlabErrorModel::Impl {
    GridSampler grid;
    TransferTable table;
    bool tagged = false;
    std::vector<std::unique_ptr<PreIntegrationTable>> preTables; ///< per row, built when needed
    std::unique_ptr<RaySet> sets[2 * kDirections];               ///< narrow, then wide
    double L0 = 1.0;
    /// The model's segment length: L0 / 4, finer where the transfer function's narrowest
    /// feature is crossed in less (its linearised v must not misplace the feature).
    double truthStep = 0.25;
    VolumeRenderMode mode = VolumeRenderMode::DVR;
    /// DVR without tags: the grid's cells classified with a pad that covers both tables'
    /// filtering, so the rays skip what cannot emit (EmptyRuns.h); unmeasured otherwise.
    EmptyCells cells;
    /// The rays' and the lattice's box (local coordinates): the volume's, or a region of it.
    glm::dvec3 regionMin{0.0}, regionMax{0.0};
    /// Integrates rays on every core: a new direction's rays are the model's main cost, and
    /// the choice runs before the frame's draws, while the rasteriser's threads are idle.
    WorkerPool pool;
    int threads = std::clamp(int(std::thread::hardware_concurrency()), 1, 4);

    /// body(i) for i in [0, count), spread over the pool in blocks; body must only write
    /// what index i owns, so the results are the same as one thread's.
    template <class Body> void forEachIndex(std::size_t count, Body&& body) {
        constexpr std::size_t kBlock = 4;
        std::atomic<std::size_t> next{0};
        const int workers = int(std::min<std::size_t>(std::size_t(threads), count / kBlock + 1));
        pool.run(workers, [&](int) {
            for (std::size_t first; (first = next.fetch_add(kBlock)) < count;)
                for (std::size_t i = first; i < std::min(first + kBlock, count); ++i)
                    body(i);
        });
    }
    /// Builds the segment tables every ray may need, so the threads only read them (once: the
    /// transfer functions are the model's for its life; tagRows has 65536 entries to scan).
    bool preTablesReady = false;
    void preparePreTables() {
        if (preTablesReady) return;
        preTablesReady = true;
        if (!tagged) {
            pre(0);
            return;
        }
        std::vector<bool> built(std::size_t(table.rows()), false);
        for (const std::uint16_t row : table.tagRows())
            if (row < built.size() && !built[row]) {
                pre(row);
                built[row] = true;
            }
    }

    /// The empty cells of DVR without tags (once), padded as both tables' lookups read.
    bool cellsClassified = false;
    bool skipsEmptyCells = true;
    void prepareEmptyCells() {
        if (tagged || cellsClassified || !skipsEmptyCells) return;
        cellsClassified = true;
        if (!cells.measured()) cells.measure(*grid.grid, nullptr, grid.lowest, grid.highest);
        cells.classify(table, false, false, PreIntegrationTable::kLookupPadV);
    }

    int rowAt(const glm::dvec3& p) const {
        return tagged ? int(table.tagRows()[std::size_t(grid.tag(p))]) : 0;
    }
    double vOf(double d, int row) const {
        const glm::dvec2 r = table.dataRange(row);
        return TransferFunction1D::normalise(d, r.x, r.y);
    }
    double vAt(const glm::dvec3& p, int row) const { return vOf(grid.data(p), row); }
    /// (r, g, b, tau L0) from the 4096-entry row, linear as the texture filter.
    glm::dvec4 classify(double v, int row) const {
        const float* t = table.texels().data() + std::size_t(row) * TransferTable::kWidth * 4;
        const double x = std::clamp(v, 0.0, 1.0) * (TransferTable::kEntries - 1);
        const int i = std::min(int(x), TransferTable::kEntries - 1);
        const double f = x - i;
        glm::dvec4 out;
        for (int c = 0; c < 4; ++c)
            out[c] = t[4 * i + c] + (t[4 * (i + 1) + c] - t[4 * i + c]) * f;
        return out;
    }
    const PreIntegrationTable& pre(int row) {
        if (preTables.empty()) preTables.resize(std::size_t(table.rows()));
        auto& t = preTables[std::size_t(row)];
        if (!t) {
            t = std::make_unique<PreIntegrationTable>();
            t->build(table.function(row));
        }
        return *t;
    }
    /// (mean colour, mean tau L0) of the segment from the 256 x 256 texels, bilinear.
    glm::dvec4 preLookup(int row, double vFront, double vBack) {
        const std::vector<float>& t = pre(row).texels();
        constexpr int n = PreIntegrationTable::kSize;
        const double x = std::clamp(vFront, 0.0, 1.0) * (n - 1);
        const double y = std::clamp(vBack, 0.0, 1.0) * (n - 1);
        const int i = std::min(int(x), n - 2), j = std::min(int(y), n - 2);
        const double fx = x - i, fy = y - j;
        glm::dvec4 out(0.0);
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
                const double w = (dx ? fx : 1.0 - fx) * (dy ? fy : 1.0 - fy);
                const float* e = t.data() + (std::size_t(j + dy) * n + std::size_t(i + dx)) * 4;
                out += w * glm::dvec4(e[0], e[1], e[2], e[3]);
            }
        return out;
    }

    RaySet& raysAlong(int dir);
    /// `across` x `across` jittered rays around direction `dirIndex` through the region's box
    /// (the same rays for the same arguments).
    std::vector<ModelRay> castRays(int dirIndex, int across) const;
    glm::dvec3 truthDvr(const ModelRay& ray);
    glm::dvec3 truthExtreme(const ModelRay& ray, const glm::dvec3& dir);
    /// The same with the data at a point from `dataAt` (GridCut: another grid per region).
    /// `runs`: stretches of the ray to skip (null: none; another grid's data may emit there).
    template <class DataAt>
    glm::dvec3 truthDvrOf(const ModelRay& ray, const DataAt& dataAt, double step,
                          const std::vector<glm::dvec2>* runs);
    template <class DataAt>
    glm::dvec3 truthExtremeOf(const ModelRay& ray, const glm::dvec3& dir, const DataAt& dataAt);
    /// The extreme of samples every L0 / 4 from end to end (the truth's besides the crossings).
    template <class DataAt>
    Extreme evenExtremeOf(const ModelRay& ray, const glm::dvec3& dir, const DataAt& dataAt) const;
    /// The extreme of the ray's ends and every voxel-centre crossing (ModelRay::crossing).
    template <class DataAt>
    Extreme crossingExtremeOf(const ModelRay& ray, const glm::dvec3& dir,
                              const DataAt& dataAt) const;
    /// The extreme of the samples at the t that along(take) visits.
    template <class DataAt, class Along>
    Extreme extremeOf(const ModelRay& ray, const glm::dvec3& dir, const DataAt& dataAt,
                      const Along& along) const;
    glm::dvec3 colourOf(const Extreme& e) const;
    /// A sampler of `other`, a grid over the same box as `grid` at its own resolution.
    GridSampler samplerOf(const VolumeGrid& other) const {
        GridSampler g = grid;
        g.tags = nullptr;
        g.use(other);
        return g;
    }
    glm::dvec3 slicedDvr(const ModelRay& ray, const glm::dvec3& dir, const PlaneLayout& layout,
                         const SlabQuadrature& q);
    glm::dvec3 slicedExtreme(const ModelRay& ray, const glm::dvec3& dir, const PlaneLayout& layout,
                             const SlabQuadrature& q) {
        return grid.withData(
            [&](const auto& at) { return slicedExtremeOf(ray, dir, layout, q, at); });
    }
    template <class DataAt>
    glm::dvec3 slicedExtremeOf(const ModelRay& ray, const glm::dvec3& dir,
                               const PlaneLayout& layout, const SlabQuadrature& q,
                               const DataAt& dataAt);
    glm::dvec3 preClassified(const ModelRay& ray, const glm::dvec3& dir, int sliceStep);
    void partColour(const glm::dvec3& origin, const glm::dvec3& dir, double a, double b, double at,
                    bool preIntegrated, glm::dvec3& C, double& D);
};

std::vector<ModelRay> SlabErrorModel::Impl::castRays(int dirIndex, int across) const {
    const glm::dvec3 d = directionOf(dirIndex % kDirections);
    const double cone = dirIndex >= kDirections ? kWideConeTangent : kConeTangent;
    const glm::dvec3 lo3 = regionMin, hi3 = regionMax;
    const glm::dvec3 helper = std::abs(d.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(d, helper));
    const glm::dvec3 w = glm::cross(d, u);
    glm::dvec2 lo(1e300), hi(-1e300);
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 p((c & 1) ? hi3.x : lo3.x, (c & 2) ? hi3.y : lo3.y,
                           (c & 4) ? hi3.z : lo3.z);
        const glm::dvec2 q(glm::dot(p, u), glm::dot(p, w));
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    std::uint32_t hash = 2463534242u + std::uint32_t(dirIndex) * 7919u;
    auto jitter = [&] { // xorshift: the same rays every time
        hash ^= hash << 13;
        hash ^= hash >> 17;
        hash ^= hash << 5;
        return double(hash) / 4294967296.0;
    };
    std::vector<ModelRay> rays;
    for (int iy = 0; iy < across; ++iy)
        for (int ix = 0; ix < across; ++ix) {
            const double fx = (ix + jitter()) / across, fy = (iy + jitter()) / across;
            ModelRay ray;
            ray.origin = u * (lo.x + fx * (hi.x - lo.x)) + w * (lo.y + fy * (hi.y - lo.y));
            ray.dir = glm::normalize(
                d + cone * ((2.0 * jitter() - 1.0) * u + (2.0 * jitter() - 1.0) * w));
            ray.depthPerT = glm::dot(ray.dir, d);
            const glm::dvec3& o = ray.origin;
            double t0 = -1e300, t1 = 1e300;
            for (int a = 0; a < 3; ++a) {
                if (std::abs(ray.dir[a]) < 1e-12) {
                    if (o[a] < lo3[a] || o[a] > hi3[a]) t1 = -1e300;
                    continue;
                }
                double ta = (lo3[a] - o[a]) / ray.dir[a], tb = (hi3[a] - o[a]) / ray.dir[a];
                if (ta > tb) std::swap(ta, tb);
                t0 = std::max(t0, ta);
                t1 = std::min(t1, tb);
            }
            ray.t0 = t0;
            ray.t1 = t1;
            if (t1 - t0 > 1e-9 * L0) rays.push_back(ray);
        }
    return rays;
}

RaySet& SlabErrorModel::Impl::raysAlong(int dirIndex) {
    if (sets[dirIndex]) return *sets[dirIndex];
    auto s = std::make_unique<RaySet>();
    const glm::dvec3 d = directionOf(dirIndex % kDirections);
    s->dir = d;
    const glm::dvec3 half = grid.half;
    // The planes are laid over the whole box (as the slicer lays them) even where the rays
    // cross only a region of it.
    const double depth = std::abs(d.x) * half.x + std::abs(d.y) * half.y + std::abs(d.z) * half.z;
    s->depthRange = {-depth, depth};
    // As many rays as a budget of model samples allows: errors often sit on a few pixels (a
    // thin feature's rim, a silhouette), which a dozen rays across can miss or over-weigh.
    const double samplesPerRay = 2.0 * depth / truthStep;
    // MIP and MINIP: twice as many across. Their errors sit on fewer pixels (thin bright
    // structures a thick slab's samples pass by), which the DVR count sampled too sparsely:
    // on the chest CT the default measured 0.72/255 at a target of 0.5, and 0.38 with these.
    const double scale = mode == VolumeRenderMode::DVR ? 1.0 : 2.0;
    // (A DVR view is predicted along kNearDirections narrow sets: they share the budget.)
    const double budget =
        dirIndex < kDirections && mode != VolumeRenderMode::MIP && mode != VolumeRenderMode::MINIP
            ? kSampleBudget / kNearDirections
            : kSampleBudget;
    const int across = std::clamp(int(scale * std::sqrt(budget / std::max(samplesPerRay, 1.0))),
                                  kMinRaysAcross, int(scale * kMaxRaysAcross));
    s->rays = castRays(dirIndex, across);
    s->truth.resize(s->rays.size());
    if (mode == VolumeRenderMode::DVR) {
        preparePreTables();
        prepareEmptyCells();
    }
    const EmptyCellMap cellMap{grid.half, grid.spacing, grid.dims,
                               cellsClassified ? &cells : nullptr};
    forEachIndex(s->rays.size(), [&](std::size_t i) {
        ModelRay& ray = s->rays[i];
        if (mode == VolumeRenderMode::DVR) {
            ray.emptyRuns = emptyRunsAlong(cellMap, ray.origin, ray.dir, ray.t0, ray.t1);
            s->truth[i] = truthDvr(ray);
            return;
        }
        s->truth[i] = grid.withData([&](const auto& at) {
            ray.crossing = crossingExtremeOf(ray, ray.dir, at);
            ray.hasCrossing = true;
            return colourOf(evenExtremeOf(ray, ray.dir, at).over(ray.crossing));
        });
    });
    sets[dirIndex] = std::move(s);
    return *sets[dirIndex];
}

glm::dvec3 SlabErrorModel::Impl::truthDvr(const ModelRay& ray) {
    return grid.withData(
        [&](const auto& at) { return truthDvrOf(ray, at, truthStep, &ray.emptyRuns); });
}

template <class DataAt>
glm::dvec3 SlabErrorModel::Impl::truthDvrOf(const ModelRay& ray, const DataAt& dataAt, double step,
                                            const std::vector<glm::dvec2>* runs) {
    // Segments of `step` (v linear along each: the trilinear field's curvature within one is
    // what this leaves out), integrated exactly through the segment table.
    const double len = ray.t1 - ray.t0;
    const int n = std::clamp(int(std::ceil(len / step)), 1, kMaxFineSteps);
    const double h = len / n;
    Composite c;
    glm::dvec3 p = ray.origin + ray.t0 * ray.dir;
    double dPrev = dataAt(p);
    EmptyRunCursor empty(runs);
    for (int i = 0; i < n && c.T > kStopTransmittance; ++i) {
        if (const glm::dvec2* r = empty.covering(ray.t0 + i * h, ray.t0 + (i + 1) * h)) {
            // Every segment up to the run's end adds nothing: on from its last point.
            const int last = std::clamp(int(std::floor((r->y - ray.t0) / h)), i + 1, n);
            p = ray.origin + (ray.t0 + last * h) * ray.dir;
            dPrev = dataAt(p);
            i = last - 1;
            continue;
        }
        const glm::dvec3 q = ray.origin + (ray.t0 + (i + 1) * h) * ray.dir;
        const double dNext = dataAt(q);
        const int row = rowAt(0.5 * (p + q));
        const glm::dvec4 seg = pre(row).absorbingSegment(vOf(dPrev, row), vOf(dNext, row));
        if (seg.a > 0.0) c.add(glm::dvec3(seg), seg.a * h / L0);
        p = q;
        dPrev = dNext;
    }
    return c.emitted;
}

glm::dvec3 SlabErrorModel::Impl::truthExtreme(const ModelRay& ray, const glm::dvec3& dir) {
    return grid.withData([&](const auto& at) { return truthExtremeOf(ray, dir, at); });
}

template <class DataAt>
glm::dvec3 SlabErrorModel::Impl::truthExtremeOf(const ModelRay& ray, const glm::dvec3& dir,
                                                const DataAt& dataAt) {
    return colourOf(evenExtremeOf(ray, dir, dataAt).over(crossingExtremeOf(ray, dir, dataAt)));
}

template <class DataAt>
Extreme SlabErrorModel::Impl::evenExtremeOf(const ModelRay& ray, const glm::dvec3& dir,
                                            const DataAt& dataAt) const {
    // Between crossings the field is a smooth cubic, whose top a quarter-voxel step misses by
    // little (L0 / 8 cost twice as much for the same choices on the sweep's MIP case and the
    // chest CT's target).
    const double len = ray.t1 - ray.t0;
    const int n = std::clamp(int(std::ceil(len / (0.25 * L0))), 1, 2 * kMaxFineSteps);
    return extremeOf(ray, dir, dataAt, [&](auto&& take) {
        for (int i = 0; i <= n; ++i)
            take(ray.t0 + len * i / n);
    });
}

template <class DataAt>
Extreme SlabErrorModel::Impl::crossingExtremeOf(const ModelRay& ray, const glm::dvec3& dir,
                                                const DataAt& dataAt) const {
    // The trilinear field is a cubic between voxel-centre planes and has its kinks on them,
    // where a tent-shaped extreme lies: every crossing is sampled, so the extreme is exact
    // there (evenly spaced samples alone came out below it, and below the slicer's crossings).
    return extremeOf(ray, dir, dataAt, [&](auto&& take) {
        take(ray.t0);
        take(ray.t1);
        forEachCrossing((ray.origin + grid.half) / grid.spacing, dir / grid.spacing, ray.t0, ray.t1,
                        take);
    });
}

template <class DataAt, class Along>
Extreme SlabErrorModel::Impl::extremeOf(const ModelRay& ray, const glm::dvec3& dir,
                                        const DataAt& dataAt, const Along& along) const {
    const bool maximum = mode == VolumeRenderMode::MIP;
    const double sign = maximum ? 1.0 : -1.0;
    if (!tagged) {
        // One row: v is monotone in the data (rising, or falling for a reversed dataRange), so
        // the extreme data gives the extreme v, normalised once (the same value).
        const glm::dvec2 r = table.dataRange(0);
        const bool largest = maximum == (r.y >= r.x);
        double extreme = largest ? -std::numeric_limits<double>::infinity()
                                 : std::numeric_limits<double>::infinity();
        along([&](double t) {
            const double d = dataAt(ray.origin + t * dir);
            extreme = largest ? std::max(extreme, d) : std::min(extreme, d);
        });
        return {sign * vOf(extreme, 0), 0};
    }
    Extreme best;
    along([&](double t) {
        const glm::dvec3 p = ray.origin + t * dir;
        const int row = rowAt(p);
        best = best.over({sign * vOf(dataAt(p), row), row});
    });
    return best;
}

glm::dvec3 SlabErrorModel::Impl::colourOf(const Extreme& e) const {
    const double v = std::clamp(mode == VolumeRenderMode::MIP ? e.score : -e.score, 0.0, 1.0);
    const glm::dvec4 rgba = table.function(e.row).evaluate(v);
    return glm::dvec3(rgba) * std::min(rgba.a, TransferTable::kMaxOpacity);
}

void SlabErrorModel::Impl::partColour(const glm::dvec3& origin, const glm::dvec3& dir, double a,
                                      double b, double at, bool preIntegrated, glm::dvec3& C,
                                      double& D) {
    const double len = b - a;
    if (!tagged) {
        if (preIntegrated) {
            const glm::dvec4 seg = preLookup(0, vAt(origin + a * dir, 0), vAt(origin + b * dir, 0));
            C = glm::dvec3(seg);
            D = seg.a * len / L0;
        } else {
            const glm::dvec4 rgba = classify(vAt(origin + at * dir, 0), 0);
            C = glm::dvec3(rgba);
            D = rgba.a * len / L0;
        }
        return;
    }
    // Tagged: the part cut at the faces of the tag cell around `at` (classifySlab), each piece
    // with its own row.
    const glm::dvec3 x = origin + at * dir;
    const glm::ivec3 cell = grid.cellOf(x);
    double c0 = -1e300, c1 = 1e300;
    for (int k = 0; k < 3; ++k) {
        const double lo = -grid.half[k] + cell[k] * grid.spacing[k];
        const double hi = lo + grid.spacing[k];
        if (std::abs(dir[k]) < 1e-15) continue;
        double ta = (lo - origin[k]) / dir[k], tb = (hi - origin[k]) / dir[k];
        if (ta > tb) std::swap(ta, tb);
        c0 = std::max(c0, ta);
        c1 = std::min(c1, tb);
    }
    const double cut[4] = {a, std::clamp(c0, a, b), 0.0, b};
    const double cuts[4] = {cut[0], cut[1], std::clamp(c1, cut[1], b), cut[3]};
    glm::dvec3 emitted(0.0);
    double depthSum = 0.0;
    glm::dvec3 fallback(0.0);
    for (int i = 0; i < 3; ++i) {
        const double l = cuts[i + 1] - cuts[i];
        if (!(l > 0.0) && i != 1) continue;
        const glm::dvec3 m = origin + 0.5 * (cuts[i] + cuts[i + 1]) * dir;
        const int row = rowAt(m);
        glm::dvec4 rgba;
        if (preIntegrated)
            rgba = preLookup(row, vAt(origin + cuts[i] * dir, row),
                             vAt(origin + cuts[i + 1] * dir, row));
        else
            rgba = classify(vAt(m, row), row);
        const double tau = rgba.a * std::max(l, 0.0);
        emitted += tau * glm::dvec3(rgba);
        depthSum += tau;
        if (i == 1) fallback = glm::dvec3(rgba);
    }
    C = depthSum > 0.0 ? emitted / depthSum : fallback;
    D = depthSum / L0;
}

glm::dvec3 SlabErrorModel::Impl::slicedDvr(const ModelRay& ray, const glm::dvec3& dir,
                                           const PlaneLayout& layout, const SlabQuadrature& q) {
    Composite c;
    // A part in cells that cannot emit adds an optical depth of exactly 0: pre-integrated,
    // its two ends' values lie in one transparent stretch of the table (the data is
    // continuous along the run); otherwise its one sample does.
    EmptyRunCursor empty(&ray.emptyRuns); // none with tags (prepareEmptyCells)
    forEachSlab(ray, layout, std::max(q.samplesPerPlane, 1), [&](const Slab& s) {
        if (c.T <= kStopTransmittance) return;
        const double part = (s.b - s.a) / s.parts;
        for (int j = 0; j < s.parts; ++j) {
            const double a = s.a + j * part, b = a + part;
            // One part of a plane's slab is sampled at the plane; parts at their middles.
            const double at = s.parts == 1 && !s.face ? s.plane : 0.5 * (a + b);
            if (q.preIntegrated ? empty.covering(a, b) : empty.covering(at, at)) continue;
            glm::dvec3 C;
            double D;
            partColour(ray.origin, dir, a, b, at, q.preIntegrated, C, D);
            c.add(C, D);
        }
    });
    return c.emitted;
}

template <class DataAt>
glm::dvec3 SlabErrorModel::Impl::slicedExtremeOf(const ModelRay& ray, const glm::dvec3& dir,
                                                 const PlaneLayout& layout, const SlabQuadrature& q,
                                                 const DataAt& dataAt) {
    const bool maximum = mode == VolumeRenderMode::MIP;
    const double sign = maximum ? 1.0 : -1.0;
    // The samples in ray order with their slab, the score (v, or -v for MINIP) and row.
    struct Sample {
        double score;
        int row, slab;
        bool counts; ///< inside its slab (the evenly spaced ones)
    };
    thread_local std::vector<Sample> samples;
    samples.clear();
    int slabIndex = 0;
    const glm::dvec3 voxelsPerT = dir / grid.spacing;
    // With peaks and several samples a plane, every slab takes every crossing in it and the
    // first and last take the ray's ends: together, the samples whose extreme the truth found
    // (ModelRay::crossing), the same for every layout. Only the middles remain to be taken.
    const bool everyCrossing = q.peaks && q.samplesPerPlane > 1;
    forEachSlab(ray, layout, std::max(q.samplesPerPlane, 1), [&](const Slab& s) {
        auto take = [&](double t) {
            const glm::dvec3 p = ray.origin + t * dir;
            const int row = rowAt(p);
            samples.push_back({sign * vOf(dataAt(p), row), row, slabIndex, true});
        };
        const double part = (s.b - s.a) / s.parts;
        if (s.parts == 1 && !s.face)
            take(s.plane);
        else
            for (int j = 0; j < s.parts; ++j)
                take(s.a + (j + 0.5) * part);
        if (q.peaks && !everyCrossing) {
            // The slab's ends on the box's face (a structure the face cuts has its extreme
            // there), and the voxel-centre crossings: the nearest plane along each axis to
            // the one sample, or every crossing in a face's sliver.
            if (s.a == ray.t0) take(s.a);
            if (s.b == ray.t1) take(s.b);
            const glm::dvec3 u0 = (ray.origin + s.plane * dir + grid.half) / grid.spacing;
            if (s.parts == 1 && !s.face) {
                for (int k = 0; k < 3; ++k) {
                    if (std::abs(voxelsPerT[k]) < 1e-15) continue;
                    const double t = s.plane + (std::floor(u0[k]) + 0.5 - u0[k]) / voxelsPerT[k];
                    if (t >= s.a && t <= s.b) take(t);
                }
            } else {
                forEachCrossing(u0, voxelsPerT, s.a - s.plane, s.b - s.plane,
                                [&](double dt) { take(s.plane + dt); });
            }
        }
        ++slabIndex;
    });
    double best = -1e300;
    int bestRow = 0;
    if (everyCrossing) {
        const Extreme c = ray.hasCrossing ? ray.crossing : crossingExtremeOf(ray, dir, dataAt);
        best = c.score;
        bestRow = c.row;
    }
    for (std::size_t i = 0; i < samples.size(); ++i)
        if (samples[i].score > best) {
            best = samples[i].score;
            bestRow = samples[i].row;
        }
    if (!q.peaks && q.refinePeaks && q.samplesPerPlane > 1 && samples.size() >= 3) {
        // Each slab's top, refined by the parabola through it and its neighbours when both
        // are below it (refinedTop in the shader); the largest of them.
        for (std::size_t i = 1; i + 1 < samples.size(); ++i) {
            const double top = samples[i].score;
            const double p = top - samples[i - 1].score, r = top - samples[i + 1].score;
            if (p < 0.0 || r < 0.0) continue;
            const double refined = top + (p - r) * (p - r) / std::max(8.0 * (p + r), 1e-30);
            if (refined > best) {
                best = refined;
                bestRow = samples[i].row;
            }
        }
    }
    const double v = std::clamp(sign * best, 0.0, 1.0);
    const glm::dvec4 rgba = classify(v, bestRow);
    return glm::dvec3(rgba) * -std::expm1(-rgba.a);
}

glm::dvec3 SlabErrorModel::Impl::preClassified(const ModelRay& ray, const glm::dvec3& dir,
                                               int sliceStep) {
    // The principal axis: the one the ray crosses most voxel planes of.
    const glm::dvec3 perVoxel = glm::abs(dir) / grid.spacing;
    const int c = perVoxel.x >= perVoxel.y && perVoxel.x >= perVoxel.z ? 0
                  : perVoxel.y >= perVoxel.z                           ? 1
                                                                       : 2;
    const int a = (c + 1) % 3, b = (c + 2) % 3;
    const int n = grid.dims[c];
    const int step = std::clamp(sliceStep, 1, std::max(1, n));
    const int phase = ((n - 1) % step) / 2;
    const double between = grid.spacing[c] / std::abs(dir[c]) * step; // path per kept slice
    const auto voxel = [&](int i, int j, int k) {
        glm::ivec3 q;
        q[a] = i;
        q[b] = j;
        q[c] = k;
        const glm::dvec3 centre = -grid.half + (glm::dvec3(q) + 0.5) * grid.spacing;
        const glm::dvec4 rgba = classify(vOf(grid.data(centre), 0), 0);
        const double alpha = -std::expm1(-rgba.a * between / L0);
        return glm::dvec4(glm::dvec3(rgba) * alpha, alpha);
    };
    glm::dvec3 emitted(0.0);
    double T = 1.0;
    const int kFirst = dir[c] > 0.0 ? 0 : n - 1, kStep = dir[c] > 0.0 ? 1 : -1;
    for (int k = kFirst; k >= 0 && k < n && T > kStopTransmittance; k += kStep) {
        if (k % step != phase) continue;
        const double plane = -grid.half[c] + (k + 0.5) * grid.spacing[c];
        const double t = (plane - ray.origin[c]) / dir[c];
        if (t < ray.t0 || t > ray.t1) continue;
        const glm::dvec3 p = ray.origin + t * dir;
        const double ua = std::clamp((p[a] + grid.half[a]) / grid.spacing[a] - 0.5, 0.0,
                                     double(grid.dims[a] - 1));
        const double ub = std::clamp((p[b] + grid.half[b]) / grid.spacing[b] - 0.5, 0.0,
                                     double(grid.dims[b] - 1));
        const int i = std::min(int(ua), std::max(grid.dims[a] - 2, 0));
        const int j = std::min(int(ub), std::max(grid.dims[b] - 2, 0));
        const double fa = ua - i, fb = ub - j;
        const int i1 = std::min(i + 1, grid.dims[a] - 1), j1 = std::min(j + 1, grid.dims[b] - 1);
        const glm::dvec4 s = (1 - fa) * (1 - fb) * voxel(i, j, k) +
                             fa * (1 - fb) * voxel(i1, j, k) + (1 - fa) * fb * voxel(i, j1, k) +
                             fa * fb * voxel(i1, j1, k);
        emitted += T * glm::dvec3(s);
        T *= 1.0 - s.a;
    }
    return emitted;
}

namespace {

/// The narrowest opacity piece and the steepest tau L0 slope of one row.
void measureFunction(const TransferTable& table, int row, SignalNeeds& needs) {
    const auto& points = table.function(row).channel(TransferFunction1D::Alpha).points();
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
        if (std::abs(points[i + 1].y - points[i].y) > 1e-3)
            needs.narrowestFeature =
                std::min(needs.narrowestFeature, std::max(points[i + 1].x - points[i].x,
                                                          1.0 / (TransferTable::kEntries - 1)));
    const float* t = table.texels().data() + std::size_t(row) * TransferTable::kWidth * 4;
    for (int i = 0; i + 1 < TransferTable::kEntries; ++i)
        needs.steepestSlope =
            std::max(needs.steepestSlope, std::abs(double(t[4 * (i + 1) + 3]) - t[4 * i + 3]) *
                                              (TransferTable::kEntries - 1));
}

} // namespace

SlabErrorModel::SlabErrorModel(const RayCastVolume& volume, std::optional<ModelRegion> region,
                               double opacityUnit, const EmptyCells* measuredCells)
    : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    const VolumeGrid& g = *volume.data;
    m.grid.use(g);
    m.grid.half = 0.5 * g.extent();
    m.regionMin = region ? glm::max(region->min, -m.grid.half) : -m.grid.half;
    m.regionMax = region ? glm::min(region->max, m.grid.half) : m.grid.half;
    const auto natural = g.naturalRange();
    m.table.build(volume.transferFunctions, {natural.first, natural.second});
    m.tagged = volume.tags && m.table.rows() > 1;
    m.grid.tags = m.tagged ? volume.tags.get() : nullptr;
    tagged_ = m.tagged;
    m.L0 = L0_ = opacityUnit > 0.0 ? opacityUnit : g.smallestSpacing();
    m.mode = mode_ = volume.mode;
    if (measuredCells && measuredCells->measured() && mode_ == VolumeRenderMode::DVR && !m.tagged)
        m.cells = *measuredCells;

    for (int r = 0; r < m.table.rows(); ++r)
        measureFunction(m.table, r, needs_);
    // |grad v| L0 on a lattice of about 20^3 voxels, where a table may give opacity.
    std::vector<double> gradients;
    int visible = 0, sampled = 0;
    // The voxels whose centres lie in the region (all of them without one).
    const glm::ivec3 first =
        glm::clamp(glm::ivec3(glm::ceil((m.regionMin + m.grid.half) / m.grid.spacing - 0.5)),
                   glm::ivec3(0), m.grid.dims - 1);
    const glm::ivec3 last =
        glm::clamp(glm::ivec3(glm::floor((m.regionMax + m.grid.half) / m.grid.spacing - 0.5)),
                   first, m.grid.dims - 1);
    const glm::ivec3 step = glm::max((last - first + 1) / 20, glm::ivec3(1));
    for (int k = first.z; k <= last.z; k += step.z)
        for (int j = first.y; j <= last.y; j += step.y)
            for (int i = first.x; i <= last.x; i += step.x) {
                const glm::dvec3 p = -m.grid.half + (glm::dvec3(i, j, k) + 0.5) * m.grid.spacing;
                const int row = m.rowAt(p);
                glm::dvec3 grad;
                for (int a = 0; a < 3; ++a) {
                    glm::dvec3 e(0.0);
                    e[a] = m.grid.spacing[a];
                    grad[a] = (m.vAt(p + e, row) - m.vAt(p - e, row)) / (2.0 * m.grid.spacing[a]);
                }
                const double gL0 = glm::length(grad) * L0_;
                const double v = m.vAt(p, row);
                ++sampled;
                if (m.table.function(row)
                        .channel(TransferFunction1D::Alpha)
                        .maxOver(std::max(v - gL0, 0.0), std::min(v + gL0, 1.0)) <= 0.0)
                    continue;
                ++visible;
                gradients.push_back(gL0);
            }
    needs_.visibleFraction = sampled > 0 ? double(visible) / sampled : 0.0;
    if (!gradients.empty()) {
        const std::size_t at = std::min(gradients.size() - 1, gradients.size() * 9 / 10);
        std::nth_element(gradients.begin(), gradients.begin() + std::ptrdiff_t(at),
                         gradients.end());
        needs_.gradientPerL0 = gradients[at];
    }
    needs_.samplesPerL0 = 2.0 * needs_.gradientPerL0 / needs_.narrowestFeature;
    m.truthStep = L0_ / std::clamp(std::ceil(4.0 * needs_.samplesPerL0), 4.0, 32.0);
}

SlabErrorModel::~SlabErrorModel() = default;

namespace {

/// Of the directions `keep` accepts, the nearest to unit vector d, either way along it, and
/// the |cosine| of its angle to d; -1 when none is accepted.
template <class Keep> std::pair<int, double> nearestAmong(const glm::dvec3& d, Keep keep) {
    int best = -1;
    double bestDot = -1.0;
    for (int i = 0; i < SlabErrorModel::kDirections; ++i) {
        if (!keep(i)) continue;
        const double c = std::abs(glm::dot(d, directionOf(i)));
        if (c > bestDot) {
            bestDot = c;
            best = i;
        }
    }
    return {best, bestDot};
}

} // namespace

int SlabErrorModel::nearestDirection(const glm::dvec3& localDirection, bool wide) {
    const int best = nearestAmong(glm::normalize(localDirection), [](int) { return true; }).first;
    return wide ? best + kDirections : best;
}

std::array<int, SlabErrorModel::kNearDirections>
SlabErrorModel::nearestDirections(const glm::dvec3& localDirection) {
    const glm::dvec3 d = glm::normalize(localDirection);
    std::array<int, kNearDirections> out{};
    for (int k = 0; k < kNearDirections; ++k)
        out[std::size_t(k)] =
            nearestAmong(d, [&](int i) {
                return std::find(out.begin(), out.begin() + k, i) == out.begin() + k;
            }).first;
    return out;
}

void SlabErrorModel::setSkipsEmptyCells(bool skips) {
    impl_->skipsEmptyCells = skips;
}

void SlabErrorModel::setThreads(int threads) {
    impl_->threads = std::clamp(threads, 1, 64);
}

double SlabErrorModel::samplesOfFullEvaluation(int dir, double samplesPerL0) {
    double length = 0.0;
    for (const ModelRay& ray : impl_->raysAlong(dir).rays)
        length += ray.t1 - ray.t0;
    return length / L0_ * samplesPerL0;
}

bool SlabErrorModel::hasDirection(int dir) const {
    return impl_->sets[dir] != nullptr;
}

int SlabErrorModel::castDirectionNear(const glm::dvec3& localDirection, bool wide,
                                      double maxDegrees) const {
    const int exact = nearestDirection(localDirection, wide);
    if (hasDirection(exact)) return exact;
    const int offset = wide ? kDirections : 0;
    const auto [near, cosine] = nearestAmong(
        glm::normalize(localDirection), [&](int i) { return impl_->sets[i + offset] != nullptr; });
    if (near < 0 || cosine < std::cos(glm::radians(maxDegrees))) return -1;
    return near + offset;
}

int SlabErrorModel::directionsCast() const {
    int n = 0;
    for (const auto& set : impl_->sets)
        n += set != nullptr;
    return n;
}

glm::dvec3 SlabErrorModel::directionVector(int dir) {
    return directionOf(dir % kDirections);
}

double SlabErrorModel::depthL0(int dir) const {
    const glm::dvec3 d = directionOf(dir % kDirections);
    const glm::dvec3 h = impl_->grid.half;
    return 2.0 * (std::abs(d.x) * h.x + std::abs(d.y) * h.y + std::abs(d.z) * h.z) / L0_;
}

double SlabErrorModel::rayRmse(int dir, const SlabQuadrature& q) {
    return rayRmseUpTo(dir, q, std::numeric_limits<double>::infinity());
}

double SlabErrorModel::rayRmseUpTo(int dir, const SlabQuadrature& q, double limit) {
    const auto key = std::make_pair(dir, q);
    if (auto it = cache_.find(key); it != cache_.end())
        if (it->second.exact || it->second.value > limit) return it->second.value;
    Impl& m = *impl_;
    const RaySet& s = m.raysAlong(dir);
    const PlaneLayout layout = PlaneLayout::over(s.depthRange, q.planeSpacingL0 * L0_);
    const std::size_t n = s.rays.size();
    // The squared errors only add up: once their sum passes n limit^2 the RMSE is above the
    // limit whatever the other rays give. A stride coprime with n near n / golden ratio spreads
    // the first rays over the whole box (the rays are made row by row).
    const double stopSum = limit * limit * double(n);
    std::size_t stride = std::max<std::size_t>(1, std::size_t(0.618034 * double(n)));
    while (n > 1 && std::gcd(stride, n) != 1)
        ++stride;
    // The rays are integrated in blocks on every core (a small first block, as most
    // candidates that miss are proved to after a few rays), their errors added in the
    // stratified order as one thread adds them: the same value and the same stop.
    if (mode_ == VolumeRenderMode::DVR) m.preparePreTables();
    double sum = 0.0;
    std::size_t visited = 0;
    std::vector<double> squared;
    std::vector<std::size_t> order;
    bool stopped = false;
    for (std::size_t k = 0, i = 0, block = 8; k < n && !stopped;
         block = std::min<std::size_t>(2 * block, 256)) {
        order.clear();
        for (; order.size() < block && k < n; ++k, i = (i + stride) % n)
            order.push_back(i);
        squared.assign(order.size(), 0.0);
        m.forEachIndex(order.size(), [&](std::size_t j) {
            const ModelRay& ray = s.rays[order[j]];
            const glm::dvec3 got = mode_ == VolumeRenderMode::DVR
                                       ? m.slicedDvr(ray, ray.dir, ray.along(layout), q)
                                       : m.slicedExtreme(ray, ray.dir, ray.along(layout), q);
            const glm::dvec3 e = got - s.truth[order[j]];
            squared[j] = glm::dot(e, e) / 3.0;
        });
        for (std::size_t j = 0; j < order.size(); ++j) {
            const ModelRay& ray = s.rays[order[j]];
            sum += squared[j];
            samplesEvaluated_ += (ray.t1 - ray.t0) / L0_ * q.samplesPerL0();
            ++visited;
            if (sum > stopSum) {
                stopped = true;
                break;
            }
        }
    }
    const bool exact = visited == n;
    const double rmse = n == 0 ? 0.0 : std::sqrt(sum / double(n));
    ++evaluations_;
    cache_[key] = CachedRmse{rmse, exact};
    return rmse;
}

namespace {
/// cutDifference: rays cast to find those that cross a coarse cell, and how many of those are
/// integrated (evenly spaced among them).
constexpr int kCutRaysAcross = 64;
constexpr std::size_t kCutRaysIntegrated = 128;
} // namespace

double SlabErrorModel::cutDifference(int dir, const GridCut& cut) {
    const auto key = std::make_pair(dir, cut.key);
    for (const auto& [k, value] : cutCache_)
        if (k == key) return value;
    Impl& m = *impl_;
    if (tagged_ || cut.grids.empty() ||
        cut.cellGrid.size() !=
            std::size_t(cut.cells.x) * std::size_t(cut.cells.y) * std::size_t(cut.cells.z))
        return 0.0;
    const auto cellAt = [&](const glm::dvec3& p) {
        const glm::ivec3 c = glm::clamp(glm::ivec3(glm::floor((p - cut.boxMin) / cut.cellSize)),
                                        glm::ivec3(0), cut.cells - 1);
        return cut.cellGrid[cut.indexOf(c)];
    };
    std::vector<GridSampler> samplers;
    for (const VolumeGrid* g : cut.grids)
        samplers.push_back(g ? m.samplerOf(*g) : m.grid);
    const auto dataAt = [&](const glm::dvec3& p) {
        return samplers[std::min<std::size_t>(cellAt(p), samplers.size() - 1)].data(p);
    };
    // Only rays that cross a cell drawn from another grid differ: a dense set of rays finds
    // them (geometry only), a sample of those is integrated both ways, and the image's mean
    // squared difference is theirs times their share.
    const std::vector<ModelRay> rays = m.castRays(dir, kCutRaysAcross);
    // Both integrations in segments of a quarter of the model's grid's voxel at most (the
    // model's own are finer for spiky transfer functions, and in level 0's voxels for a
    // paged stand-in): only the difference of the two is wanted, and a segment's v is
    // integrated exactly either way (the segment table). Half a voxel under-predicted a spiky
    // function's difference by up to 1.3 times more; this cost 25-50 ms a new cut on the
    // chest CT at 512 x 512 on one thread.
    const double gridVoxel = std::min({m.grid.spacing.x, m.grid.spacing.y, m.grid.spacing.z});
    const double cutStep = std::max(m.truthStep, 0.25 * gridVoxel);
    const auto ownAt = [&m](const glm::dvec3& p) { return m.grid.data(p); };
    const double step = 0.5 * std::min({cut.cellSize.x, cut.cellSize.y, cut.cellSize.z});
    std::vector<std::uint8_t> crosses(rays.size(), 0);
    m.forEachIndex(rays.size(), [&](std::size_t i) {
        const ModelRay& ray = rays[i];
        for (double t = ray.t0; t <= ray.t1; t += step)
            if (cellAt(ray.origin + t * ray.dir) != 0) {
                crosses[i] = 1;
                break;
            }
    });
    std::vector<std::size_t> crossing;
    for (std::size_t i = 0; i < rays.size(); ++i)
        if (crosses[i]) crossing.push_back(i);
    double rmse = 0.0;
    if (!crossing.empty()) {
        const std::size_t stride = std::max<std::size_t>(1, crossing.size() / kCutRaysIntegrated);
        const std::size_t integrated = (crossing.size() + stride - 1) / stride;
        if (mode_ == VolumeRenderMode::DVR) m.preparePreTables();
        std::vector<double> squared(integrated);
        m.forEachIndex(integrated, [&](std::size_t j) {
            const ModelRay& ray = rays[crossing[j * stride]];
            const glm::dvec3 e =
                mode_ == VolumeRenderMode::DVR
                    ? m.truthDvrOf(ray, dataAt, cutStep, nullptr) -
                          m.truthDvrOf(ray, ownAt, cutStep, nullptr)
                    : m.truthExtremeOf(ray, ray.dir, dataAt) - m.truthExtreme(ray, ray.dir);
            squared[j] = glm::dot(e, e) / 3.0;
        });
        double sum = 0.0; // in ray order, as one thread adds them
        for (const double e : squared)
            sum += e;
        const double share =
            double(crossing.size()) / double(std::max<std::size_t>(rays.size(), 1));
        rmse = std::sqrt(share * sum / double(integrated));
    }
    ++evaluations_;
    if (cutCache_.size() >= 8) cutCache_.erase(cutCache_.begin());
    cutCache_.emplace_back(key, rmse);
    return rmse;
}

double SlabErrorModel::preClassifiedRmse(int dir, int sliceStep) {
    const auto key = std::make_pair(dir, sliceStep);
    if (auto it = preClassifiedCache_.find(key); it != preClassifiedCache_.end()) return it->second;
    Impl& m = *impl_;
    const RaySet& s = m.raysAlong(dir);
    double sum = 0.0;
    for (std::size_t i = 0; i < s.rays.size(); ++i) {
        const glm::dvec3 e = m.preClassified(s.rays[i], s.rays[i].dir, sliceStep) - s.truth[i];
        sum += glm::dot(e, e) / 3.0;
    }
    const double rmse = s.rays.empty() ? 0.0 : std::sqrt(sum / double(s.rays.size()));
    ++evaluations_;
    preClassifiedCache_.emplace(key, rmse);
    return rmse;
}

} // namespace volsg
