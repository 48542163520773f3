#include "RtvrSuite.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <set>

#include "ReferenceViews.h"
#include "Timing.h"
#include <volsg/actions/SearchAction.h>
#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/nodes/VolumeObject.h>
#include <volsg/render/Renderer.h>
#include <volsg/shearwarp/VoxelObject.h>
#include <volsg/volume/TransferFunction1D.h>

#ifndef VOLSG_RTVR_SCENE_DIR
#define VOLSG_RTVR_SCENE_DIR ""
#endif

namespace volsg::bench {

namespace {

constexpr const char* kRtvrVolume = "RTVR_VOLUME";
/// The rows of a scene: each mode with the paper's column (MIP, DVR, DVR mono, mixed) it is
/// compared with.
struct ModeRow {
    RtvrMode mode;
    int paperColumn;
};
constexpr ModeRow kModes[] = {{RtvrMode::Mip, 0},
                              {RtvrMode::MipGeneral, 0},
                              {RtvrMode::Dvr, 1},
                              {RtvrMode::DvrMono, 2},
                              {RtvrMode::MixedMipDvr, 3}};

std::string sceneDirectory(const RtvrSuiteSettings& st) {
    if (!st.sceneDir.empty()) return st.sceneDir;
    if (const char* env = std::getenv("VOLSG_RTVR_SCENE_DIR"); env && *env) return env;
    return VOLSG_RTVR_SCENE_DIR;
}

ShearWarpVolume& suiteVolume(Node& root, const std::string& file) {
    Node* node = findByName(root, kRtvrVolume);
    if (!node || !node->isA<ShearWarpVolume>())
        throw Error(std::string("no ShearWarpVolume named ") + kRtvrVolume, file);
    return static_cast<ShearWarpVolume&>(*node);
}

/// Luminance in place of colour: every control point of any channel gets
/// 0.299 R + 0.587 G + 0.114 B there (exact: the luminance is linear between those points).
void makeGrey(TransferFunction& tf) {
    const TransferFunction1D f = tf.function();
    std::set<float> knots;
    for (const MFVec2f* channel : {&tf.red, &tf.green, &tf.blue})
        for (const glm::vec2& p : channel->getValues())
            knots.insert(p.x);
    std::vector<glm::vec2> grey;
    for (float v : knots) {
        const glm::dvec4 c = f.evaluate(double(v));
        grey.emplace_back(v, float(0.299 * c.r + 0.587 * c.g + 0.114 * c.b));
    }
    tf.red = grey;
    tf.green = grey;
    tf.blue = grey;
}

/// The largest alpha of a transfer function's control points.
float maxAlpha(const TransferFunction& tf) {
    float a = 0.0f;
    for (const glm::vec2& p : tf.alpha.getValues())
        a = std::max(a, p.y);
    return a;
}

void applyMode(ShearWarpVolume& volume, const RtvrScene& scene, RtvrMode mode) {
    if (!volume.children()) return;
    float alpha = 1.0f; // of the transfer function before the object
    for (const ref_ptr<Node>& child : *volume.children()) {
        if (!child) continue;
        if (child->isA<TransferFunction>()) {
            auto& tf = static_cast<TransferFunction&>(*child);
            if (mode == RtvrMode::DvrMono) makeGrey(tf);
            alpha = maxAlpha(tf);
        }
        if (!child->isA<VolumeObject>()) continue;
        auto& object = static_cast<VolumeObject&>(*child);
        const bool mixedMip = std::find(scene.mixedMipObjects.begin(), scene.mixedMipObjects.end(),
                                        object.getName()) != scene.mixedMipObjects.end();
        const bool allMip = mode == RtvrMode::Mip || mode == RtvrMode::MipGeneral;
        if (allMip || (mode == RtvrMode::MixedMipDvr && mixedMip)) {
            object.compositing = VolumeObject::MIP;
            object.renderMode = VolumeObject::TF;
            // MIP shows C(vmax) A(vmax): opacities meant for a DVR sum would leave it dim, so
            // the object's alpha multiplier brings its largest alpha to 1.
            if (alpha > 0.0f) object.opacity = 1.0f / alpha;
        }
    }
    if (mode == RtvrMode::Mip || mode == RtvrMode::MipGeneral)
        volume.interObjectCompositing = ShearWarpVolume::MIP;
    volume.valueSortedMip = mode != RtvrMode::MipGeneral;
    if (mode == RtvrMode::MixedMipDvr) volume.interObjectCompositing = ShearWarpVolume::DVR;
}

/// The voxels the scene's objects extract: each VolumeObject with the transfer function
/// before it among the ShearWarpVolume's children, from the scene's VolumeData.
std::size_t sceneVoxels(Node& root, ShearWarpVolume& volume, const std::string& file) {
    const std::vector<Node*> data = findAll(root, VolumeData::classType());
    if (data.empty()) throw Error("no VolumeData in the scene", file);
    auto& volumeData = static_cast<VolumeData&>(*data.front());
    ref_ptr<const VolumeGrid> grid = volumeData.grid();
    ref_ptr<const VolumeGrid> tags = volumeData.tagGrid();
    std::size_t total = 0;
    TransferFunction1D tf;
    for (const ref_ptr<Node>& child : *volume.children()) {
        if (!child) continue;
        if (child->isA<TransferFunction>())
            tf = static_cast<TransferFunction&>(*child).function();
        else if (child->isA<VolumeObject>())
            total += VoxelObject::extract(*grid, tags.get(),
                                          static_cast<VolumeObject&>(*child).extractionSpec(tf))
                         ->voxelCount();
    }
    return total;
}

void printHeader(const RtvrSuiteSettings& st) {
    std::printf("RTVR table 1 (Mroz & Hauser): ShearWarpVolume, %dx%d, median of %d rotating "
                "orthographic views; paper: 400 MHz Pentium II, JDK 1.3, 512x512\n",
                st.width, st.height, st.frames);
    std::printf("%-22s %-17s %9s %10s %9s %10s %9s %9s\n", "scene", "mode", "voxels", "ms/frame",
                "min ms", "cpu ms", "paper ms", "speed-up");
}

} // namespace

std::vector<RtvrScene> rtvrScenes() {
    return {
        {"rtvr-chest-380k.iv", "hand & vessels", 380, {80, 135, 80, 170}, {"SKIN", "BONE"}},
        {"rtvr-chest-640k.iv", "head & vessels", 640, {100, 185, 110, 290}, {"SKIN", "BONE"}},
        {"rtvr-attractor-basin.iv", "attractor & basin", 1000, {130, 250, 140, 333}, {"ATTRACTOR"}},
    };
}

const char* rtvrModeName(RtvrMode mode) {
    switch (mode) {
    case RtvrMode::Mip:
        return "MIP";
    case RtvrMode::MipGeneral:
        return "MIP, general path";
    case RtvrMode::Dvr:
        return "DVR";
    case RtvrMode::DvrMono:
        return "DVR mono";
    case RtvrMode::MixedMipDvr:
        return "mixed MIP/DVR";
    }
    return "?";
}

std::vector<BenchRow> runRtvrSuite(const RtvrSuiteSettings& st) {
    const std::filesystem::path dir = sceneDirectory(st);
    if (dir.empty())
        throw Error("the rtvr suite needs its scene folder (viewer/bench/scenes): set "
                    "VOLSG_RTVR_SCENE_DIR");
    auto context = Context::createOffscreen(st.backend);
    printHeader(st);
    std::vector<BenchRow> rows;
    for (const RtvrScene& scene : rtvrScenes()) {
        const std::string file = (dir / scene.file).string();
        std::size_t voxels = 0;
        for (std::size_t m = 0; m < std::size(kModes); ++m) {
            const RtvrMode mode = kModes[m].mode;
            const double paperMs = scene.paperMs[kModes[m].paperColumn];
            // A fresh graph per mode: every mode starts from the file as written.
            ref_ptr<Node> root = readScene(file);
            ShearWarpVolume& volume = suiteVolume(*root, file);
            if (m == 0) voxels = sceneVoxels(*root, volume, file);
            applyMode(volume, scene, mode);

            RenderOptions options = suiteOptions(st);
            const OrbitViews views = makeOrbitViews(*root, options, st.frames, 0);
            Renderer renderer;
            options.camera = views.cameras[0];
            const Image first = renderer.render(*root, options); // warm-up: extraction, lists
            volume.waitForOptimizer();
            Samples samples, cpu;
            for (const ref_ptr<Camera>& camera : views.cameras) {
                options.camera = camera;
                const double cpu0 = processCpuMs();
                samples.ms.push_back(timeMs([&] { renderer.render(*root, options); }));
                cpu.ms.push_back(processCpuMs() - cpu0);
            }

            BenchRow row;
            row.scene = std::filesystem::path(scene.file).stem().string();
            row.path = "shearwarp";
            row.setting = rtvrModeName(mode);
            row.ms = samples.median();
            row.frames = int(samples.ms.size());
            row.note = "paper " + std::to_string(int(paperMs)) + " ms (" + scene.paperName + ", " +
                       std::to_string(scene.paperVoxelsK) + "k voxels); scene voxels " +
                       std::to_string(voxels);
            rows.push_back(row);
            std::printf("%-22s %-17s %9zu %10.2f %9.2f %10.2f %9.0f %8.1fx\n", row.scene.c_str(),
                        row.setting.c_str(), voxels, row.ms, samples.min(), cpu.median(), paperMs,
                        paperMs / std::max(row.ms, 1e-9));
            std::fflush(stdout);
            if (!st.keepDir.empty()) {
                std::filesystem::create_directories(st.keepDir);
                std::string name = row.scene + "-" + row.setting;
                std::replace_if(
                    name.begin(), name.end(), [](char c) { return c == ' ' || c == '/'; }, '-');
                writePng((std::filesystem::path(st.keepDir) / (name + ".png")).string(), first);
            }
        }
    }
    return rows;
}

} // namespace volsg::bench
