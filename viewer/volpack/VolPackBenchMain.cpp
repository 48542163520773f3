// volsg-volpack-bench: VolPack 1.0b3 (Lacroute's shear-warp library) and volsg's
// ShearWarpVolume on a family of volumes (VolPackCases.h), the same classification and the same
// rotating orthographic views, alternating frame by frame: medians of VolPack's frame, the node's
// whole frame and its engine at 2 and 1 threads, and both errors against the reference ray
// caster. A benchmark, not a test: it prints and asserts nothing.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "../CommandLine.h"
#include "../bench/ImageError.h"
#include "../bench/PrintfFormat.h"
#include "../bench/ReferenceViews.h"
#include "../bench/Timing.h"
#include "VolPackCases.h"
#include "VolPackRenderer.h"
#include <volsg/context/Context.h>
#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/render/Renderer.h>
#include <volsg/volumescene/ReferenceScene.h>

#ifndef VOLSG_DATA_DIR
#define VOLSG_DATA_DIR ""
#endif

namespace {

using namespace volsg;
using namespace volsg::volpackbench;
using bench::printfFormat;
using bench::processCpuMs;

/// CPU time of the calling thread in ms. VolPack renders on one thread, so this is its frame
/// time without the waits a loaded machine adds (wall time is printed too).
double threadCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

/// The first ShearWarpVolume under `node` (depth first), or null.
ShearWarpVolume* findShearWarp(Node& node) {
    if (node.isA<ShearWarpVolume>()) return static_cast<ShearWarpVolume*>(&node);
    if (auto* children = node.children())
        for (const auto& child : *children)
            if (child)
                if (ShearWarpVolume* found = findShearWarp(*child)) return found;
    return nullptr;
}

const char* usage =
    "usage: volsg-volpack-bench [--case NAME|all]... [--size N] [--frames N] [--frame K]\n"
    "                           [--out DIR] [--data DIR] [--side N] [--no-reference]\n"
    "                           [--tolerance T] [--volpack-only] [--slice-step N]\n"
    "                           [--max-ray-opacity X] [--no-pixel-shift] [--gl-frames]\n"
    "                           [--raw FILE --dims X Y Z [--spacing X Y Z] [--tf LO HI A]]\n"
    "       volsg-volpack-bench --compare IMAGE.pfm REFERENCE.pfm\n"
    "  Renders each case with VolPack and with volsg's ShearWarpVolume (one WHOLE object, DVR,\n"
    "  TF mode, SHADED for the shaded cases) at NxN (default 512) over N rotating orthographic\n"
    "  views (default 20: the scene camera turned about the vertical axis by 2 pi i / N, the\n"
    "  same rotation per frame for both), after one untimed pass over all views. Per frame:\n"
    "  VolPack, the node with 2 threads, the node with 1 thread (alternating, so all see the\n"
    "  same machine load). Prints medians of: VolPack's frame (wall, thread CPU); the node's\n"
    "  whole frame (Renderer::render: the engine and the composite over the background, on the\n"
    "  CPU; with --gl-frames on GL: clear, image upload, composite, float read-back, as a\n"
    "  window's frame is) and its engine alone (wall, CPU over its threads) at 2 and 1 threads; "
    "and, with the\n"
    "  reference (default; cached in DIR), the RMSE of both at frame K against the reference\n"
    "  ray caster on the same rays (unshaded cases: the reference does not shade).\n"
    "  --raw         adds cases raw and raw-shaded: an 8-bit raw volume (x fastest) with a grey\n"
    "                colour and alpha ramp from 0 at byte LO to 1 and A at HI (default 40 255 "
    "0.6)\n"
    "  --slice-step  the node composites every N-th slice (its interactive setting)\n"
    "  --compare     prints RMSE, PSNR and max abs error (RGB) of one PFM against another\n"
    "  cases: sphere shell blobs random1 random10 ml ml-shaded chest-skin[-shaded]\n"
    "         chest-bone[-shaded] head-skin[-shaded] head-bone[-shaded] (raw[-shaded]); all\n";

struct Settings {
    std::vector<std::string> cases;
    int size = 512;
    int frames = 20;
    int frame = 0;
    CaseInputs inputs;
    bool reference = true;
    double tolerance = 1e-3;
    double maxRayOpacity = 1.0;
    bool pixelShift = true;
    bool shearWarp = true;
    int sliceStep = 1;     ///< the node's slice step (1: full quality, a still frame)
    bool glFrames = false; ///< the node's frames on GL (RenderDebug::cpuFrames off)
};

/// What one case measured (medians, ms/frame) and its errors (negative: not measured).
struct CaseResult {
    std::string name;
    std::size_t volpackVoxels = 0;
    double volpack = 0.0, volpackCpu = 0.0;
    /// 2 and 1 threads: the whole frame (wall, process CPU), the engine (wall, CPU).
    double whole[2] = {0.0, 0.0}, wholeCpu[2] = {0.0, 0.0};
    double engine[2] = {0.0, 0.0}, engineCpu[2] = {0.0, 0.0};
    double voxelsRead = 0.0, voxelsHidden = 0.0; ///< the node's, per frame (median)
    double volpackRmse = -1.0, nodeRmse = -1.0;
};

/// The scene classification VolPack is given: the transfer function at each byte.
volpack::Classification classify(const RayCastVolume& volume) {
    const auto found = volume.transferFunctions.find(-1);
    const TransferFunction1D tf =
        found != volume.transferFunctions.end() ? found->second : TransferFunction1D();
    const glm::dvec2 range = tf.resolvedDataRange(*volume.data);
    volpack::Classification c;
    for (int d = 0; d < 256; ++d) {
        const glm::dvec4 rgba = tf.evaluate(TransferFunction1D::normalise(d, range.x, range.y));
        c.color[std::size_t(d)] = glm::dvec3(rgba);
        c.opacity[std::size_t(d)] = rgba.a;
    }
    return c;
}

double printError(const char* what, const Image& image, const Image& reference) {
    bench::ImageError error;
    error.add(image, reference);
    std::printf("  %-30s RMSE %.4e  PSNR %.2f dB  max abs %.4e  (%dx%d, RGB)\n", what, error.rmse(),
                error.psnr(), error.maxAbs(), image.width, image.height);
    return error.rmse();
}

/// The node's scene: the case's with its Volume replaced by a ShearWarpVolume of one WHOLE
/// object (TF mode, or SHADED) composited by DVR.
std::string shearWarpScene(const Case& c, int sliceStep) {
    std::string text = c.sceneText;
    const std::string volumeNode = "  Volume { }\n";
    text.replace(text.find(volumeNode), volumeNode.size(),
                 "  ShearWarpVolume { interactiveSliceStep " + std::to_string(sliceStep) + "\n" +
                     c.shearWarpTransferFunction +
                     "    VolumeObject { source WHOLE voxels VISIBLE renderMode " +
                     (c.shaded ? "SHADED" : "TF") + " compositing DVR }\n  }\n");
    return text;
}

/// The reference of frame K, read from DIR when an earlier run rendered the same scene, view
/// and tolerance (the file name holds a hash of them), else rendered and written.
Image referenceImage(Node& root, const Case& c, const RenderOptions& view, const Settings& st) {
    const std::string key = c.sceneText + "|" + std::to_string(st.size) + "|" +
                            std::to_string(st.frames) + "|" + std::to_string(st.frame) + "|" +
                            std::to_string(st.tolerance);
    char hash[32];
    std::snprintf(hash, sizeof hash, "%016zx", std::hash<std::string>{}(key));
    const std::filesystem::path file =
        st.inputs.out /
        ("reference-" + c.name + "-frame" + std::to_string(st.frame) + "-" + hash + ".pfm");
    if (std::filesystem::exists(file)) {
        std::printf("  reference: %s (cached)\n", file.string().c_str());
        return readPfm(file.string());
    }
    RayCastOptions rayOptions;
    rayOptions.tolerance = st.tolerance;
    RayCastResult details;
    Image reference;
    const double ms =
        bench::timeMs([&] { reference = renderReference(root, view, &details, rayOptions); });
    writePfm(file.string(), reference);
    std::printf("  reference (tolerance %g, error bound %.2g, %.0f ms) written as %s\n",
                st.tolerance, details.errorBound, ms, file.string().c_str());
    return reference;
}

/// The node's side of a case: its scene, renderer and the three timings per frame.
struct NodeRun {
    ref_ptr<Node> root;
    ShearWarpVolume* node = nullptr;
    std::unique_ptr<volsg::Renderer> renderer;
    bench::Samples whole[2], wholeCpu[2], engine[2], engineCpu[2], voxelsRead, voxelsHidden;

