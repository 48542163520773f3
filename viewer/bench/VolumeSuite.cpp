#include "VolumeSuite.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

#include "ImageError.h"
#include "PrintfFormat.h"
#include "ReferenceViews.h"
#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeObject.h>
#include <volsg/render/Renderer.h>

namespace volsg::bench {

namespace {

constexpr const char* kSuiteVolume = "SUITE_VOLUME";
constexpr const char* kShearWarpName = "SUITE_SHEARWARP";

/// Opacity of a slab L0 thick, given for side 64, for a volume of `side` voxels in the same
/// box: L0 scales by 64 / side.
double opacityFor(double alphaAt64, int side) {
    return 1.0 - std::pow(1.0 - alphaAt64, 64.0 / double(side));
}

/// Header, camera and light shared by every suite scene: slightly above the equator, far
/// enough that the box's bounding sphere (radius about sqrt(3)) fits at every orbit angle.
std::string sceneStart(const std::string& name) {
    return "#Inventor V2.1 ascii\n# volsg-bench volume suite: " + name +
           "\nSeparator {\n"
           "  PerspectiveCamera { position 0 1.2 4 orientation 1 0 0 -0.2914567944778671 "
           "heightAngle 0.9 nearDistance 2 farDistance 6.5 focalDistance 4.18 }\n";
}

std::string volumeNode() {
    return std::string("  DEF ") + kSuiteVolume + " Volume { }\n}\n";
}

Volume* findSuiteVolume(Node& node) {
    if (node.getName() == kSuiteVolume && node.isA<Volume>()) return static_cast<Volume*>(&node);
    if (auto* children = node.children())
        for (const auto& child : *children)
            if (child)
                if (Volume* v = findSuiteVolume(*child)) return v;
    return nullptr;
}

ShearWarpVolume* findShearWarp(Node& node) {
    if (node.getName() == kShearWarpName && node.isA<ShearWarpVolume>())
        return static_cast<ShearWarpVolume*>(&node);
    if (auto* children = node.children())
        for (const auto& child : *children)
            if (child)
                if (ShearWarpVolume* v = findShearWarp(*child)) return v;
    return nullptr;
}

/// The suite scene for the shear-warp rows: shear-warp renders parallel projections only, so
/// the perspective camera becomes an orthographic one at the same place whose view height is
/// the perspective frustum's at the focal distance (the volume looks the same size), and the
/// Volume node becomes a ShearWarpVolume with one DVR object per transfer function (per tag
/// for the labelled volume, so each voxel keeps its function).
std::string shearWarpSceneText(const std::string& text, bool labelled) {
    std::string out = text;
    const std::string perspective = "PerspectiveCamera {";
    const std::size_t at = out.find(perspective);
    if (at != std::string::npos) {
        const std::size_t end = out.find('}', at);
        std::string camera = out.substr(at, end + 1 - at);
        camera.replace(0, perspective.size(), "OrthographicCamera {");
        const std::size_t angle = camera.find("heightAngle 0.9 ");
        if (angle != std::string::npos)
            camera.replace(angle, 16, printfFormat("height %.6g ", 2.0 * 4.18 * std::tan(0.45)));
        out.replace(at, end + 1 - at, camera);
    }
    const std::string volume = std::string("DEF ") + kSuiteVolume + " Volume { }";
    const std::size_t v = out.find(volume);
    if (v != std::string::npos) {
        const std::string objects =
            labelled ? "VolumeObject { source TAG tag 0 } VolumeObject { source TAG tag 1 } "
                       "VolumeObject { source TAG tag 2 } VolumeObject { source TAG tag 3 }"
                     : "VolumeObject { }";
        out.replace(v, volume.size(),
                    std::string("DEF ") + kShearWarpName + " ShearWarpVolume { " + objects + " }");
    }
    return out;
}

bool sameImages(const std::vector<Image>& a, const std::vector<Image>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].pixels != b[i].pixels) return false;
    return true;
}

/// A fixed plane count (one sample per plane), or with planesPerVoxel 0 the node's default:
/// every quality field unset, chosen from Volume.errorTarget (interactiveErrorTarget).
struct SlicingSetting {
    double planesPerVoxel;
    bool preIntegrated;
    bool interactive;
    bool automatic() const { return planesPerVoxel <= 0.0; }
};

std::string settingText(const SlicingSetting& s) {
    if (s.automatic())
        return s.interactive ? "default, interactive (interactiveErrorTarget)"
                             : "default, still (errorTarget)";
    return printfFormat("%g planes/voxel", s.planesPerVoxel) +
           (s.interactive ? ", interactive" : ", still") +
           (s.preIntegrated ? ", pre-integrated" : "");
}

