#include "SeriesSuite.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <thread>
#include <vector>

#include <sys/resource.h>

#include "ReferenceViews.h"
#include "Timing.h"
#include <volsg/actions/SearchAction.h>
#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeSeries.h>
#include <volsg/render/Renderer.h>
#include <volsg/shearwarp/VoxelObject.h>

namespace volsg::bench {

namespace {

enum class SeriesNode { ShearWarp, Volume };

std::string seriesScene(const SeriesSuiteSettings& st, double budgetMegabytes, SeriesNode node) {
    const double spacing = 2.0 / st.side; // the box is [-1, 1]^3 whatever the side
    const char* transfer =
        "TransferFunction { red [ 0 1, 1 1 ] green [ 0 0.6, 1 0.9 ] blue [ 0 0.2, 1 1 ]\n"
        "                       alpha [ 0 0, 0.15 0, 0.2 0.3, 0.6 0.05, 1 0.6 ] }\n";
    const std::string renderer =
        node == SeriesNode::ShearWarp
            ? std::string("  ShearWarpVolume {\n    ") + transfer + "    VolumeObject { }\n  }\n"
            // 64 planes (not the automatic 2 per voxel, ~600 here): llvmpipe slices 256^3 in
            // seconds otherwise; fewer planes leave the step change's upload a larger share.
            : std::string("  ") + transfer + "  DEF VOLUME Volume { numPlanes 64 }\n";
    char text[1024];
    std::snprintf(text, sizeof text,
                  "#Inventor V2.1 ascii\nSeparator {\n"
                  "  OrthographicCamera { position 0.3 0.4 5 orientation 1 0 0 -0.08 height 2.4 "
                  "nearDistance 1 farDistance 9 }\n"
                  "  DEF SERIES VolumeSeries { timeGenerator MOVING_SPHERE dimensions %d %d %d "
                  "spacing %.9g %.9g %.9g timeSteps 0 %d cacheMegabytes %.6g prefetch %d }\n",
                  st.side, st.side, st.side, spacing, spacing, spacing, st.steps - 1,
                  budgetMegabytes, st.prefetch);
    return text + renderer + "}\n";
}

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(p * double(v.size() - 1) + 0.5))];
}

/// CPU time of the calling thread, ms.
double threadCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

/// Frame times of one phase: wall clock and the render thread's CPU, plus the process's CPU.
struct Phase {
    Samples wall, cpu;
    double processCpu = 0.0, processWall = 0.0;
};

void printFrames(const char* what, const Phase& p) {
    std::printf("%-38s %4zu frames  median %8.1f  p95 %8.1f  max %8.1f  min %8.1f ms"
                "  | render-thread CPU median %7.1f max %7.1f ms | process CPU %.1f s in %.1f s\n",
                what, p.wall.ms.size(), p.wall.median(), percentile(p.wall.ms, 0.95),
                percentile(p.wall.ms, 1.0), p.wall.min(), p.cpu.median(), percentile(p.cpu.ms, 1.0),
                p.processCpu / 1e3, p.processWall / 1e3);
}

double peakRssMegabytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_maxrss) / 1024.0;
}

/// The default budget: a quarter of the series' lists, estimated from the middle step's.
double defaultBudget(const SeriesSuiteSettings& st, const RenderOptions& options) {
    const ref_ptr<Node> root = readSceneFromString(seriesScene(st, 1e6, SeriesNode::ShearWarp));
    auto* series = static_cast<VolumeSeries*>(findByName(*root, "SERIES"));
    Renderer renderer;
    series->step = st.steps / 2;
    renderer.render(*root, options);
    series->cache().waitUntilIdle();
    const SeriesCacheStats s = series->cache().stats();
    const double perStep =
        double(s.memoryBytes) / double(std::max<std::uint64_t>(1, s.extractions + s.diskReads));
    return std::max(1.0, 0.25 * st.steps * perStep / 1048576.0);
}