    /// A frame into `image` (its storage reused from frame to frame, as VolPack's).
    void render(const RenderOptions& options, const ref_ptr<Camera>& camera, int threads,
                int sliceStep, Image& image) {
        node->threads = threads;
        RenderOptions o = options;
        o.camera = camera;
        o.interactive = sliceStep > 1; // the node's interactiveSliceStep is the step
        renderer->render(*root, o, image);
    }
};

void printRow(const char* label, const bench::Samples& s, const std::string& what) {
    std::printf("  %-30s %4zu frames  median %8.3f  min %8.3f  ms/frame%s\n", label, s.ms.size(),
                s.median(), s.min(), what.c_str());
}

CaseResult runCase(const Case& c, const Settings& st) {
    const std::filesystem::path& out = st.inputs.out;
    const std::filesystem::path scenePath = out / ("volpack-" + c.name + ".iv");
    std::ofstream(scenePath) << c.sceneText;
    ref_ptr<Node> root = readScene(scenePath.string());
    const std::vector<RayCastVolume> volumes = collectVolumes(*root);
    if (volumes.size() != 1) throw Error("a VolPack case scene must hold exactly one Volume");
    const RayCastVolume& volume = volumes.front();

    RenderOptions options;
    options.width = options.height = st.size;
    options.debug.cpuFrames = !st.glFrames;
    const bench::OrbitViews views = bench::makeOrbitViews(*root, options, st.frames, 0);
    const int keepFrame = std::clamp(st.frame, 0, st.frames - 1);

    volpack::Shading shading;
    shading.enabled = c.shaded;
    shading.lightDirection = glm::dvec3(0.0, 0.0, 1.0); // a headlight, as the ShearWarpVolume's
    std::unique_ptr<volpack::Renderer> volpack;
    const double classifyMs = bench::timeMs([&] {
        volpack = std::make_unique<volpack::Renderer>(*volume.data, classify(volume), shading);
    });
    volpack->setMaxRayOpacity(st.maxRayOpacity);
    volpack->setPixelCenterShift(st.pixelShift);

    std::unique_ptr<Context> context = Context::createOffscreen(Backend::OSMesa);
    std::optional<NodeRun> node;
    double extractMs = 0.0;
    if (st.shearWarp) {
        const std::filesystem::path swPath = out / ("shearwarp-" + c.name + ".iv");
        std::ofstream(swPath) << shearWarpScene(c, st.sliceStep);
        node.emplace();
        node->root = readScene(swPath.string());
        node->node = findShearWarp(*node->root);
        if (!node->node) throw Error("no ShearWarpVolume in " + swPath.string());
        node->renderer = std::make_unique<volsg::Renderer>();
        // Untimed: every view once (the extraction and each principal axis's lists), then the
        // optimizer's pass over them, so no timed frame builds lists or competes with it.
        extractMs = bench::timeMs([&] {
            Image image;
            for (const ref_ptr<Camera>& camera : views.cameras)
                node->render(options, camera, 2, st.sliceStep, image);
            node->node->waitForOptimizer();
        });
    }
    volpack->render(*views.cameras[0], st.size, st.size); // warm-up: buffers, tables

    bench::Samples volpackMs, volpackCpu;
    Image kept, swKept, image, swImage;   // each renderer's image reused from frame to frame
    for (int i = 0; i < st.frames; ++i) { // alternating: all see the same machine load
        const ref_ptr<Camera>& camera = views.cameras[std::size_t(i)];
        const double cpu0 = threadCpuMs();
        volpackMs.ms.push_back(
            bench::timeMs([&] { volpack->render(*camera, st.size, st.size, image); }));
        volpackCpu.ms.push_back(threadCpuMs() - cpu0);
        if (i == keepFrame) kept = image;
        if (!node) continue;
        for (int t = 0; t < 2; ++t) {
            const double processCpu0 = processCpuMs();
            node->whole[t].ms.push_back(bench::timeMs(
                [&] { node->render(options, camera, 2 - t, st.sliceStep, swImage); }));
            node->wholeCpu[t].ms.push_back(processCpuMs() - processCpu0);
            const ShearWarpStats& stats = node->node->lastFrame()->stats;
            node->engine[t].ms.push_back(stats.engineMs);
            node->engineCpu[t].ms.push_back(stats.engineCpuMs);
            if (t == 0) {
                node->voxelsRead.ms.push_back(double(stats.voxelsTouched));
                node->voxelsHidden.ms.push_back(double(stats.voxelsHidden));
            }
            if (i == keepFrame && t == 0) swKept = swImage;
        }
    }

    CaseResult r;
    r.name = c.name;
    r.volpackVoxels = volpack->classifiedVoxels();
    r.volpack = volpackMs.median();
    r.volpackCpu = volpackCpu.median();
    const glm::ivec3 d = volume.data->dimensions();
    std::printf("case %-18s %s: %dx%dx%d, %zu voxels classified visible by VolPack (%.1f%%), %s, "
                "%dx%d\n",
                c.name.c_str(), c.description.c_str(), d.x, d.y, d.z, r.volpackVoxels,
                100.0 * double(r.volpackVoxels) / double(volume.data->voxelCount()),
                volpack->colorChannels() == 1 ? "grey" : "RGB", st.size, st.size);
    printRow("VolPack (wall)", volpackMs, printfFormat("  (classification %.0f ms)", classifyMs));
    printRow("VolPack (thread CPU)", volpackCpu, "");
    if (node) {
        for (int t = 0; t < 2; ++t) {
            r.whole[t] = node->whole[t].median();
            r.wholeCpu[t] = node->wholeCpu[t].median();
            r.engine[t] = node->engine[t].median();
            r.engineCpu[t] = node->engineCpu[t].median();
            const std::string threads = std::to_string(2 - t) + (t == 0 ? " threads" : " thread");
            printRow(
                ("node whole frame, " + threads).c_str(), node->whole[t],
                printfFormat("  (VolPack / node: %.2f)", r.volpack / std::max(r.whole[t], 1e-9)));
            printRow(("  engine alone (wall)"), node->engine[t],
                     printfFormat("  (VolPack / engine: %.2f)",
                                  r.volpack / std::max(r.engine[t], 1e-9)));
            printRow("  process CPU", node->wholeCpu[t], "");
            printRow(("  engine alone (CPU)"), node->engineCpu[t], "");
        }
        r.voxelsRead = node->voxelsRead.median();
        r.voxelsHidden = node->voxelsHidden.median();
        std::printf("  node: %.0f voxels read per frame, %.0f of them skipped as hidden (median)\n",
                    r.voxelsRead, r.voxelsHidden);
        std::printf("  node: untimed first pass (extraction, lists, optimizer) %.0f ms\n",
                    extractMs);
    }
    const std::string stem = c.name + "-frame" + std::to_string(keepFrame);
    writePfm((out / ("volpack-" + stem + ".pfm")).string(), kept);
    writePng((out / ("volpack-" + stem + ".png")).string(), kept);
    if (node) {
        writePfm((out / ("shearwarp-" + stem + ".pfm")).string(), swKept);
        writePng((out / ("shearwarp-" + stem + ".png")).string(), swKept);
    }
    if (st.reference && !c.shaded) {
        RenderOptions view = options;
        view.camera = views.cameras[std::size_t(keepFrame)];
        Settings keyed = st;
        keyed.frame = keepFrame;
        const Image reference = referenceImage(*root, c, view, keyed);
        r.volpackRmse = printError("VolPack vs reference", kept, reference);
        if (node) r.nodeRmse = printError("ShearWarpVolume vs reference", swKept, reference);
    }
    std::fflush(stdout);
    return r;
}

/// The tables of every case run (markdown): wall-clock medians with the ratios VolPack / node,
/// then CPU medians (VolPack's thread; the node's engine over its threads and the process
/// during its whole frame, llvmpipe's threads included) and the errors.
void printSummary(const std::vector<CaseResult>& results) {
    const auto ratio = [](double a, double b) { return a / std::max(b, 1e-9); };
    std::printf("\n| case | VolPack | node whole, 2 thr | VolPack / whole 2 | engine 2 thr | node "
                "whole, 1 thr | VolPack / whole 1 | engine 1 thr |\n");
    std::printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (const CaseResult& r : results)
        std::printf("| %s | %.2f | %.2f | **%.2f** | %.2f | %.2f | **%.2f** | %.2f |\n",
                    r.name.c_str(), r.volpack, r.whole[0], ratio(r.volpack, r.whole[0]),
                    r.engine[0], r.whole[1], ratio(r.volpack, r.whole[1]), r.engine[1]);
    const auto rmse = [](double v) { return v < 0.0 ? std::string("-") : printfFormat("%.2e", v); };
    std::printf("\n| case | VolPack voxels | node voxels read (hidden) | VolPack CPU | engine CPU "
                "2 thr | process CPU whole 2 thr | engine CPU 1 thr | RMSE VolPack | RMSE node "
                "|\n");
    std::printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (const CaseResult& r : results)
        std::printf("| %s | %zu | %.0f (%.0f) | %.2f | %.2f | %.2f | %.2f | %s | %s |\n",
                    r.name.c_str(), r.volpackVoxels, r.voxelsRead, r.voxelsHidden, r.volpackCpu,
                    r.engineCpu[0], r.wholeCpu[0], r.engineCpu[1], rmse(r.volpackRmse).c_str(),
                    rmse(r.nodeRmse).c_str());
}

/// A number, or an Error naming the option.
double parseNumber(const std::string& word, const std::string& option) {
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    if (word.empty() || *end != '\0') throw Error(option + ": '" + word + "' is not a number");
    return v;
}

/// `--raw`'s options: the file, then --dims, --spacing, --tf.
void addRawOptions(cli::Options& table, Settings& st) {
    const auto raw = [&st]() -> RawInput& {
        if (!st.inputs.raw) st.inputs.raw.emplace();
        return *st.inputs.raw;
    };
    const auto three = [](cli::Arguments& words, const std::string& option) {
        glm::dvec3 v;
        for (int i = 0; i < 3; ++i)
            v[i] = parseNumber(words.value(option), option);
        return v;
    };
    table.value("--raw", [raw](const std::string& v) { raw().file = v; })
        .add("--dims",
             [raw, three](cli::Arguments& words, const std::string& option) {
                 const glm::dvec3 v = three(words, option);
                 if (!(v.x >= 1 && v.y >= 1 && v.z >= 1 && v.x <= 4096 && v.y <= 4096 &&
                       v.z <= 4096))
                     throw Error("--dims: three sizes in 1..4096");
                 raw().dimensions = glm::ivec3(v);
             })
        .add("--spacing",
             [raw, three](cli::Arguments& words, const std::string& option) {
                 const glm::dvec3 v = three(words, option);
                 if (!(v.x > 0 && v.y > 0 && v.z > 0 && std::isfinite(v.x + v.y + v.z)))
                     throw Error("--spacing: three finite sizes > 0");
                 raw().spacing = v;
             })
        .add("--tf", [raw, three](cli::Arguments& words, const std::string& option) {
            const glm::dvec3 v = three(words, option);
            if (!(v.x >= 0 && v.x < v.y && v.y <= 255 && v.z > 0 && v.z <= 1))
                throw Error("--tf LO HI ALPHA: 0 <= LO < HI <= 255, 0 < ALPHA <= 1");
            raw().tfLow = v.x;
            raw().tfHigh = v.y;
            raw().tfAlpha = v.z;
        });
}

int run(cli::Arguments& args) {
    Settings st;
    st.inputs.out = ".";
    st.inputs.data = VOLSG_DATA_DIR;
    std::vector<std::string> compare;
    bool volpackOnly = false, noReference = false, legacyShearWarp = false;
    const auto number = [](double& target, const char* option) {
        return [&target, option](const std::string& v) { target = parseNumber(v, option); };
    };
    cli::Options table;
    table.value("--case", [&](const std::string& which) { st.cases.push_back(which); })
        .integer("--size", st.size, 8, 4096)
        .integer("--frames", st.frames, 1, 100000)
        .integer("--frame", st.frame, 0, 100000)
        .integer("--side", st.inputs.side, 8, 1024)
        .value("--out", [&](const std::string& v) { st.inputs.out = v; })
        .value("--data", [&](const std::string& v) { st.inputs.data = v; })
        .flag("--reference", st.reference) // the default; kept for older command lines
        .flag("--no-reference", noReference)
        .value("--tolerance", number(st.tolerance, "--tolerance"))
        .value("--slice-step",
               [&](const std::string& v) {
                   const double step = parseNumber(v, "--slice-step");
                   if (!(step >= 1.0 && step <= 16.0)) throw Error("--slice-step: 1 to 16");
                   st.sliceStep = int(step);
               })
        .value("--max-ray-opacity", number(st.maxRayOpacity, "--max-ray-opacity"))
        .flag("--no-pixel-shift", st.pixelShift, false)
        .flag("--gl-frames", st.glFrames)
        .flag("--shearwarp", legacyShearWarp) // the default; kept for older command lines
        .flag("--volpack-only", volpackOnly)
        .add("--compare", [&](cli::Arguments& words, const std::string& option) {
            compare.push_back(words.value(option));
            compare.push_back(words.value(option));
        });
    addRawOptions(table, st);
    if (!table.read(args, usage, nullptr)) return 0;
    if (!compare.empty()) {
        printError((compare[0] + " vs " + compare[1]).c_str(), readPfm(compare[0]),
                   readPfm(compare[1]));
        return 0;
    }
    st.reference = !noReference;
    st.shearWarp = !volpackOnly;
    if (st.inputs.raw && st.inputs.raw->dimensions.x == 0) throw Error("--raw needs --dims X Y Z");
    std::vector<std::string> names;
    for (const std::string& c : st.cases)
        if (c == "all") {
            const std::vector<std::string> every = caseNames(st.inputs);
            names.insert(names.end(), every.begin(), every.end());
        } else {
            names.push_back(c);
        }
    if (names.empty())
        names = st.inputs.raw ? std::vector<std::string>{"raw"} : caseNames(st.inputs);
    std::vector<CaseResult> results;
    for (const std::string& name : names)
        results.push_back(runCase(makeCase(name, st.inputs), st));
    if (results.size() > 1 || st.shearWarp) printSummary(results);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return volsg::cli::runTool("volsg-volpack-bench", argc, argv, run);
}
