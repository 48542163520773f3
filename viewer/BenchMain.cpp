// volsg-bench: frame times of a scene seen from orbiting views (and, with --error, their error
// against the reference ray caster), and the built-in suites.
// A benchmark, not a test: it prints medians and minima and asserts nothing.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "CommandLine.h"
#include "VolumeReport.h"
#include "bench/BenchRow.h"
#ifdef VOLSG_BENCH_COIN
#include "bench/CoinSuite.h"
#endif
#include "bench/CompactSuite.h"
#include "bench/ImageError.h"
#include "bench/NodeSuite.h"
#include "bench/OrbitCamera.h"
#include "bench/ReferenceViews.h"
#include "bench/RtvrSuite.h"
#include "bench/SceneGenerators.h"
#include "bench/SeriesSuite.h"
#include "bench/TargetCases.h"
#include "bench/TargetSweep.h"
#include "bench/Timing.h"
#include "bench/VolumeSuite.h"
#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/context/Context.h>
#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Volume.h>
#include <volsg/render/Renderer.h>

namespace {

using namespace volsg;

const char* usage =
    "usage: volsg-bench SCENE.iv [--frames N] [--size WxH] [--backend osmesa|egl]\n"
    "                   [--error [--error-frames K]] [--csv FILE] [--plot FILE.svg]\n"
    "                   [--interactive]   (the viewer's frames while the user drags)\n"
    "                   [--per-frame]   (each view's ms and its volumes' settings)\n"
    "       volsg-bench --suite parse|traversal|all [--nodes N] [--side S] [--frames N]\n"
    "                   [--keep DIR]\n"
    "       volsg-bench --suite series [--size WxH] [--frames STEPS] [--volume-side N]\n"
    "                   [--budget MB] [--cases shearwarp,volume]   (a 100-step series of\n"
    "                   256^3 volumes by default)\n"
    "       volsg-bench --suite compact [--frames REPEATS] [--keep DIR]   (.vsgv of the RTVR\n"
    "                   scenes: bytes per voxel, write and load ms)\n"
    "       volsg-bench --suite volumes [--size WxH] [--frames N] [--error-frames K]\n"
    "                   [--volume-side N] [--csv FILE] [--plot FILE.svg] [--keep DIR]\n"
    "       volsg-bench --suite node [--size WxH] [--frames N] [--error-frames K]\n"
    "                   [--tolerance T] [--planes P,P,...] [--planes-only] [--cases NAME,...]\n"
    "                   [--kinds dvr,dvr-lit,mip] [--samples-per-plane K] [--no-mip-peaks]\n"
    "                   [--scenes DIR]\n"
    "                   [--reference-dir DIR] [--compare DIR [--rows CSV]] [--keep DIR]\n"
    "                   [--csv FILE] [--plot FILE.svg]\n"
    "       volsg-bench --suite node --export-views DIR [--size WxH] [--frames N] ...\n"
    "       volsg-bench --suite coin [--size WxH] [--frames N] [--cases NAME,...]\n"
    "                   [--models FILE|DIR,...] [--read-back] [--keep DIR]   (built where\n"
    "                   Coin is found; --read-back: volsg's frame reads the float image back)\n"
    "       volsg-bench --suite volumes|node --sweep [--targets T,T,...] [--sweep-quick]\n"
    "                   [--before-after]\n"
    "                   [--large] [--cases NAME,...] [--reference-dir DIR] [--csv FILE]\n"
    "       every form also takes the debug switches [--no-empty-cells]\n"
    "                   [--no-texture-staging] [--max-3d-texture N] [--scalar-kernels]\n"
    "                   [--byte-target] [--no-render-caching] [--no-batching]\n"
    "                   [--no-shape-detail] [--gl-frames]\n"
    "                   [--per-fragment-lighting | --per-vertex-lighting]\n"
    "  --error         also compare K of the frames with the reference ray caster (same\n"
    "                  views, same size): RMSE, PSNR and max abs error\n"
    "  --error-frames  how many frames to compare (default: all, at most 4)\n"
    "  --suite volumes generated volume scenes, every volume path and setting: ms/frame,\n"
    "                  error against the reference, memory (default 128x128, 12 frames,\n"
    "                  64^3 voxels; --volume-side 128 for 128^3)\n"
    "  --suite node    the Volume node on Marschner-Lobb 256^3, the chest CT and the head CT\n"
    "                  (scenes in viewer/bench/scenes/node-*.iv; default 512x512, 8 frames, 2\n"
    "                  compared with the reference at --tolerance, default 1e-4): DVR unlit\n"
    "                  and lit, MIP; automatic (2 per voxel), interactive (a quarter) and\n"
    "                  --planes (planes per voxel, default 0.25) plane counts; ms/frame,\n"
    "                  process and node CPU per frame, bricks drawn and skipped, texture\n"
    "                  memory, error\n"
    "  --cases         ml256, chest-ct, head-ct (default all); --kinds: dvr, dvr-lit, mip\n"
    "                  (default all); --planes-only: only the --planes rows;\n"
    "                  --samples-per-plane: the rows' Volume.samplesPerPlane (default 1);\n"
    "                  --no-mip-peaks: the MIP rows with Volume.mipPeaks FALSE\n"
    "  --reference-dir keep the reference images there and reuse them on later runs\n"
    "  --sweep         error targets (Volume.errorTarget): per case a grid of fixed settings,\n"
    "                  the fastest that meets each target against the default at that target,\n"
    "                  and the error model's prediction against the measured error of each\n"
    "                  (--suite volumes: the sweep's own cases, 4 views, all compared; --large\n"
    "                  adds 128^3 and the 256^3 at 512x512; --suite node: its cases, DVR and\n"
    "                  MIP). --targets in 1/255 (default 0.5,0.25,2; the first is the\n"
    "                  default's), --sweep-quick: a coarser grid, --before-after: no grid,\n"
    "                  the old fixed rule (errorTarget 0) and the defaults only\n"
    "  --export-views  write the cameras, volumes and transfer functions of the node suite\n"
    "                  for viewer/vtk/vtk_volume_bench.py into DIR, and stop\n"
    "  --compare DIR   add VTK's rows (DIR/vtk-results.tsv and its PFM frames, written by\n"
    "                  vtk_volume_bench.py) with their error on the same views, and the\n"
    "                  side-by-side table at equal error\n"
    "  --rows CSV      take the Volume node's rows from the CSV of an earlier node-suite run\n"
    "                  instead of timing them again\n"
    "  debug switches: an optimisation off, to measure what it saves (RenderOptions::debug)\n"
    "  --no-empty-cells      Volume: draw the 8^3 cells the transfer function shows nothing of\n"
    "  --no-texture-staging  Volume: upload each VolumeSeries step directly, not staged in a\n"
    "                        pixel buffer while the one before shows\n"
    "  --max-3d-texture N    Volume: bricks of at most N texels a side (below the driver's\n"
    "                        GL_MAX_3D_TEXTURE_SIZE)\n"
    "  --scalar-kernels      ShearWarpVolume: the scalar kernels, not the widest vector ones\n"
    "                        this CPU runs\n"
    "  --byte-target         frames without volumes on an 8-bit target even when float\n"
    "                        pixels are read (the default only for 8-bit output)\n"
    "  --no-render-caching   Separators traverse every frame (no render caches)\n"
    "  --gl-frames           frames of ShearWarpVolumes alone drawn on GL, not composited on\n"
    "                        the CPU\n"
    "  --no-batching         opaque shapes drawn one by one, not as instanced batches\n"
    "  --no-shape-detail     spheres, cones and cylinders always drawn from their full\n"
    "                        tessellation (not the coarser ones small projections allow)\n"
    "  --per-fragment-lighting, --per-vertex-lighting  shapes sum their lights there, not\n"
    "                        where the error model chooses (VertexLighting.h)\n"
    "  --suite coin    the same files through Coin3D (SoGLRenderAction, caching AUTO, +\n"
    "                  glFinish) and volsg (into an 8-bit window framebuffer + glFinish, as the\n"
    "                  viewer draws), frames alternating, median\n"
    "                  ms and Coin/volsg (default 512x512, 20 frames; cases grid, grid-edit,\n"
    "                  grid100k, grid100k-edit, cone, models; --models: the files of the\n"
    "                  models case, default six of /usr/share/inventor/data/models)\n";

struct Settings {
    std::string scene, suite, keepDir, csv, plot;
    int frames = 20;
    bool framesGiven = false;
    int nodes = 100000;
    int side = 100;
    int volumeSide = 64;
    bool volumeSideGiven = false;
    double budgetMegabytes = 0.0; ///< --suite series: the step cache's budget (0: its default)
    bool error = false;
    int errorFrames = 4;
    bool errorFramesGiven = false;
    double tolerance = 0.0; ///< 0: the suite's default
    std::vector<double> planes;
    std::vector<std::string> cases, kinds, models;
    bool planesOnly = false;
    bool perFrame = false; ///< SCENE: print each view's time and volume settings
    bool readBack = false; ///< --suite coin: volsg's frame reads the image back
    int samplesPerPlane = 1;
    bool mipPeaks = true;
    std::string scenesDir = VOLSG_BENCH_SCENES_DIR;
    std::string referenceDir, exportDir, compareDir, rowsCsv;
    bool sweep = false, sweepQuick = false, large = false, beforeAfter = false;
    std::vector<double> targets;
    RenderOptions options;
    bool sizeGiven = false;
    Backend backend = Backend::OSMesa;
};

void printRow(const char* what, const bench::Samples& s, const char* unit = "ms/frame") {
    std::printf("%-44s %6zu runs  median %9.3f  min %9.3f  %s\n", what, s.ms.size(), s.median(),
                s.min(), unit);
}

/// Times the orbit views; keeps the images of the views listed in views.errorIndices.
bench::Samples orbitFrames(Renderer& renderer, Node& root, const RenderOptions& base,
                           const bench::OrbitViews& views, std::vector<Image>* kept = nullptr,
                           std::vector<std::vector<double>>* predicted = nullptr,
                           bool perFrame = false) {
    RenderOptions options = base;
    options.camera = views.cameras[0];
    renderer.render(root, options); // warm-up: shader compiles and uploads are not frames
    bench::Samples samples;
    std::size_t next = 0;
    for (std::size_t i = 0; i < views.cameras.size(); ++i) {
        options.camera = views.cameras[i];
        Image image;
        samples.ms.push_back(bench::timeMs([&] { image = renderer.render(root, options); }));
        if (perFrame) // what each view drew (no prediction cast for it: later frames unchanged)
            for (const std::string& line : cli::volumeQualityLines(root, false))
                std::printf("  view %zu: %.1f ms, %s\n", i, samples.ms.back(), line.c_str());
        if (kept && next < views.errorIndices.size() && views.errorIndices[next] == int(i)) {
            kept->push_back(std::move(image));
            if (predicted) predicted->push_back(cli::predictedErrors(root));
            ++next;
        }
    }
    return samples;
}

bench::Samples orbitFrames(Node& root, const Settings& st) {
    auto context = Context::createOffscreen(st.backend);
    Renderer renderer;
    return orbitFrames(renderer, root, st.options,
                       bench::makeOrbitViews(root, st.options, st.frames, 0));
}

void keep(const Settings& st, const std::string& name, const std::string& text) {
    if (st.keepDir.empty()) return;
    std::filesystem::create_directories(st.keepDir);
    std::ofstream(std::filesystem::path(st.keepDir) / name) << text;
    std::printf("wrote %s/%s\n", st.keepDir.c_str(), name.c_str());
}

void parseSuite(const Settings& st) {
    const std::string text = bench::generateParseScene(st.nodes);
    keep(st, "parse.iv", text);
    bench::Samples s;
    for (int i = 0; i < 5; ++i)
        s.ms.push_back(bench::timeMs([&] { readSceneFromString(text, "parse.iv"); }));
    char what[96];
    std::snprintf(what, sizeof what, "parse %d-node file (%.1f MB)", st.nodes, text.size() / 1e6);
    printRow(what, s, "ms/parse");
}

void traversalSuite(const Settings& st) {
    const std::string text = bench::generateGridScene(st.side);
    keep(st, "traversal.iv", text);
    ref_ptr<Node> root = readSceneFromString(text, "traversal.iv");
    bench::Samples bbox;
    for (int i = 0; i < 20; ++i)
        bbox.ms.push_back(bench::timeMs([&] { computeBoundingBox(*root); }));
    char what[96];
    std::snprintf(what, sizeof what, "bounding box, %dx%d grid (%d shapes)", st.side, st.side,
                  st.side * st.side);
    printRow(what, bbox, "ms/traversal");
    std::snprintf(what, sizeof what, "render %dx%d, %dx%d grid", st.options.width,
                  st.options.height, st.side, st.side);
    printRow(what, orbitFrames(*root, st));
}

void writeOutputs(const Settings& st, const std::vector<bench::BenchRow>& rows,
                  const std::string& title, const std::string& note = {}) {
    if (!st.csv.empty()) {
        bench::writeCsv(st.csv, rows);
        std::printf("wrote %s\n", st.csv.c_str());
    }
    if (!st.plot.empty()) {
        bench::writeRowsPlot(st.plot, title, rows, note);
        std::printf("wrote %s\n", st.plot.c_str());
    }
}

/// A scene file: the frame times of its orbit views, and with --error its error against the
/// reference on K of the same views.
int sceneBenchmark(const Settings& st) {
    ref_ptr<Node> root = readScene(st.scene);
    auto context = Context::createOffscreen(st.backend);
    Renderer renderer;
    const bench::OrbitViews views =
        bench::makeOrbitViews(*root, st.options, st.frames, st.error ? st.errorFrames : 0);
    std::vector<Image> images;
    std::vector<std::vector<double>> predicted; // per error view, per volume node
    const bench::Samples samples =
        orbitFrames(renderer, *root, st.options, views, &images, &predicted, st.perFrame);
    char what[160];
    std::snprintf(what, sizeof what, "%s %dx%d %s%s", st.scene.c_str(), st.options.width,
                  st.options.height, st.backend == Backend::EGL ? "egl" : "osmesa",
                  st.options.interactive ? " interactive" : "");
    printRow(what, samples);
    for (const std::string& line : cli::volumeQualityLines(*root)) // the last view's
        std::printf("  %s\n", line.c_str());

    bench::BenchRow row;
    row.scene = std::filesystem::path(st.scene).stem().string();
    row.path = "gl";
    row.setting = std::to_string(st.options.width) + "x" + std::to_string(st.options.height) +
                  (st.backend == Backend::EGL ? " egl" : " osmesa") +
                  (st.options.interactive ? " interactive" : "");
    row.ms = samples.median();
    row.frames = int(samples.ms.size());
    row.series = "gl";
    std::vector<bench::BenchRow> rows;
    if (st.error) {
        const RayCastOptions rayOptions;
        const bench::ReferenceImages reference =
            bench::renderReferenceViews(*root, st.options, views, rayOptions);
        row.setError(images, reference.images);
        row.note = "reference error bound " + std::to_string(reference.errorBound);
        std::printf("%-44s %6zu views RMSE %.3e  PSNR %.2f dB  max abs %.3e  (reference %.1f "
                    "ms/frame, error bound %.2g%s)\n",
                    "  error vs reference", images.size(), row.rmse, row.psnr, row.maxAbs,
                    reference.ms.median(), reference.errorBound,
                    reference.converged ? "" : ", not converged everywhere");
        // The error model's prediction over the same views (RMS over them), per volume node;
        // with one volume in the scene it is the image's, comparable with the measured RMSE.
        if (!predicted.empty())
            for (std::size_t v = 0; v < predicted.front().size(); ++v) {
                double squares = 0.0;
                bool all = true;
                for (const auto& perView : predicted) {
                    all = all && perView[v] >= 0.0;
                    squares += perView[v] * perView[v];
                }
                if (all)
                    std::printf("  volume #%zu: predicted RMSE %.3g/255, measured %.3g/255 (the "
                                "whole image)\n",
                                v + 1, std::sqrt(squares / double(predicted.size())) * 255.0,
                                row.rmse * 255.0);
                else
                    std::printf("  volume #%zu: no prediction\n", v + 1);
            }
        bench::BenchRow refRow;
        refRow.scene = row.scene;
        refRow.path = "reference";
        refRow.setting = "tolerance " + std::to_string(rayOptions.tolerance);
        refRow.ms = reference.ms.median();
        refRow.frames = int(reference.ms.ms.size());
        refRow.memoryBytes = reference.rssDelta;
        refRow.memoryKind = "rss";
        rows.push_back(refRow);
    }
    rows.insert(rows.begin(), row);
    writeOutputs(st, rows, "volsg-bench " + row.scene + ": RMSE against the reference vs time");
    return 0;
}

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        if (comma > start) out.push_back(text.substr(start, comma - start));
        start = comma + 1;
    }
    return out;
}