std::string seriesOf(const SlicingSetting& s) {
    if (s.automatic()) return "slicing default";
    return std::string("slicing ") + (s.interactive ? "interactive" : "still") +
           (s.preIntegrated ? " pre-integrated" : "");
}

/// Times one render per orbit view (after `betweenFrames`, untimed) and keeps the images of
/// the views listed in views.errorIndices.
template <class BetweenFrames>
Samples timeOrbit(Renderer& renderer, Node& root, RenderOptions options, const OrbitViews& views,
                  std::vector<Image>& images, BetweenFrames&& betweenFrames) {
    Samples samples;
    std::size_t next = 0;
    for (std::size_t i = 0; i < views.cameras.size(); ++i) {
        options.camera = views.cameras[i];
        Image image;
        samples.ms.push_back(timeMs([&] { image = renderer.render(root, options); }));
        betweenFrames();
        if (next < views.errorIndices.size() && views.errorIndices[next] == int(i)) {
            images.push_back(std::move(image));
            ++next;
        }
    }
    return samples;
}

/// Fills the row's time and its error against the reference images of the same views.
void setTimeAndError(BenchRow& row, const Samples& samples, const std::vector<Image>& images,
                     const ReferenceImages& reference) {
    row.ms = samples.median();
    row.frames = int(samples.ms.size());
    row.setError(images, reference.images);
}

/// Times the rotating views with one setting of the Volume node and measures the error views.
BenchRow measureSlicing(Node& root, Volume& volume, const SuiteScene& scene,
                        const SlicingSetting& setting, const VolumeSuiteSettings& st,
                        const OrbitViews& views, const ReferenceImages& reference,
                        std::vector<Image>& images) {
    BenchRow row;
    row.scene = scene.name;
    row.path = "slicing";
    row.setting = settingText(setting);
    row.series = seriesOf(setting);
    row.pointLabel = setting.automatic()
                         ? (setting.interactive ? "default, interactive" : "default")
                         : printfFormat("%g", setting.planesPerVoxel);
    images.clear();

    const glm::dvec3 dims = glm::dvec3(st.side);
    volume.numPlanes =
        setting.automatic() ? 0 : int(std::ceil(setting.planesPerVoxel * glm::length(dims)));
    volume.numPlanes.setDefault(setting.automatic());
    volume.interactivePlanes = 0;
    volume.interactivePlanes.setDefault(true);
    // A fixed row fixes every quality field (one sample per plane); the default row leaves
    // them unset, as a scene that never names them.
    volume.preIntegrated = setting.preIntegrated;
    volume.preIntegrated.setDefault(setting.automatic());
    volume.samplesPerPlane = 1;
    volume.samplesPerPlane.setDefault(setting.automatic());
    RenderOptions options = suiteOptions(st);
    options.background = st.background;
    options.interactive = setting.interactive;
    try {
        const std::size_t rssBefore = residentBytes();
        Renderer renderer;
        options.camera = views.cameras[0];
        renderer.render(root, options); // warm-up: uploads and shader builds are not frames
        const Samples samples = timeOrbit(renderer, root, options, views, images, [] {});
        setTimeAndError(row, samples, images, reference);
        if (volume.slicingStats().textureBytes > 0) {
            row.memoryBytes = volume.slicingStats().textureBytes;
            row.memoryKind = "texture";
        } else {
            const std::size_t rssAfter = residentBytes();
            row.memoryBytes = rssAfter > rssBefore ? rssAfter - rssBefore : 0;
            row.memoryKind = "rss";
        }
    } catch (const Error& e) {
        row.available = false;
        row.note = e.what();
        images.clear();
    }
    return row;
}

/// Times the rotating views with the ShearWarpVolume node: a warm-up pass over every view
/// first (it extracts the objects and builds the lists of every principal axis the orbit
/// uses), then, with `optimized`, waits for the idle-time optimizer before timing. With
/// `interactive`, the frames are the viewer's interactive ones (the node's interactive slice
/// step).
BenchRow measureShearWarp(Node& root, ShearWarpVolume& volume, const SuiteScene& scene, int threads,
                          bool optimized, bool interactive, const VolumeSuiteSettings& st,
                          const OrbitViews& views, const ReferenceImages& reference) {
    BenchRow row;
    row.scene = scene.name;
    row.path = "shear-warp";
    row.setting =
        printfFormat("%g threads", threads) + (optimized ? ", optimized" : ", not optimized") +
        ", orthographic" +
        (interactive ? printfFormat(", interactive (slice step %g)", volume.sliceStepFor(true, 1.0))
                     : std::string());
    row.series = interactive ? "shear-warp interactive"
                 : optimized ? "shear-warp optimized"
                             : "shear-warp";
    row.pointLabel = printfFormat("%g thr", threads);
    volume.threads = threads;
    volume.optimize = optimized;
    RenderOptions options = suiteOptions(st);
    options.interactive = interactive;
    options.background = st.background;
    try {
        Renderer renderer;
        for (const auto& camera : views.cameras) { // warm-up: extraction and lists
            options.camera = camera;
            renderer.render(root, options);
            if (optimized) volume.waitForOptimizer();
        }
        std::vector<Image> images;
        const Samples samples = timeOrbit(renderer, root, options, views, images, [&] {
            if (optimized) volume.waitForOptimizer(); // idle time between frames, not timed
        });
        setTimeAndError(row, samples, images, reference);
        row.memoryBytes = volume.voxelListBytes();
        row.memoryKind = "voxel lists";
    } catch (const Error& e) {
        row.available = false;
        row.note = e.what();
    }
    return row;
}

} // namespace

