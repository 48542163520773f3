// volsg-volpack-bench: VolPack 1.0b3 (Lacroute's shear-warp library) on the same volumes,
// classification and rotating orthographic views as volsg-bench, for the ShearWarpVolume
// baseline of issue 5: median ms/frame, and one frame as PFM with its error against the
// reference ray caster. A benchmark, not a test: it prints and asserts nothing.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "../CommandLine.h"
#include "../bench/ImageError.h"
#include "../bench/ReferenceViews.h"
#include "../bench/Timing.h"
#include "VolPackRenderer.h"
#include <volsg/context/Context.h>
#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/render/Renderer.h>
#include <volsg/volumescene/ReferenceScene.h>

namespace {

using namespace volsg;

/// CPU time of the calling thread in ms. VolPack renders on one thread, so this is its frame
/// time without the waits a loaded machine adds (wall time is printed too).
double threadCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

/// CPU time of the whole process in ms (every thread: the engine's, llvmpipe's, the optimizer's).
double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
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
    "usage: volsg-volpack-bench [--case sphere|ml|ml-shaded|all] [--size N] [--frames N]\n"
    "                           [--frame K] [--out DIR] [--reference [--tolerance T]]\n"
    "                           [--max-ray-opacity X] [--no-pixel-shift] [--side N]\n"
    "                           [--shearwarp [--slice-step N]]\n"
    "       volsg-volpack-bench --compare IMAGE.pfm REFERENCE.pfm\n"
    "  Renders each case with VolPack at NxN (default 512) over N rotating orthographic views\n"
    "  (default 20, after one warm-up frame), the views volsg-bench makes from the scene file it\n"
    "  writes to DIR (default .) as volpack-CASE.iv, and prints the median ms/frame.\n"
    "  Frame K (default 0: the scene's own camera, so `volsg-render volpack-CASE.iv --reference`\n"
    "  renders the same view) is written as volpack-CASE-frameK.pfm/.png.\n"
    "  --reference   also renders frame K with the reference ray caster (tolerance T, default\n"
    "                1e-3) and prints RMSE, PSNR and max abs error of VolPack's frame\n"
    "  --shearwarp   also renders the same views with volsg's ShearWarpVolume (one WHOLE\n"
    "                object, DVR, TF mode or SHADED for ml-shaded: shearwarp-CASE.iv),\n"
    "                alternating frame by frame with VolPack, and prints both medians, the\n"
    "                ratio and (with --reference) both errors; for the node: the whole frame\n"
    "                (GL side and the image read back included), the process CPU per frame,\n"
    "                and the engine alone (ShearWarpRenderer::render: wall time and CPU\n"
    "                summed over its threads)\n"
    "  --slice-step  the node composites every N-th slice (opacity-corrected; its interactive\n"
    "                setting, interactiveSliceStep N), for a comparison at equal error\n"
    "  --compare     prints RMSE, PSNR and max abs error (RGB) of one PFM against another\n"
    "  cases: sphere     soft sphere 256^3, 1.4M voxels visible (8%), grey DVR, unshaded\n"
    "         ml         Marschner-Lobb 256^3, smooth colour transfer function, unshaded\n"
    "         ml-shaded  the same volume and opacity, Phong shading by a headlight (VolPack's\n"
    "                    vpShadeTable; the node's SHADED mode; timed, no reference)\n";

struct Settings {
    std::vector<std::string> cases;
    int size = 512;
    int frames = 20;
    int frame = 0;
    int side = 256;
    std::filesystem::path out = ".";
    bool reference = false;
    double tolerance = 1e-3;
    double maxRayOpacity = 1.0;
    bool pixelShift = true;
    bool shearWarp = false;
    int sliceStep = 1; ///< the node's slice step (1: full quality, a still frame)
};

struct Case {
    std::string name;
    std::string description;
    std::string sceneText;
    bool shaded = false;
    /// The ShearWarpVolume's transfer function when it differs from the scene's (shaded: the
    /// colour ramp over the shading intensity that gives VolPack's material colour).
    std::string shearWarpTransferFunction;
};

std::string number(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.9g", v);
    return buffer;
}

/// An orthographic camera 0.3 rad above the equator that sees a cube of side `extent` centred
/// on the origin whole from every orbit angle (its bounding sphere fits the view height).
std::string cameraFor(double extent) {
    const double radius = 0.5 * std::sqrt(3.0) * extent;
    const double distance = 2.0 * radius, elevation = 0.3;
    return "  OrthographicCamera { position 0 " + number(distance * std::sin(elevation)) + " " +
           number(distance * std::cos(elevation)) + " orientation 1 0 0 " + number(-elevation) +
           " height " + number(2.0 * radius * 1.02) + " nearDistance " +
           number(distance - 1.05 * radius) + " farDistance " + number(distance + 1.05 * radius) +
           " focalDistance " + number(distance) + " }\n";
}

std::vector<Case> makeCases(int side) {
    const std::string n = std::to_string(side);
    std::vector<Case> cases;
    // Soft sphere: v = 1 - r / (0.45 n). Visible where v >= 0.4, a ball of radius 0.27 n:
    // 4/3 pi (0.27 * 256)^3 = 1.40M voxels at n = 256 (8.4% of the volume).
    cases.push_back(
        {"sphere", "soft sphere " + n + "^3, grey DVR, unshaded",
         "#Inventor V2.1 ascii\n# volsg-volpack-bench case sphere: a " + n +
             "^3 8-bit soft "
             "sphere, ~8% of its voxels visible, grey DVR\nSeparator {\n" +
             cameraFor(double(side)) + "  VolumeData { generator SOFT_SPHERE dimensions " + n +
             " " + n + " " + n +
             " }\n"
             "  TransferFunction { red [ 0 0, 0.4 0.2, 1 1 ] green [ 0 0, 0.4 0.2, 1 1 ] "
             "blue [ 0 0, 0.4 0.2, 1 1 ] alpha [ 0 0, 0.399 0, 0.4 0.004, 1 0.05 ] }\n"
             "  Volume { }\n}\n",
         false, ""});
    // Marschner-Lobb with the volume suite's smooth transfer function (its opacity given for
    // 64^3, converted to this side so the optical depth is the same).
    const double alpha = 1.0 - std::pow(1.0 - 0.06, 64.0 / double(side));
    const std::string ml = "#Inventor V2.1 ascii\n# volsg-volpack-bench case ml: Marschner-Lobb " +
                           n + "^3, smooth transfer function (the volume suite's)\nSeparator {\n" +
                           cameraFor(double(side) * 2.0 / double(side - 1)) +
                           "  VolumeData { generator MARSCHNER_LOBB dimensions " + n + " " + n +
                           " " + n +
                           " }\n"
                           "  TransferFunction {\n"
                           "    red [ 0 0.1, 0.5 0.9, 1 1 ]  green [ 0 0.3, 0.5 0.6, 1 0.9 ]  "
                           "blue [ 0 1, 0.5 0.4, 1 0.1 ]\n"
                           "    alpha [ 0 0, 1 " +
                           number(alpha) + " ]\n  }\n  Volume { }\n}\n";
    cases.push_back({"ml", "Marschner-Lobb " + n + "^3, smooth TF, unshaded", ml, false, ""});
    // Shaded, the ShearWarpVolume reads the colour channels as a ramp over the Phong intensity
    // (RTVR's LUT3): black to VolPack's material colour, with the same opacity.
    const glm::dvec3 material = volpack::Shading{}.materialColor;
    const std::string shadedTf = "    TransferFunction { red [ 0 0, 1 " + number(material.r) +
                                 " ] green [ 0 0, 1 " + number(material.g) + " ] blue [ 0 0, 1 " +
                                 number(material.b) + " ] alpha [ 0 0, 1 " + number(alpha) +
                                 " ] }\n";
    cases.push_back({"ml-shaded", "Marschner-Lobb " + n + "^3, Phong shading", ml, true, shadedTf});
    return cases;
}

/// The scene's transfer function (the default one, key -1, or the identity) at each byte.
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

void printError(const char* what, const Image& image, const Image& reference) {
    bench::ImageError error;
    error.add(image, reference);
    std::printf("  %-28s RMSE %.4e  PSNR %.2f dB  max abs %.4e  (%dx%d, RGB)\n", what, error.rmse(),
                error.psnr(), error.maxAbs(), image.width, image.height);
}

void runCase(const Case& c, const Settings& st) {
    std::filesystem::create_directories(st.out);
    const std::filesystem::path scenePath = st.out / ("volpack-" + c.name + ".iv");
    std::ofstream(scenePath) << c.sceneText;
    ref_ptr<Node> root = readScene(scenePath.string());
    const std::vector<RayCastVolume> volumes = collectVolumes(*root);
    if (volumes.size() != 1) throw Error("a VolPack case scene must hold exactly one Volume");
    const RayCastVolume& volume = volumes.front();

    RenderOptions options;
    options.width = options.height = st.size;
    const bench::OrbitViews views = bench::makeOrbitViews(*root, options, st.frames, 0);
    const int keepFrame = std::clamp(st.frame, 0, st.frames - 1);

    volpack::Shading shading;
    shading.enabled = c.shaded;
    shading.lightDirection = glm::dvec3(0.0, 0.0, 1.0); // a headlight, as the ShearWarpVolume's
    std::unique_ptr<volpack::Renderer> renderer;
    const double classifyMs = bench::timeMs([&] {
        renderer = std::make_unique<volpack::Renderer>(*volume.data, classify(volume), shading);
    });
    renderer->setMaxRayOpacity(st.maxRayOpacity);
    renderer->setPixelCenterShift(st.pixelShift);

    // The ShearWarpVolume on the same data, transfer function and views, when asked: the
    // scene with its Volume replaced by one WHOLE object in TF mode composited by DVR.
    std::unique_ptr<Context> context;
    std::unique_ptr<volsg::Renderer> glRenderer;
    ref_ptr<Node> swRoot;
    ShearWarpVolume* swNode = nullptr;
    if (st.shearWarp) {
        std::string text = c.sceneText;
        const std::string volumeNode = "  Volume { }\n";
        text.replace(text.find(volumeNode), volumeNode.size(),
                     "  ShearWarpVolume { interactiveSliceStep " + std::to_string(st.sliceStep) +
                         "\n" + c.shearWarpTransferFunction +
                         "    VolumeObject { source WHOLE voxels VISIBLE renderMode " +
                         (c.shaded ? "SHADED" : "TF") + " compositing DVR }\n  }\n");
        const std::filesystem::path swPath = st.out / ("shearwarp-" + c.name + ".iv");
        std::ofstream(swPath) << text;
        swRoot = readScene(swPath.string());
        swNode = findShearWarp(*swRoot);
        if (!swNode) throw Error("no ShearWarpVolume in " + swPath.string());
        context = Context::createOffscreen(Backend::OSMesa);
        glRenderer = std::make_unique<volsg::Renderer>();
    }
    auto renderShearWarp = [&](int view) {
        RenderOptions o = options;
        o.camera = views.cameras[std::size_t(view)];
        o.interactive = st.sliceStep > 1; // the node's interactiveSliceStep is the step
        return glRenderer->render(*swRoot, o);
    };

    renderer->render(*views.cameras[0], st.size, st.size); // warm-up: buffers, tables
    if (swRoot) renderShearWarp(0);                        // warm-up: extraction, lists
    bench::Samples samples, swSamples, cpuSamples, swCpuSamples, engineSamples, engineCpuSamples;
    Image kept, swKept;
    // Alternating frame by frame, so both see the same machine load.
    for (int i = 0; i < st.frames; ++i) {
        Image image;
        const double cpu0 = threadCpuMs();
        samples.ms.push_back(bench::timeMs(
            [&] { image = renderer->render(*views.cameras[std::size_t(i)], st.size, st.size); }));
        cpuSamples.ms.push_back(threadCpuMs() - cpu0);
        if (i == keepFrame) kept = std::move(image);
        if (swRoot) {
            const double processCpu0 = processCpuMs();
            swSamples.ms.push_back(bench::timeMs([&] { image = renderShearWarp(i); }));
            swCpuSamples.ms.push_back(processCpuMs() - processCpu0);
            const ShearWarpStats& stats = swNode->lastFrame()->stats;
            engineSamples.ms.push_back(stats.engineMs);
            engineCpuSamples.ms.push_back(stats.engineCpuMs);
            if (i == keepFrame) swKept = std::move(image);
        }
    }
    const glm::ivec3 d = volume.data->dimensions();
    std::printf("volpack %-10s %dx%dx%d, %zu voxels classified visible (%.1f%%), %s, %dx%d\n",
                c.name.c_str(), d.x, d.y, d.z, renderer->classifiedVoxels(),
                100.0 * double(renderer->classifiedVoxels()) / double(volume.data->voxelCount()),
                renderer->colorChannels() == 1 ? "grey" : "RGB", st.size, st.size);
    // One row: label, frame count, median and min, then what the row measures.
    const auto row = [](const char* label, const bench::Samples& s, const std::string& what) {
        std::printf("  %-28s %4zu frames  median %8.3f  min %8.3f  ms/frame%s\n", label,
                    s.ms.size(), s.median(), s.min(), what.c_str());
    };
    const auto format = [](const char* pattern, double a, double b = 0.0) {
        char text[160];
        std::snprintf(text, sizeof text, pattern, a, b);
        return std::string(text);
    };
    row(c.description.c_str(), samples,
        format("  (classification %.0f ms, max ray opacity %g)", classifyMs, st.maxRayOpacity));
    row("", cpuSamples, " of VolPack's thread CPU time (its frame time on an idle core)");

    if (swRoot) {
        const auto ratio = [](double volpack, double ours) {
            return volpack / std::max(ours, 1e-9);
        };
        const std::string label =
            st.sliceStep > 1 ? "ShearWarpVolume, slice step " + std::to_string(st.sliceStep)
                             : std::string("ShearWarpVolume, same views");
        row(label.c_str(), swSamples,
            format("  (VolPack / ShearWarpVolume: %.2f)",
                   ratio(samples.median(), swSamples.median())));
        row("", swCpuSamples, " of process CPU time (every thread)");
        row("  engine alone (wall)", engineSamples,
            format("  (VolPack / engine: %.2f)", ratio(samples.median(), engineSamples.median())));
        row("  engine alone (CPU)", engineCpuSamples,
            format(" of CPU time summed over its threads (VolPack CPU / engine CPU: %.2f)",
                   ratio(cpuSamples.median(), engineCpuSamples.median())));
    }
    const std::string stem = "volpack-" + c.name + "-frame" + std::to_string(keepFrame);
    writePfm((st.out / (stem + ".pfm")).string(), kept);
    writePng((st.out / (stem + ".png")).string(), kept);
    std::printf("  wrote %s and %s.png (frame %d)\n", scenePath.string().c_str(),
                (st.out / stem).string().c_str(), keepFrame);
    const std::string swStem = "shearwarp-" + c.name + "-frame" + std::to_string(keepFrame);
    if (swRoot) {
        writePfm((st.out / (swStem + ".pfm")).string(), swKept);
        writePng((st.out / (swStem + ".png")).string(), swKept);
    }

    if (st.reference && !c.shaded) {
        if (!context) context = Context::createOffscreen(Backend::OSMesa);
        RenderOptions view = options;
        view.camera = views.cameras[std::size_t(keepFrame)];
        RayCastOptions rayOptions;
        rayOptions.tolerance = st.tolerance;
        RayCastResult details;
        Image reference;
        const double ms =
            bench::timeMs([&] { reference = renderReference(*root, view, &details, rayOptions); });
        const std::string refStem = "reference-" + c.name + "-frame" + std::to_string(keepFrame);
        writePfm((st.out / (refStem + ".pfm")).string(), reference);
        writePng((st.out / (refStem + ".png")).string(), reference);
        std::printf("  reference (tolerance %g, error bound %.2g, %.0f ms) written as %s.pfm\n",
                    st.tolerance, details.errorBound, ms, (st.out / refStem).string().c_str());
        printError("VolPack vs reference", kept, reference);
        if (swRoot) printError("ShearWarpVolume vs reference", swKept, reference);
    }
}

int run(cli::Arguments& args) {
    Settings st;
    std::vector<std::string> compare;
    const auto number = [](double& target) {
        return [&target](const std::string& v) { target = std::stod(v); };
    };
    cli::Options table;
    table
        .value("--case",
               [&](const std::string& which) {
                   if (which == "all")
                       st.cases = {"sphere", "ml", "ml-shaded"};
                   else
                       st.cases.push_back(which);
               })
        .integer("--size", st.size, 8, 4096)
        .integer("--frames", st.frames, 1, 100000)
        .integer("--frame", st.frame, 0, 100000)
        .integer("--side", st.side, 8, 1024)
        .value("--out", [&](const std::string& v) { st.out = v; })
        .flag("--reference", st.reference)
        .value("--tolerance", number(st.tolerance))
        .value("--slice-step",
               [&](const std::string& v) { st.sliceStep = std::clamp(std::stoi(v), 1, 16); })
        .value("--max-ray-opacity", number(st.maxRayOpacity))
        .flag("--no-pixel-shift", st.pixelShift, false)
        .flag("--shearwarp", st.shearWarp)
        .add("--compare", [&](cli::Arguments& words, const std::string& option) {
            compare.push_back(words.value(option));
            compare.push_back(words.value(option));
        });
    // No operands: a word that is not an option is an unknown argument.
    if (!table.read(args, usage, nullptr)) return 0;
    if (!compare.empty()) {
        printError((compare[0] + " vs " + compare[1]).c_str(), readPfm(compare[0]),
                   readPfm(compare[1]));
        return 0;
    }
    if (st.cases.empty()) st.cases = {"sphere", "ml", "ml-shaded"};
    const std::vector<Case> cases = makeCases(st.side);
    for (const std::string& name : st.cases) {
        auto found =
            std::find_if(cases.begin(), cases.end(), [&](const Case& c) { return c.name == name; });
        if (found == cases.end())
            throw Error("unknown case '" + name + "' (sphere, ml, ml-shaded, all)");
        runCase(*found, st);
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return volsg::cli::runTool("volsg-volpack-bench", argc, argv, run);
}
