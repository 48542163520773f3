#include "SeriesSuite.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include <sys/resource.h>

#include "Timing.h"
#include <volsg/actions/SearchAction.h>
#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/VolumeSeries.h>
#include <volsg/render/Renderer.h>

namespace volsg::bench {

namespace {

std::string seriesScene(const SeriesSuiteSettings& st, double budgetMegabytes) {
    const double spacing = 2.0 / st.side; // the box is [-1, 1]^3 whatever the side
    char text[1024];
    std::snprintf(
        text, sizeof text,
        "#Inventor V2.1 ascii\nSeparator {\n"
        "  OrthographicCamera { position 0.3 0.4 5 orientation 1 0 0 -0.08 height 2.4 "
        "nearDistance 1 farDistance 9 }\n"
        "  DEF SERIES VolumeSeries { timeGenerator MOVING_SPHERE dimensions %d %d %d "
        "spacing %.9g %.9g %.9g timeSteps 0 %d cacheMegabytes %.6g prefetch %d }\n"
        "  ShearWarpVolume {\n"
        "    TransferFunction { red [ 0 1, 1 1 ] green [ 0 0.6, 1 0.9 ] blue [ 0 0.2, 1 1 ]\n"
        "                       alpha [ 0 0, 0.15 0, 0.2 0.3, 0.6 0.05, 1 0.6 ] }\n"
        "    VolumeObject { }\n  }\n}\n",
        st.side, st.side, st.side, spacing, spacing, spacing, st.steps - 1, budgetMegabytes,
        st.prefetch);
    return text;
}

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(p * double(v.size() - 1) + 0.5))];
}

void printFrames(const char* what, const Samples& s) {
    std::printf("%-34s %4zu frames  median %8.1f  p95 %8.1f  max %8.1f  min %8.1f ms\n", what,
                s.ms.size(), s.median(), percentile(s.ms, 0.95), percentile(s.ms, 1.0), s.min());
}

double peakRssMegabytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_maxrss) / 1024.0;
}

} // namespace

int runSeriesSuite(const SeriesSuiteSettings& st) {
    if (st.steps < 4) throw Error("the series suite needs at least 4 steps");
    auto context = Context::createOffscreen(st.backend);
    RenderOptions options;
    options.width = st.width;
    options.height = st.height;

    // Default budget: a quarter of the series' lists, estimated from the middle step's.
    double budget = st.budgetMegabytes;
    if (budget <= 0) {
        SeriesSuiteSettings probe = st;
        const ref_ptr<Node> root = readSceneFromString(seriesScene(probe, 1e6));
        auto* series = static_cast<VolumeSeries*>(findByName(*root, "SERIES"));
        Renderer renderer;
        series->step = st.steps / 2;
        renderer.render(*root, options);
        series->cache().waitUntilIdle();
        const SeriesCacheStats s = series->cache().stats();
        const double perStep =
            double(s.memoryBytes) / double(std::max<std::uint64_t>(1, s.extractions + s.diskReads));
        budget = std::max(1.0, 0.25 * st.steps * perStep / 1048576.0);
    }
    // The measured run starts with an empty cache.
    const ref_ptr<Node> root = readSceneFromString(seriesScene(st, budget));
    auto* series = static_cast<VolumeSeries*>(findByName(*root, "SERIES"));
    if (!series) throw Error("series suite scene has no SERIES node");
    Renderer renderer;
    const double firstFrameMs = timeMs([&] { renderer.render(*root, options); });
    series->cache().waitUntilIdle();
    std::printf("series suite: %d steps of %d^3 (MOVING_SPHERE), %dx%d, budget %.1f MB, "
                "prefetch %d, play period %.0f ms\n",
                st.steps, st.side, st.width, st.height, budget, st.prefetch, st.playPeriodMs);
    std::printf("first frame (context, programs, step 0): %.1f ms\n", firstFrameMs);

    // Cold steps: jump while paused to steps nobody prepared.
    Samples cold;
    for (int step : {st.steps / 2, st.steps / 4, 3 * st.steps / 4}) {
        series->step = step;
        cold.ms.push_back(timeMs([&] { renderer.render(*root, options); }));
        series->cache().waitUntilIdle(); // the prefetch after the jump is not the next jump's
    }
    printFrames("cold step (jump to an unprepared step)", cold);

    // Play through three times from step 0: at the play period, the first pass meets steps for
    // the first time (prefetch races the player) and the second finds every step in memory or
    // on disk; the third plays the cached steps as fast as frames go (no period).
    series->step = 0;
    renderer.render(*root, options);
    series->cache().waitUntilIdle();
    const char* names[3] = {"play, first pass", "play, second pass (cached steps)",
                            "play, third pass, no period (cached)"};
    Samples passes[3];
    for (int pass = 0; pass < 3; ++pass) {
        const double period = pass < 2 ? st.playPeriodMs : 0.0;
        for (int i = 1; i <= st.steps; ++i) {
            const auto started = std::chrono::steady_clock::now();
            series->step = i % st.steps;
            passes[pass].ms.push_back(timeMs([&] { renderer.render(*root, options); }));
            if (period > 0)
                std::this_thread::sleep_until(started +
                                              std::chrono::duration<double, std::milli>(period));
        }
        printFrames(names[pass], passes[pass]);
    }
    for (int pass = 1; pass < 3; ++pass) {
        const double median = passes[pass].median();
        const double stall = percentile(passes[pass].ms, 1.0) - median;
        std::printf("longest stall on cached steps, pass %d: %.1f ms over the median frame of "
                    "%.1f ms (%s one frame)\n",
                    pass + 1, stall, median, stall <= median ? "within" : "MORE THAN");
    }

    series->cache().waitUntilIdle();
    const SeriesCacheStats s = series->cache().stats();
    std::printf("cache: %llu extractions, %llu grid loads, %llu spills, %llu disk reads, "
                "%llu memory hits, %llu waits for the worker\n",
                (unsigned long long)s.extractions, (unsigned long long)s.gridLoads,
                (unsigned long long)s.spills, (unsigned long long)s.diskReads,
                (unsigned long long)s.memoryHits, (unsigned long long)s.waits);
    std::printf("memory: voxel lists high-water %.1f MB (budget %.1f MB, now %.1f MB), grids "
                "high-water %.1f MB, disk %.1f MB, process peak RSS %.0f MB\n",
                double(s.memoryHighWater) / 1048576.0, budget, double(s.memoryBytes) / 1048576.0,
                double(s.gridHighWater) / 1048576.0, double(s.diskBytes) / 1048576.0,
                peakRssMegabytes());
    return 0;
}

} // namespace volsg::bench