/// One run from an empty cache: cold steps, then three play-throughs.
void runVariant(const SeriesSuiteSettings& st, RenderOptions options, double budget,
                SeriesNode node, bool improved) {
    const char* name = node == SeriesNode::ShearWarp
                           ? (improved ? "ShearWarpVolume, spill files with RenderLists (after)"
                                       : "ShearWarpVolume, spill files of arrays only (before)")
                           : (improved ? "Volume, uploads staged in a pixel buffer (after)"
                                       : "Volume, direct uploads (before)");
    // The slicer's debug switch (off for every run with --no-texture-staging); the cache's
    // setting.
    options.debug.textureStaging =
        options.debug.textureStaging && !(node == SeriesNode::Volume && !improved);
    const ref_ptr<Node> root = readSceneFromString(seriesScene(st, budget, node));
    auto* series = static_cast<VolumeSeries*>(findByName(*root, "SERIES"));
    if (!series) throw Error("series suite scene has no SERIES node");
    series->cache().setSpillRenderLists(improved || node != SeriesNode::ShearWarp);
    const auto* volume = static_cast<const Volume*>(findByName(*root, "VOLUME"));
    std::uint64_t uploads = 0, staged = 0, refilled = 0;
    Renderer renderer;
    auto frame = [&](Phase& phase) {
        const double cpu0 = threadCpuMs();
        phase.wall.ms.push_back(timeMs([&] { renderer.render(*root, options); }));
        phase.cpu.ms.push_back(threadCpuMs() - cpu0);
        if (volume) {
            // A new step starts a new texture cache: its counters are that step's.
            uploads += volume->slicingStats().brickUploads;
            staged += volume->slicingStats().stagedUploads;
            refilled += volume->slicingStats().refilledTextures;
        }
    };
    auto timed = [&](Phase& phase, auto&& body) {
        const double cpu0 = processCpuMs();
        const auto t0 = std::chrono::steady_clock::now();
        body();
        phase.processCpu = processCpuMs() - cpu0;
        phase.processWall =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
    };

    std::printf("\n== %s\n", name);
    Phase first;
    timed(first, [&] { frame(first); });
    series->cache().waitUntilIdle();
    std::printf("first frame (context, programs, step 0): %.1f ms\n", first.wall.ms.front());

    // Cold steps: jump while paused to steps nobody prepared.
    Phase cold;
    timed(cold, [&] {
        for (int step : {st.steps / 2, st.steps / 4, 3 * st.steps / 4}) {
            series->step = step;
            frame(cold);
            series->cache().waitUntilIdle(); // the prefetch after the jump is not the next jump's
        }
    });
    printFrames("cold step (jump to an unprepared step)", cold);

    // Play through three times from step 0: at the play period, the first pass meets steps for
    // the first time (prefetch races the player) and the second finds every step in memory or
    // on disk (shear-warp; the texture path keeps grids for the prefetch window only); the
    // third plays as fast as frames go (no period).
    series->step = 0;
    renderer.render(*root, options);
    series->cache().waitUntilIdle();
    uploads = staged = refilled = 0;
    const char* names[3] = {"play, first pass", "play, second pass (cached steps)",
                            "play, third pass, no period (cached)"};
    Phase passes[3];
    std::uint64_t sortsBefore[3] = {}, sortsAfter[3] = {}; // RenderLists sorted, any thread
    for (int pass = 0; pass < 3; ++pass) {
        sortsBefore[pass] = VoxelObject::processRenderListBuilds();
        const double period = pass < 2 ? st.playPeriodMs : 0.0;
        timed(passes[pass], [&] {
            for (int i = 1; i <= st.steps; ++i) {
                const auto started = std::chrono::steady_clock::now();
                series->step = i % st.steps;
                frame(passes[pass]);
                if (period > 0)
                    std::this_thread::sleep_until(
                        started + std::chrono::duration<double, std::milli>(period));
            }
        });
        sortsAfter[pass] = VoxelObject::processRenderListBuilds();
        printFrames(names[pass], passes[pass]);
    }
    // What each step costs to draw once it is settled (its lists or textures in place, nothing
    // pending): shown, the cache left to go idle, then drawn twice more, the faster kept. The
    // sphere grows through the series (about 3x the voxels from first to last step), so a
    // frame's excess over its own step's settled time is the stall, not its excess over the
    // median frame.
    std::vector<double> settled(std::size_t(st.steps), 0.0);
    for (int step = 0; step < st.steps; ++step) {
        series->step = step;
        renderer.render(*root, options);
        series->cache().waitUntilIdle();
        double best = 1e300;
        for (int repeat = 0; repeat < 2; ++repeat)
            best = std::min(best, timeMs([&] { renderer.render(*root, options); }));
        settled[std::size_t(step)] = best;
    }
    for (int pass = 1; pass < 3; ++pass) {
        std::vector<double> stalls;
        for (std::size_t i = 0; i < passes[pass].wall.ms.size(); ++i)
            stalls.push_back(passes[pass].wall.ms[i] - settled[(i + 1) % settled.size()]);
        const double median = passes[pass].wall.median();
        const double longest = percentile(stalls, 1.0);
        std::printf("stall on cached steps, pass %d (frame minus its step's settled frame): "
                    "median %.1f  p95 %.1f  max %.1f ms; one frame (median) %.1f ms: %s\n",
                    pass + 1, percentile(stalls, 0.5), percentile(stalls, 0.95), longest, median,
                    longest <= median ? "never longer than one frame" : "LONGER THAN one frame");
    }

    series->cache().waitUntilIdle();
    const SeriesCacheStats s = series->cache().stats();
    std::printf("cache: %llu extractions, %llu grid loads, %llu spills, %llu disk reads, "
                "%llu RenderList sorts by the cache, %llu memory hits, %llu waits for the worker\n",
                (unsigned long long)s.extractions, (unsigned long long)s.gridLoads,
                (unsigned long long)s.spills, (unsigned long long)s.diskReads,
                (unsigned long long)s.renderListSorts, (unsigned long long)s.memoryHits,
                (unsigned long long)s.waits);
    if (!volume)
        std::printf("RenderLists sorted (any thread) per pass: %llu, %llu, %llu\n",
                    (unsigned long long)(sortsAfter[0] - sortsBefore[0]),
                    (unsigned long long)(sortsAfter[1] - sortsBefore[1]),
                    (unsigned long long)(sortsAfter[2] - sortsBefore[2]));
    if (volume)
        std::printf("texture uploads in the passes: %llu bricks, %llu of them from staged "
                    "buffers, %llu into the last step's textures\n",
                    (unsigned long long)uploads, (unsigned long long)staged,
                    (unsigned long long)refilled);
    std::printf("memory: voxel lists high-water %.1f MB (budget %.1f MB, now %.1f MB), grids "
                "high-water %.1f MB, disk %.1f MB, process peak RSS %.0f MB\n",
                double(s.memoryHighWater) / 1048576.0, budget, double(s.memoryBytes) / 1048576.0,
                double(s.gridHighWater) / 1048576.0, double(s.diskBytes) / 1048576.0,
                peakRssMegabytes());
}

} // namespace

int runSeriesSuite(const SeriesSuiteSettings& st) {
    if (st.steps < 4) throw Error("the series suite needs at least 4 steps");
    auto context = Context::createOffscreen(st.backend);
    const RenderOptions options = suiteOptions(st);
    const double budget = st.budgetMegabytes > 0 ? st.budgetMegabytes : defaultBudget(st, options);
    std::printf("series suite: %d steps of %d^3 (MOVING_SPHERE), %dx%d, budget %.1f MB, "
                "prefetch %d, play period %.0f ms; each run starts with an empty cache\n",
                st.steps, st.side, st.width, st.height, budget, st.prefetch, st.playPeriodMs);
    for (const SeriesNode node : {SeriesNode::ShearWarp, SeriesNode::Volume}) {
        if ((node == SeriesNode::ShearWarp && !st.shearWarp) ||
            (node == SeriesNode::Volume && !st.volume))
            continue;
        for (const bool improved : {false, true})
            runVariant(st, options, budget, node, improved);
    }
    return 0;
}

} // namespace volsg::bench