double parsePositive(const std::string& text, const std::string& option) {
    std::size_t used = 0;
    double v = 0.0;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || !(v > 0.0) || !std::isfinite(v))
        throw Error(option + " wants positive numbers, got '" + text + "'");
    return v;
}

double parseTolerance(const std::string& text) {
    const double t = parsePositive(text, "--tolerance");
    if (t >= 1.0) throw Error("--tolerance wants a number between 0 and 1, got '" + text + "'");
    return t;
}

/// --suite node: the Volume node on the volumes, or (--export-views) the views and
/// volumes for the VTK script.
int nodeSuite(const Settings& st) {
    bench::NodeSuiteSettings ns;
    if (st.sizeGiven) {
        ns.width = st.options.width;
        ns.height = st.options.height;
    }
    if (st.framesGiven) ns.frames = st.frames;
    if (st.errorFramesGiven) ns.errorFrames = st.errorFrames;
    ns.errorFrames = std::min(ns.errorFrames, ns.frames);
    if (st.tolerance > 0.0) ns.tolerance = st.tolerance;
    if (!st.planes.empty()) ns.planesPerVoxel = st.planes;
    ns.background = st.options.background;
    ns.debug = st.options.debug;
    ns.backend = st.backend;
    ns.scenesDir = st.scenesDir;
    ns.cases = st.cases;
    ns.kinds = st.kinds;
    ns.planesOnly = st.planesOnly;
    ns.samplesPerPlane = st.samplesPerPlane;
    ns.mipPeaks = st.mipPeaks;
    ns.referenceDir = st.referenceDir;
    ns.keepDir = st.keepDir;
    ns.compareDir = st.compareDir;
    ns.rowsCsv = st.rowsCsv;
    if (!st.exportDir.empty()) {
        bench::exportNodeSuiteViews(ns, st.exportDir);
        return 0;
    }
    const std::vector<bench::BenchRow> rows = bench::runNodeSuite(ns);
    char note[200];
    std::snprintf(note, sizeof note,
                  "%dx%d, %d rotating views, %d compared with the reference at tolerance %g; "
                  "labels: planes per voxel",
                  ns.width, ns.height, ns.frames, ns.errorFrames, ns.tolerance);
    writeOutputs(st, rows, "volsg-bench node suite: RMSE against the reference vs time", note);
    return 0;
}