std::vector<SuiteScene> volumeSuiteScenes(int side) {
    const double n = side;
    const double spacing = 2.0 / n; // every box about [-1, 1]^3
    std::vector<SuiteScene> scenes;

    // Marschner-Lobb keeps its own spacing 2/(n-1): the signal's coordinates.
    const std::string ml =
        printfFormat("  VolumeData { generator MARSCHNER_LOBB dimensions %g %g %g }\n", n, n, n);
    scenes.push_back({printfFormat("marschner-lobb-%g-smooth", n),
                      sceneStart("Marschner-Lobb, smooth transfer function") + ml +
                          "  TransferFunction {\n"
                          "    red [ 0 0.1, 0.5 0.9, 1 1 ]  green [ 0 0.3, 0.5 0.6, 1 0.9 ]  "
                          "blue [ 0 1, 0.5 0.4, 1 0.1 ]\n" +
                          printfFormat("    alpha [ 0 0, 1 %.6g ]\n  }\n", opacityFor(0.06, side)) +
                          volumeNode()});
    scenes.push_back({printfFormat("marschner-lobb-%g-spiky", n),
                      sceneStart("Marschner-Lobb, spiky transfer function (alpha peak 0.05 wide)") +
                          ml +
                          "  TransferFunction {\n"
                          "    red [ 0 1 ]  green [ 0 0.6 ]  blue [ 0 0.2 ]\n" +
                          printfFormat("    alpha [ 0 0, 0.475 0, 0.5 %.6g, 0.525 0, 1 0 ]\n  }\n",
                                       opacityFor(0.6, side)) +
                          volumeNode()});
    scenes.push_back(
        {printfFormat("ramp16-%g", n),
         sceneStart("16-bit ramp through a narrow data window") +
             printfFormat("  VolumeData { generator RAMP16 dimensions %g %g %g ", n, n, n) +
             printfFormat("spacing %.9g %.9g %.9g }\n", spacing, spacing, spacing) +
             "  TransferFunction {\n"
             "    dataRange 30000 36000\n"
             "    red [ 0 1, 1 0.2 ]  green [ 0 0.8, 1 0.5 ]  blue [ 0 0.1, 1 1 ]\n" +
             printfFormat("    alpha [ 0 0, 1 %.6g ]\n  }\n", opacityFor(0.08, side)) +
             volumeNode()});
    scenes.push_back(
        {printfFormat("labelled-%g", n),
         sceneStart("labelled volume, one transfer function per tag") +
             printfFormat("  VolumeData { generator LABELLED dimensions %g %g %g ", n, n, n) +
             printfFormat("spacing %.9g %.9g %.9g }\n", spacing, spacing, spacing) +
             printfFormat("  TransferFunction { red [ 0 0.7 ] green [ 0 0.7 ] blue [ 0 0.7 ] "
                          "alpha [ 0 0, 1 %.6g ] }\n",
                          opacityFor(0.01, side)) +
             printfFormat("  TransferFunction { tag 1 red [ 0 1 ] green [ 0 0.2 ] blue [ 0 0.1 ] "
                          "alpha [ 0 0, 1 %.6g ] }\n",
                          opacityFor(0.15, side)) +
             printfFormat("  TransferFunction { tag 2 red [ 0 0.2 ] green [ 0 0.9 ] blue [ 0 0.3 ] "
                          "alpha [ 0 0, 0.3 0, 1 %.6g ] }\n",
                          opacityFor(0.05, side)) +
             printfFormat("  TransferFunction { tag 3 red [ 0 0.2 ] green [ 0 0.4 ] blue [ 0 1 ] "
                          "alpha [ 0 %.6g ] }\n",
                          opacityFor(0.03, side)) +
             volumeNode()});
    return scenes;
}

