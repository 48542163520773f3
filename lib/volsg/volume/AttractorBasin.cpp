#include <volsg/volume/AttractorBasin.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/core/Error.h>

namespace volsg {

namespace {

// The classic chaotic parameters (Lorenz 1963).
constexpr double sigma = 10.0, rho = 28.0, beta = 8.0 / 3.0;

glm::dvec3 lorenz(const glm::dvec3& p) {
    return {sigma * (p.y - p.x), p.x * (rho - p.z) - p.y, p.x * p.y - beta * p.z};
}

glm::dvec3 rk4Step(const glm::dvec3& p, double h) {
    const glm::dvec3 k1 = lorenz(p);
    const glm::dvec3 k2 = lorenz(p + 0.5 * h * k1);
    const glm::dvec3 k3 = lorenz(p + 0.5 * h * k2);
    const glm::dvec3 k4 = lorenz(p + h * k3);
    return p + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

/// Runs `work(begin, end)` over [0, count) split between the cores. Each part writes only its
/// own elements, so the result does not depend on the number of threads.
template <class F> void parallelFor(std::size_t count, F&& work) {
    const std::size_t threads = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 8);
    if (threads == 1 || count < 2) {
        work(std::size_t(0), count);
        return;
    }
    std::vector<std::thread> pool;
    for (std::size_t t = 0; t < threads; ++t) {
        const std::size_t b = count * t / threads, e = count * (t + 1) / threads;
        pool.emplace_back([&work, b, e] { work(b, e); });
    }
    for (auto& thread : pool)
        thread.join();
}

/// A cubic float field, x fastest.
struct SampledField {
    int n;
    std::vector<float> v;
    explicit SampledField(int side) : n(side), v(std::size_t(side) * side * side, 0.0f) {}
    std::size_t index(int i, int j, int k) const {
        return std::size_t(i) + std::size_t(n) * (std::size_t(j) + std::size_t(n) * std::size_t(k));
    }
};

/// One box-filter pass of radius r along `axis` (0 = x, 1 = y, 2 = z), zero outside the
/// volume, by running sums. Lines along the axis are taken in blocks of up to 256 neighbouring
/// lines (contiguous in memory), so that the strided axes still stream memory in order.
void boxBlurAxis(SampledField& f, int axis, int r) {
    const std::size_t n = std::size_t(f.n), rr = std::size_t(r);
    const std::size_t stride = axis == 0 ? 1 : axis == 1 ? n : n * n;
    // Line starts: x lines start at every (j, k); y lines at (i, k); z lines at (i, j). The
    // starts of the y and z lines that share a k (y) or that are all (z) are contiguous runs.
    const std::size_t runLength = axis == 0 ? 1 : stride; // contiguous line starts per run
    const std::size_t runs = n * n / runLength;
    const std::size_t block = std::min<std::size_t>(runLength, 256);
    const std::size_t blocksPerRun = (runLength + block - 1) / block;
    const float scale = 1.0f / float(2 * r + 1);
    parallelFor(runs * blocksPerRun, [&](std::size_t begin, std::size_t end) {
        std::vector<float> line(n * block), sum(block);
        for (std::size_t item = begin; item < end; ++item) {
            const std::size_t run = item / blocksPerRun, c0 = (item % blocksPerRun) * block;
            const std::size_t cn = std::min(block, runLength - c0);
            // Run `run` starts at: x: run * n; y: run * n * n (slice k = run); z: 0.
            const std::size_t base = (axis == 0 ? run * n : run * n * runLength) + c0;
            for (std::size_t s = 0; s < n; ++s)
                for (std::size_t c = 0; c < cn; ++c)
                    line[s * block + c] = f.v[base + c + s * stride];
            std::fill(sum.begin(), sum.end(), 0.0f);
            for (std::size_t s = 0; s < std::min(rr, n); ++s)
                for (std::size_t c = 0; c < cn; ++c)
                    sum[c] += line[s * block + c];
            for (std::size_t s = 0; s < n; ++s) {
                if (s + rr < n)
                    for (std::size_t c = 0; c < cn; ++c)
                        sum[c] += line[(s + rr) * block + c];
                for (std::size_t c = 0; c < cn; ++c)
                    f.v[base + c + s * stride] = sum[c] * scale;
                if (s >= rr)
                    for (std::size_t c = 0; c < cn; ++c)
                        sum[c] -= line[(s - rr) * block + c];
            }
        }
    });
}

/// Two box passes per axis: a separable tent filter of radius 2r, close enough to a Gaussian.
void smooth(SampledField& f, int r) {
    if (r < 1) return;
    for (int pass = 0; pass < 2; ++pass)
        for (int axis = 0; axis < 3; ++axis)
            boxBlurAxis(f, axis, r);
}

} // namespace

AttractorBasinVolume makeAttractorBasin(int n) {
    if (n < 16)
        throw Error("the attractor-basin volume needs at least 16 voxels a side, got " +
                    std::to_string(n));
    // Working memory is about 11 n^3 bytes (two float fields): 1.5 GB at 512.
    if (n > 512)
        throw Error("the attractor-basin volume has at most 512 voxels a side, got " +
                    std::to_string(n));

    // The trajectory: a fixed start, a transient left out, then samples every h. The sample
    // count grows with the attractor's area in voxels (n^2), so the density per voxel stays put.
    const double h = 0.004;
    const std::size_t transient = 5000;
    const std::size_t samples =
        std::size_t(3e6 * (double(n) / 256.0) * (double(n) / 256.0)) + 200000;
    std::vector<glm::vec3> path(samples);
    glm::dvec3 p(1.0, 1.0, 20.0);
    for (std::size_t s = 0; s < transient; ++s)
        p = rk4Step(p, h);
    glm::dvec3 lo(1e30), hi(-1e30);
    for (std::size_t s = 0; s < samples; ++s) {
        p = rk4Step(p, h);
        path[s] = glm::vec3(p);
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }

    // Phase space to voxel space, per axis: the attractor spans [margin, n - margin]. Each
    // tent filter below reaches 2r voxels, so a margin of both reaches and a voxel keeps the
    // smoothed attractor and its surface off the faces at any n.
    const int attractorRadius = std::max(1, int(std::lround(0.02 * n)));
    const int basinRadius = std::max(1, int(std::lround(0.03 * n)));
    const double margin = std::max(0.09 * n, 2.0 * (attractorRadius + basinRadius) + 1.0);
    const glm::dvec3 scale = (double(n) - 2.0 * margin) / glm::max(hi - lo, glm::dvec3(1e-9));
    SampledField density(n);
    for (const glm::vec3& q : path) {
        const glm::dvec3 u = (glm::dvec3(q) - lo) * scale + margin;
        const glm::ivec3 c =
            glm::clamp(glm::ivec3(glm::floor(u)), glm::ivec3(0), glm::ivec3(n - 1));
        density.v[density.index(c.x, c.y, c.z)] += 1.0f;
    }
    path = {};

    // Attractor voxels: the smoothed time-in-voxel above a level relative to the mean density
    // of a thin sheet (samples spread over ~n^2 voxels), so the same fraction of the volume is
    // attractor at every n.
    smooth(density, attractorRadius);
    const float perSheetVoxel = float(samples) / float(double(n) * n);
    const float attractorLevel = 0.005f * perSheetVoxel;

    AttractorBasinVolume out;
    out.data = VolumeGrid::create({n, n, n}, VoxelType::UByte);
    out.tags = VolumeGrid::create({n, n, n}, VoxelType::UByte);
    auto data = out.data->data<std::uint8_t>();
    auto tags = out.tags->data<std::uint8_t>();

    float maxDensity = 0.0f;
    for (float d : density.v)
        maxDensity = std::max(maxDensity, d);
    const float logRange = std::log(maxDensity / attractorLevel);
    SampledField basin(n); // the attractor's indicator, blurred wide below
    for (std::size_t v = 0; v < density.v.size(); ++v)
        if (density.v[v] >= attractorLevel) {
            tags[v] = AttractorBasinVolume::attractorTag;
            const float t =
                logRange > 0.0f ? std::log(density.v[v] / attractorLevel) / logRange : 1.0f;
            data[v] = std::uint8_t(128 + std::lround(127.0f * std::clamp(t, 0.0f, 1.0f)));
            basin.v[v] = 1.0f;
        }
    density = SampledField(1);

    // The basin region: the wide blur of the indicator above a level, plus the attractor and
    // its 6-neighbours (so the attractor is inside however thin it is somewhere).
    smooth(basin, basinRadius);
    const float basinLevel = 0.08f;
    std::vector<std::uint8_t> region(basin.v.size(), 0);
    const std::size_t sx = 1, sy = std::size_t(n), sz = std::size_t(n) * n;
    // Slices in parallel: each writes only its own voxels and reads the finished tags.
    parallelFor(std::size_t(n), [&](std::size_t kBegin, std::size_t kEnd) {
        for (int k = int(kBegin); k < int(kEnd); ++k)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const std::size_t v = basin.index(i, j, k);
                    bool inside = basin.v[v] >= basinLevel || tags[v] != 0;
                    if (!inside)
                        inside = (i > 0 && tags[v - sx]) || (i + 1 < n && tags[v + sx]) ||
                                 (j > 0 && tags[v - sy]) || (j + 1 < n && tags[v + sy]) ||
                                 (k > 0 && tags[v - sz]) || (k + 1 < n && tags[v + sz]);
                    region[v] = inside;
                    if (!tags[v]) // 0..127, the surface's level at 64
                        data[v] = std::uint8_t(
                            std::lround(std::min(127.0f, 64.0f * basin.v[v] / basinLevel)));
                }
    });

    // The surface: region voxels with a 6-neighbour outside (the volume's outside counts as
    // outside, so a region touching a face would still be closed). Only attractor-free voxels
    // change, and the test reads `region` alone, so slices can run in parallel.
    parallelFor(std::size_t(n), [&](std::size_t kBegin, std::size_t kEnd) {
        for (int k = int(kBegin); k < int(kEnd); ++k)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const std::size_t v = basin.index(i, j, k);
                    if (!region[v] || tags[v] == AttractorBasinVolume::attractorTag) continue;
                    const bool boundary = i == 0 || j == 0 || k == 0 || i == n - 1 || j == n - 1 ||
                                          k == n - 1 || !region[v - sx] || !region[v + sx] ||
                                          !region[v - sy] || !region[v + sy] || !region[v - sz] ||
                                          !region[v + sz];
                    if (boundary) tags[v] = AttractorBasinVolume::basinSurfaceTag;
                }
    });

    for (std::uint8_t t : tags) {
        if (t == AttractorBasinVolume::attractorTag) ++out.attractorVoxels;
        if (t == AttractorBasinVolume::basinSurfaceTag) ++out.surfaceVoxels;
    }
    return out;
}

} // namespace volsg