/// --sweep: the error targets against a grid of fixed settings (lib/volsg/slicing/README.md).
int sweepSuite(const Settings& st) {
    bench::SweepSettings sw;
    if (!st.targets.empty()) sw.targets = st.targets;
    sw.quick = st.sweepQuick;
    sw.beforeAfter = st.beforeAfter;
    std::vector<bench::BenchRow> rows;
    std::vector<bench::SweepLine> lines;
    std::vector<bench::ValidationLine> validation;
    const auto wanted = [&](const std::string& name) {
        return st.cases.empty() ||
               std::find(st.cases.begin(), st.cases.end(), name) != st.cases.end();
    };
    auto context = Context::createOffscreen(st.backend);
    bench::printHeader();
    if (st.suite == "volumes") {
        const std::string dataDir =
            st.keepDir.empty()
                ? (std::filesystem::temp_directory_path() / "volsg-bench-sweep").string()
                : st.keepDir;
        for (const bench::TargetCaseSpec& spec : bench::targetCaseSpecs(dataDir, st.large)) {
            if (!wanted(spec.name)) continue;
            bench::SweepCase c = bench::loadTargetCase(spec, st.options.debug, st.referenceDir);
            c.options.background = st.options.background;
            const auto r = bench::runTargetSweep(c, sw, lines, validation);
            rows.insert(rows.end(), r.begin(), r.end());
        }
    } else {
        bench::NodeSuiteSettings ns;
        if (st.sizeGiven) {
            ns.width = st.options.width;
            ns.height = st.options.height;
        }
        if (st.framesGiven) ns.frames = st.frames;
        if (st.errorFramesGiven) ns.errorFrames = st.errorFrames;
        ns.errorFrames = std::min(ns.errorFrames, ns.frames);
        if (st.tolerance > 0.0) ns.tolerance = st.tolerance;
        ns.debug = st.options.debug;
        ns.scenesDir = st.scenesDir;
        ns.cases = st.cases;
        ns.kinds = st.kinds;
        ns.referenceDir = st.referenceDir;
        rows = bench::runNodeSweep(ns, sw, lines, validation);
    }
    bench::printSweepTables(lines, validation);
    writeOutputs(st, rows, "volsg-bench error-target sweep: RMSE against the reference vs time");
    return 0;
}