std::vector<BenchRow> runVolumeSuite(const VolumeSuiteSettings& st) {
    std::vector<BenchRow> rows;
    auto emit = [&](BenchRow row) {
        printRow(row);
        rows.push_back(std::move(row));
    };
    auto context = Context::createOffscreen(st.backend);
    printHeader();
    for (const SuiteScene& scene : volumeSuiteScenes(st.side)) {
        if (!st.keepDir.empty()) {
            std::filesystem::create_directories(st.keepDir);
            const auto file = std::filesystem::path(st.keepDir) / (scene.name + ".iv");
            std::ofstream(file) << scene.text;
        }
        ref_ptr<Node> root = readSceneFromString(scene.text, scene.name + ".iv");
        Volume* volume = findSuiteVolume(*root);
        if (!volume) throw Error("suite scene " + scene.name + " has no " + kSuiteVolume);

        RenderOptions options = suiteOptions(st);
        options.background = st.background;
        const OrbitViews views = makeOrbitViews(*root, options, st.frames, st.errorFrames);

        // The truth: the reference at its default tolerance on the error views.
        RayCastOptions truthOptions;
        const ReferenceImages truth = renderReferenceViews(*root, options, views, truthOptions);
        BenchRow truthRow;
        truthRow.scene = scene.name;
        truthRow.path = "reference";
        truthRow.setting = printfFormat("tolerance %g (the truth)", truthOptions.tolerance);
        truthRow.ms = truth.ms.median();
        truthRow.frames = int(truth.ms.ms.size());
        truthRow.memoryBytes = truth.rssDelta;
        truthRow.memoryKind = "rss";
        truthRow.note = printfFormat("error bound %.2g", truth.errorBound) +
                        (truth.converged ? "" : ", not converged everywhere");
        emit(truthRow);
        for (double tolerance : {1e-3, 1e-2}) {
            RayCastOptions coarse;
            coarse.tolerance = tolerance;
            const ReferenceImages images = renderReferenceViews(*root, options, views, coarse);
            BenchRow row = truthRow;
            row.setting = printfFormat("tolerance %g", tolerance);
            row.ms = images.ms.median();
            row.setError(images.images, truth.images);
            row.memoryBytes = images.rssDelta;
            row.note = printfFormat("error bound %.2g", images.errorBound);
            row.series = "reference";
            row.pointLabel = printfFormat("tol %g", tolerance);
            emit(row);
        }

        for (bool interactive : {false, true}) {
            std::vector<Image> automatic;
            emit(measureSlicing(*root, *volume, scene, {0.0, false, interactive}, st, views, truth,
                                automatic));
        }
        for (bool interactive : {false, true})
            for (double planes : {0.5, 1.0, 2.0, 4.0}) {
                std::vector<Image> plain, preIntegrated;
                BenchRow off = measureSlicing(*root, *volume, scene, {planes, false, interactive},
                                              st, views, truth, plain);
                emit(off);
                BenchRow on = measureSlicing(*root, *volume, scene, {planes, true, interactive}, st,
                                             views, truth, preIntegrated);
                // Bit-identical images with and without: the node does not pre-integrate.
                if (on.available && off.available && !plain.empty() &&
                    sameImages(plain, preIntegrated)) {
                    on.available = false;
                    on.note = "preIntegrated gives the same image as without: not supported";
                }
                emit(on);
            }

        // Shear-warp: the same volume and transfer functions seen by an orthographic camera,
        // measured against the reference of those views.
        const bool labelled = scene.name.rfind("labelled", 0) == 0;
        ref_ptr<Node> swRoot =
            readSceneFromString(shearWarpSceneText(scene.text, labelled), scene.name + "-sw.iv");
        ShearWarpVolume* shearWarp = findShearWarp(*swRoot);
        if (!shearWarp) throw Error("suite scene " + scene.name + " has no " + kShearWarpName);
        const OrbitViews swViews = makeOrbitViews(*swRoot, options, st.frames, st.errorFrames);
        const ReferenceImages swTruth =
            renderReferenceViews(*swRoot, options, swViews, truthOptions);
        BenchRow swTruthRow = truthRow;
        swTruthRow.setting =
            printfFormat("tolerance %g, orthographic (shear-warp's truth)", truthOptions.tolerance);
        swTruthRow.ms = swTruth.ms.median();
        swTruthRow.frames = int(swTruth.ms.ms.size());
        swTruthRow.memoryBytes = swTruth.rssDelta;
        swTruthRow.note = printfFormat("error bound %.2g", swTruth.errorBound);
        emit(swTruthRow);
        for (bool optimized : {false, true})
            for (int threads : {1, 2})
                emit(measureShearWarp(*swRoot, *shearWarp, scene, threads, optimized, false, st,
                                      swViews, swTruth));
        emit(measureShearWarp(*swRoot, *shearWarp, scene, 2, true, true, st, swViews, swTruth));
    }
    return rows;
}

} // namespace volsg::bench