int run(cli::Arguments& args) {
    Settings st;
    const auto list = [](std::vector<std::string>& target) {
        return [&target](const std::string& v) { target = splitList(v); };
    };
    cli::Options table;
    table.integer("--frames", st.frames, 1, 100000, &st.framesGiven)
        .size("--size", st.options.width, st.options.height, &st.sizeGiven)
        .flag("--error", st.error)
        .flag("--interactive", st.options.interactive)
        .flag("--per-frame", st.perFrame)
        .integer("--error-frames", st.errorFrames, 1, 100000, &st.errorFramesGiven)
        .value("--tolerance", [&](const std::string& v) { st.tolerance = parseTolerance(v); })
        .value("--planes",
               [&](const std::string& v) {
                   for (const std::string& p : splitList(v))
                       st.planes.push_back(parsePositive(p, "--planes"));
               })
        .value("--cases", list(st.cases))
        .value("--kinds", list(st.kinds))
        .value("--models", list(st.models))
        .flag("--planes-only", st.planesOnly)
        .flag("--read-back", st.readBack)
        .integer("--samples-per-plane", st.samplesPerPlane, 1, 256)
        .flag("--no-mip-peaks", st.mipPeaks, false)
        .text("--scenes", st.scenesDir)
        .text("--reference-dir", st.referenceDir)
        .flag("--sweep", st.sweep)
        .flag("--sweep-quick", st.sweepQuick)
        .flag("--before-after", st.beforeAfter)
        .flag("--large", st.large)
        .value("--targets",
               [&](const std::string& v) {
                   for (const std::string& t : splitList(v))
                       st.targets.push_back(parsePositive(t, "--targets"));
               })
        .text("--export-views", st.exportDir)
        .text("--compare", st.compareDir)
        .text("--rows", st.rowsCsv)
        .text("--csv", st.csv)
        .text("--plot", st.plot)
        .integer("--volume-side", st.volumeSide, 2, 1024, &st.volumeSideGiven)
        .value("--budget",
               [&](const std::string& v) { st.budgetMegabytes = parsePositive(v, "--budget"); })
        .color("--background", st.options.background)
        .value("--backend", [&](const std::string& v) { st.backend = parseBackend(v); })
        .text("--suite", st.suite)
        .integer("--nodes", st.nodes, 4, 10000000)
        .integer("--side", st.side, 1, 1000)
        .text("--keep", st.keepDir)
        // Debug switches: RenderOptions::debug.
        .flag("--no-empty-cells", st.options.debug.skipEmptyCells, false)
        .flag("--no-texture-staging", st.options.debug.textureStaging, false)
        .integer("--max-3d-texture", st.options.debug.max3DTextureSize, 2, 16384)
        .flag("--scalar-kernels", st.options.debug.vectorKernels, false)
        .flag("--byte-target", st.options.debug.byteTarget)
        .flag("--gl-frames", st.options.debug.cpuFrames, false)
        .flag("--no-render-caching", st.options.debug.renderCaching, false)
        .flag("--no-batching", st.options.debug.batchShapes, false)
        .flag("--no-shape-detail", st.options.debug.shapeDetail, false)
        .add("--per-fragment-lighting",
             [&](cli::Arguments&, const std::string&) {
                 st.options.debug.shapeLighting = RenderDebug::Lighting::PerFragment;
             })
        .add("--per-vertex-lighting", [&](cli::Arguments&, const std::string&) {
            st.options.debug.shapeLighting = RenderDebug::Lighting::PerVertex;
        });
    const auto scene = [&](const std::string& a) {
        if (!st.scene.empty()) throw Error("more than one scene file given");
        st.scene = a;
    };
    if (!table.read(args, usage, scene)) return 0;
    if (st.scene.empty() == st.suite.empty()) return cli::usageError(usage);
    if (!st.scene.empty()) return sceneBenchmark(st);
    if (st.sweep && (st.suite == "volumes" || st.suite == "node")) return sweepSuite(st);
    if (st.suite == "volumes") {
        bench::VolumeSuiteSettings vs;
        if (st.sizeGiven) {
            vs.width = st.options.width;
            vs.height = st.options.height;
        }
        if (st.framesGiven) vs.frames = st.frames;
        vs.errorFrames = std::min(st.errorFrames, vs.frames);
        vs.side = st.volumeSide;
        vs.background = st.options.background;
        vs.debug = st.options.debug;
        vs.backend = st.backend;
        vs.keepDir = st.keepDir;
        const std::vector<bench::BenchRow> rows = bench::runVolumeSuite(vs);
        char note[200];
        std::snprintf(note, sizeof note,
                      "%dx%d, %d rotating views, %d compared with the reference at tolerance "
                      "1e-4; labels: planes per voxel (slicing), tolerance (reference)",
                      vs.width, vs.height, vs.frames, vs.errorFrames);
        writeOutputs(st, rows, "volsg-bench volume suite: RMSE against the reference vs time",
                     note);
        return 0;
    }
    if (st.suite == "node") return nodeSuite(st);
    if (st.suite == "coin") {
#ifdef VOLSG_BENCH_COIN
        bench::CoinSuiteSettings cs;
        if (st.sizeGiven) {
            cs.width = st.options.width;
            cs.height = st.options.height;
        }
        if (st.framesGiven) cs.frames = st.frames;
        cs.cases = st.cases;
        cs.models = st.models;
        cs.keepDir = st.keepDir;
        cs.debug = st.options.debug;
        cs.readBack = st.readBack;
        return bench::runCoinSuite(cs) > 0 ? 0 : 1;
#else
        throw Error("this volsg-bench was built without Coin3D (libcoin-dev): no coin suite");
#endif
    }
    if (st.suite == "compact") { // .vsgv sizes and times (lib/volsg/voxelfile)
        bench::CompactSuiteSettings cs;
        if (st.framesGiven) cs.repeats = st.frames;
        cs.keepDir = st.keepDir;
        return bench::runCompactSuite(cs);
    }
    if (st.suite == "series") { // time series through the step cache (lib/volsg/series)
        bench::SeriesSuiteSettings ss;
        if (st.sizeGiven) {
            ss.width = st.options.width;
            ss.height = st.options.height;
        }
        if (st.framesGiven) ss.steps = st.frames;
        if (st.volumeSideGiven) ss.side = st.volumeSide;
        ss.budgetMegabytes = st.budgetMegabytes;
        if (!st.cases.empty()) {
            ss.shearWarp = ss.volume = false;
            for (const std::string& c : st.cases) {
                if (c == "shearwarp")
                    ss.shearWarp = true;
                else if (c == "volume")
                    ss.volume = true;
                else
                    throw Error("unknown series case '" + c + "' (shearwarp, volume)");
            }
        }
        ss.backend = st.backend;
        ss.debug = st.options.debug;
        return bench::runSeriesSuite(ss);
    }
    if (st.suite == "rtvr") { // exit code 1 when no row was measured
        const bench::RtvrSuiteSettings rs{st.options.width, st.options.height, st.frames,
                                          st.backend,       st.keepDir,        {},
                                          st.options.debug};
        return bench::runRtvrSuite(rs).empty();
    }
    if (st.suite == "parse" || st.suite == "all") parseSuite(st);
    if (st.suite == "traversal" || st.suite == "all") traversalSuite(st);
    if (st.suite != "parse" && st.suite != "traversal" && st.suite != "all")
        throw Error("unknown suite '" + st.suite +
                    "' (parse, traversal, volumes, node, rtvr, series, all)");
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return volsg::cli::runTool("volsg-bench", argc, argv, run);
}
