// volsg-ooc: out-of-core rendering's test data and measurements (issue 26, part 2).
// `generate` writes a large pyramid without ever holding its volume; `bench` opens a pyramid
// paged under host and texture budgets and reports first image, orbit frame times and I/O,
// resident memory, convergence and the converged image's error against an in-memory render.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "CommandLine.h"
#include "VolumeReport.h"
#include <volsg/context/Context.h>
#include <volsg/core/Error.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/BoxClip.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/Group.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Translation.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/paging/PagedVolume.h>
#include <volsg/render/Renderer.h>
#include <volsg/volumeio/OmeZarrPyramid.h>
#include <volsg/volumeio/PyramidSource.h>
#include <volsg/volumeio/VolumeReader.h>

namespace {

using namespace volsg;
using Clock = std::chrono::steady_clock;

const char* usage =
    "usage: volsg-ooc generate OUT.zarr [--side N] [--chunk C]\n"
    "       volsg-ooc bench PYRAMID.zarr [--size WxH] [--frames N] [--memory MiB]\n"
    "                 [--texture MiB] [--crop N] [--pixels P] [--error-target T]\n"
    "                 [--images DIR]\n"
    "  generate  a UByte N^3 volume (default 2048: 8 GiB) of gyroid sheets in a sphere, written\n"
    "            plane by plane as an OME-Zarr pyramid of C^3 chunks (default 64), zstd\n"
    "  bench     pages the pyramid (VolumeData paging ON, memoryBudget --memory, default\n"
    "            1024; Volume textureBudget --texture, default 512; lodPixels --pixels,\n"
    "            default 1; errorTarget --error-target, default the Volume's, 0: the fixed\n"
    "            rules) and prints: the first image's time; per frame of an orbit of\n"
    "            --frames (default 36) interactive frames its time, bricks, levels, I/O and\n"
    "            memory; the time to converge; peak resident memory against the budgets;\n"
    "            and the converged still image against the in-memory render of a region\n"
    "            that fits memory (a central --crop^3 voxels under a BoxClip, default 256;\n"
    "            the whole volume when level 0 has at most 512 MiB; drawn in memory at a\n"
    "            tenth of the target, and at the target for its time). --images writes PNGs\n"
    "%s";

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// VmRSS and VmHWM of this process, MiB.
std::pair<double, double> residentMiB() {
    std::ifstream in("/proc/self/status");
    std::string line;
    double rss = 0.0, peak = 0.0;
    while (std::getline(in, line)) {
        if (line.rfind("VmRSS:", 0) == 0) rss = std::stod(line.substr(6)) / 1024.0;
        if (line.rfind("VmHWM:", 0) == 0) peak = std::stod(line.substr(6)) / 1024.0;
    }
    return {rss, peak};
}

double mib(std::uint64_t bytes) {
    return double(bytes) / double(1 << 20);
}

// ---- generate ------------------------------------------------------------------------------

/// Gyroid sheets (24 periods across) modulated by a finer gyroid (6 times finer), inside a
/// sphere: structure at every level of the pyramid, empty space around it, made per plane
/// from per-axis sine tables.
int generate(const std::string& out, int side, int chunk) {
    const double kCoarse = 2.0 * M_PI * 12.0, kFine = kCoarse * 6.0;
    const std::size_t n = std::size_t(side);
    std::vector<double> s1(n), c1(n), s2(n), c2(n), u(n);
    for (int i = 0; i < side; ++i) {
        const double p = (i + 0.5) / side * 2.0 - 1.0;
        u[std::size_t(i)] = p;
        s1[std::size_t(i)] = std::sin(kCoarse * p);
        c1[std::size_t(i)] = std::cos(kCoarse * p);
        s2[std::size_t(i)] = std::sin(kFine * p);
        c2[std::size_t(i)] = std::cos(kFine * p);
    }
    constexpr int kTable = 4096; // exp(-(g / w)^2) for g in [-3, 3]
    std::vector<double> sheet(kTable);
    for (int i = 0; i < kTable; ++i) {
        const double g = (i + 0.5) / kTable * 6.0 - 3.0;
        sheet[std::size_t(i)] = std::exp(-(g / 0.25) * (g / 0.25));
    }
    const auto started = Clock::now();
    PyramidOptions options;
    options.chunk = chunk;
    options.codec = ZarrCodec::named("zstd");
    options.codec.level = 1;
    std::printf("volsg-ooc: writing %d^3 UByte (%.2f GiB) to %s\n", side,
                double(side) * side * side / double(1 << 30), out.c_str());
    int lastPercent = -1;
    const std::vector<PyramidLevel> levels = writeOmeZarrPyramid(
        glm::ivec3(side), VoxelType::UByte, glm::dvec3(1.0), VolumeGeometry{},
        [&](int z, std::vector<double>& plane) {
            const std::size_t zi = std::size_t(z);
            for (int y = 0; y < side; ++y) {
                const std::size_t yi = std::size_t(y);
                const double r2yz = u[yi] * u[yi] + u[zi] * u[zi];
                double* row = plane.data() + yi * std::size_t(side);
                for (int x = 0; x < side; ++x) {
                    const std::size_t xi = std::size_t(x);
                    if (r2yz + u[xi] * u[xi] > 0.9) {
                        row[x] = 0.0;
                        continue;
                    }
                    const double g = s1[xi] * c1[yi] + s1[yi] * c1[zi] + s1[zi] * c1[xi];
                    const double f = s2[xi] * c2[yi] + s2[yi] * c2[zi] + s2[zi] * c2[xi];
                    const int k = std::clamp(int((g + 3.0) / 6.0 * kTable), 0, kTable - 1);
                    row[x] = std::round(255.0 * sheet[std::size_t(k)] * (0.7 + 0.2 * f));
                }
            }
        },
        out, options,
        [&](double done) {
            const int percent = int(done * 100.0);
            if (percent != lastPercent && percent % 5 == 0) {
                std::printf("  %3d%%  %.0f s\n", percent, millisecondsSince(started) / 1000.0);
                std::fflush(stdout);
            }
            lastPercent = percent;
        });
    std::uint64_t stored = 0;
    for (const PyramidLevel& l : levels)
        stored += l.storedBytes;
    std::printf("volsg-ooc: %zu levels, %.2f GiB of chunk files, %.0f s\n", levels.size(),
                double(stored) / double(1 << 30), millisecondsSince(started) / 1000.0);
    return 0;
}

// ---- bench ---------------------------------------------------------------------------------

struct BenchOptions {
    std::string pyramid, images;
    int width = 512, height = 512, frames = 36, crop = 256;
    std::uint32_t memoryMiB = 1024, textureMiB = 512;
    double pixels = 1.0;
    double errorTarget = -1.0; ///< the paged Volume's (1/255); < 0: the Volume's default
};

const char* kTransferFunction = R"(TransferFunction {
    dataRange 0 255
    red [ 0 0.9, 0.5 1, 1 1 ]
    green [ 0 0.5, 0.5 0.7, 1 0.95 ]
    blue [ 0 0.2, 0.5 0.35, 1 0.8 ]
    alpha [ 0 0, 0.25 0, 0.5 0.05, 1 0.4 ]
})";

/// A perspective camera at `eye` looking at `target` (+Y up).
ref_ptr<PerspectiveCamera> cameraAt(glm::dvec3 eye, glm::dvec3 target, double range) {
    auto camera = PerspectiveCamera::create();
    camera->position = glm::vec3(eye);
    const glm::vec3 forward = glm::normalize(glm::vec3(target - eye));
    const glm::vec3 axis = glm::cross(glm::vec3(0, 0, -1), forward);
    const float s = glm::length(axis);
    const float angle = std::atan2(s, glm::dot(glm::vec3(0, 0, -1), forward));
    camera->orientation = Rotation{s > 1e-6f ? axis / s : glm::vec3(0, 1, 0), angle};
    const double distance = glm::length(eye - target);
    camera->nearDistance = float(std::max(distance - range, distance * 0.05));
    camera->farDistance = float(distance + range);
    camera->heightAngle = 0.7f;
    return camera;
}

/// The orbit's camera at `step` of `steps` around +Y, `distance` from `target`.
ref_ptr<PerspectiveCamera> orbitCamera(int step, int steps, glm::dvec3 target, double distance,
                                       double range) {
    const double a = 2.0 * M_PI * step / steps + 0.6;
    const glm::dvec3 eye = target + distance * glm::dvec3(std::sin(a), 0.35, std::cos(a));
    return cameraAt(eye, target, range);
}

/// Renders still frames until every paged volume has converged (or 5 minutes pass).
Image converge(Renderer& renderer, Node& root, RenderOptions options, int& frames,
               double& milliseconds) {
    options.interactive = false;
    const auto started = Clock::now();
    Image image = renderer.render(root, options);
    frames = 1;
    while (cli::volumesRefining(root) && millisecondsSince(started) < 300000.0) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        image = renderer.render(root, options);
        ++frames;
    }
    milliseconds = millisecondsSince(started);
    return image;
}

void difference(const Image& a, const Image& b, double& rmse, double& max) {
    double sum = 0.0;
    max = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double e = double(a.pixels[i][c]) - double(b.pixels[i][c]);
            sum += e * e;
            max = std::max(max, std::abs(e));
        }
    rmse = std::sqrt(sum / (3.0 * double(a.pixels.size())));
}

int bench(const BenchOptions& o) {
    auto context = Context::createOffscreen(Backend::OSMesa);
    Renderer renderer;
    {
        // The slicer's programs compiled before the clock starts (llvmpipe takes about a
        // second): the first image measures paging, as a viewer that drew anything before.
        RenderOptions tiny;
        tiny.width = tiny.height = 16;
        renderer.render(*readSceneFromString("#Inventor V2.1 ascii\nSeparator { VolumeData { "
                                             "generator SOFT_SPHERE dimensions 8 8 8 } Volume "
                                             "{ errorTarget 0 } }"),
                        tiny);
    }
    const double target =
        o.errorTarget >= 0.0 ? o.errorTarget : double(Volume::create()->errorTarget());
    const auto opened = Clock::now();
    char sceneText[2048];
    std::snprintf(sceneText, sizeof sceneText,
                  "#Inventor V2.1 ascii\nSeparator { VolumeData { fileName \"%s\" paging ON "
                  "memoryBudget %u } %s "
                  "Volume { textureBudget %llu lodPixels %g errorTarget %g } }",
                  std::filesystem::absolute(o.pyramid).c_str(), o.memoryMiB, kTransferFunction,
                  static_cast<unsigned long long>(std::uint64_t(o.textureMiB) << 20), o.pixels,
                  target);
    ref_ptr<Node> root = readSceneFromString(sceneText);
    auto* data = static_cast<VolumeData*>(root->children()->at(0).get());
    auto* volume = static_cast<Volume*>(root->children()->at(2).get());
    const std::shared_ptr<PagedVolume> paged = data->pagedVolume(); // opens the pyramid
    const double openMs = millisecondsSince(opened);
    if (!paged) throw Error("not paged", o.pyramid);
    const PyramidSource& source = paged->source();
    const glm::ivec3 dims = source.level(0).dimensions;
    const glm::dvec3 extent = glm::dvec3(dims) * source.level(0).spacing;
    const double size = std::max({extent.x, extent.y, extent.z});
    std::printf("pyramid %s: %d x %d x %d %s, %d levels, stand-in level %d, bricks of %d^3\n",
                o.pyramid.c_str(), dims.x, dims.y, dims.z, voxelTypeName(source.type()),
                source.levelCount(), paged->standInLevel(), paged->layout().brickCells());
    std::printf("budgets: host %u MiB, textures %u MiB (limit for resident memory: %.0f MiB = "
                "budgets + 20%%)\n",
                o.memoryMiB, o.textureMiB, 1.2 * (o.memoryMiB + o.textureMiB));

    RenderOptions options;
    options.width = o.width;
    options.height = o.height;
    options.camera = orbitCamera(0, o.frames, glm::dvec3(0.0), 1.6 * size, size);
    const Image first = renderer.render(*root, options);
    const double firstMs = millisecondsSince(opened);
    std::printf("first image: %.0f ms after opening began (opening and the coarse levels "
                "kept whole %.0f ms; levels %d..%d drawn)\n",
                firstMs, openMs, volume->slicingStats().paging.finestLevel,
                volume->slicingStats().paging.coarsestLevel);
    if (!o.images.empty()) writePng(o.images + "/ooc-first.png", first);

    std::printf("orbit, %d interactive frames:\n%5s %8s %6s %7s %7s %8s %9s %8s %8s %7s\n",
                o.frames, "frame", "ms", "bricks", "levels", "worstpx", "loaded", "loadedMiB",
                "hostMiB", "texMiB", "RSSMiB");
    std::vector<double> frameMs;
    double worstRss = 0.0;
    for (int f = 0; f < o.frames; ++f) {
        options.camera = orbitCamera(f, o.frames, glm::dvec3(0.0), 1.6 * size, size);
        options.interactive = true;
        const auto started = Clock::now();
        renderer.render(*root, options);
        const double ms = millisecondsSince(started);
        frameMs.push_back(ms);
        const PagingStats& p = volume->slicingStats().paging;
        const double rss = residentMiB().first;
        worstRss = std::max(worstRss, rss);
        std::printf("%5d %8.1f %6d %4d..%-2d %7.2f %8llu %9.0f %8.0f %8.0f %7.0f\n", f, ms,
                    p.bricksDrawn, p.finestLevel, p.coarsestLevel, p.worstVoxelPixels,
                    static_cast<unsigned long long>(p.bricksLoaded), mib(p.bytesLoaded),
                    mib(p.hostBytes), mib(p.textureBytes), rss);
        std::fflush(stdout);
    }
    std::sort(frameMs.begin(), frameMs.end());
    std::printf("orbit frame ms: median %.1f, 90th percentile %.1f, max %.1f\n",
                frameMs[frameMs.size() / 2], frameMs[frameMs.size() * 9 / 10], frameMs.back());

    int frames = 0;
    double convergeMs = 0.0;
    options.camera = orbitCamera(0, o.frames, glm::dvec3(0.0), 1.6 * size, size);
    const Image still = converge(renderer, *root, options, frames, convergeMs);
    for (const std::string& line : cli::volumeQualityLines(*root))
        std::printf("%s\n", line.c_str());
    std::printf("whole view converged: %d still frames, %.0f ms\n", frames, convergeMs);
    if (!o.images.empty()) writePng(o.images + "/ooc-converged.png", still);

    // The region that fits memory: the whole volume, or a central crop under a BoxClip.
    const std::uint64_t levelBytes = std::uint64_t(dims.x) * std::uint64_t(dims.y) *
                                     std::uint64_t(dims.z) * voxelTypeSize(source.type());
    const bool whole = levelBytes <= (std::uint64_t(512) << 20);
    const glm::ivec3 cropCount = whole ? dims : glm::min(glm::ivec3(o.crop), dims);
    const glm::ivec3 cropFirst = (dims - cropCount) / 2;
    const glm::dvec3 spacing = source.level(0).spacing;
    const glm::dvec3 cropMin = glm::dvec3(cropFirst) * spacing - 0.5 * extent;
    const glm::dvec3 cropSize = glm::dvec3(cropCount) * spacing;
    const glm::dvec3 cropCentre = cropMin + 0.5 * cropSize;
    const double cropExtent = std::max({cropSize.x, cropSize.y, cropSize.z});
    auto clip = BoxClip::create();
    clip->origin = glm::vec3(cropMin);
    clip->extent = glm::vec3(cropSize);
    clip->outsideOpacity = 0.0f;
    if (!whole) static_cast<Group*>(root.get())->insertChild(clip, 2);
    options.camera =
        cameraAt(cropCentre + 1.7 * cropExtent * glm::dvec3(0.55, 0.35, 0.76), cropCentre, size);
    const Image pagedCrop = converge(renderer, *root, options, frames, convergeMs);
    const PagingStats pagedStats = volume->slicingStats().paging;
    // A still frame of the converged region, everything resident: the paged frame's cost.
    options.interactive = false;
    const auto again = Clock::now();
    renderer.render(*root, options);
    const double lastFrameMs = millisecondsSince(again);
    std::printf("region %d x %d x %d from voxel %d %d %d: paged converged in %d frames, %.0f "
                "ms, levels %d..%d, worst voxel %.2f px\n",
                cropCount.x, cropCount.y, cropCount.z, cropFirst.x, cropFirst.y, cropFirst.z,
                frames, convergeMs, pagedStats.finestLevel, pagedStats.coarsestLevel,
                pagedStats.worstVoxelPixels);

    // With one voxel more on each side (where the level has it) under the same BoxClip: the
    // voxels trilinear sampling reads at the crop's faces are the paged volume's.
    const glm::ivec3 readFirst = whole ? cropFirst : glm::max(cropFirst - 1, glm::ivec3(0));
    const glm::ivec3 readCount =
        whole ? cropCount : glm::min(cropFirst + cropCount + 1, dims) - readFirst;
    const ref_ptr<VolumeGrid> region = source.readBox(0, readFirst, readCount);
    region->setGeometry(source.geometry());
    auto inMemory = Separator::create();
    if (!whole) inMemory->addChild(clip);
    auto move = Translation::create();
    move->translation = glm::vec3(glm::dvec3(readFirst) * spacing - 0.5 * extent +
                                  0.5 * glm::dvec3(readCount) * spacing);
    auto regionData = VolumeData::create();
    regionData->adoptLoaded(region, "");
    auto regionVolume = Volume::create();
    inMemory->addChild(move);
    inMemory->addChild(regionData);
    inMemory->addChild(root->children()->at(1)); // the same TransferFunction
    inMemory->addChild(regionVolume);
    options.interactive = false;
    // In memory at the paged frame's own target, for its time (the second frame: the first
    // uploads the region)...
    regionVolume->errorTarget = float(target);
    renderer.render(*inMemory, options);
    const auto inMemoryStarted = Clock::now();
    const Image sameTarget = renderer.render(*inMemory, options);
    const double inMemoryMs = millisecondsSince(inMemoryStarted);
    // ...and at a tenth of it (the fixed rules without a target), the image to compare with.
    regionVolume->errorTarget = float(0.1 * target);
    const Image want = renderer.render(*inMemory, options);
    double rmse = 0.0, max = 0.0, sameRmse = 0.0, sameMax = 0.0;
    difference(pagedCrop, want, rmse, max);
    difference(sameTarget, want, sameRmse, sameMax);
    std::printf("region in memory: %.0f ms a still frame at errorTarget %.2f/255; paged: %.0f ms "
                "(converged, a still frame)\n",
                inMemoryMs, target, lastFrameMs);
    std::printf("against the in-memory render at errorTarget %.3g/255: paged converged RMSE "
                "%.3f/255, max %.1f/255; in memory at %.2f/255: RMSE %.3f/255, max %.1f/255\n",
                0.1 * target, rmse * 255.0, max * 255.0, target, sameRmse * 255.0, sameMax * 255.0);
    if (!o.images.empty()) {
        writePng(o.images + "/ooc-region-paged.png", pagedCrop);
        writePng(o.images + "/ooc-region-in-memory.png", want);
    }
    const auto [rss, peak] = residentMiB();
    worstRss = std::max(worstRss, rss);
    const PagingStats& p = volume->slicingStats().paging;
    std::printf("memory: peak RSS %.0f MiB (VmHWM), %.0f MiB at most during the orbit; limit "
                "%.0f MiB; host bytes %.0f MiB, textures %.0f MiB now\n",
                peak, worstRss, 1.2 * (o.memoryMiB + o.textureMiB), mib(p.hostBytes),
                mib(p.textureBytes));
    std::printf("I/O: %llu bricks, %.0f MiB loaded in %.0f ms of loader time; %llu host "
                "evictions, %llu texture uploads, %llu texture evictions, %llu failures\n",
                static_cast<unsigned long long>(p.bricksLoaded), mib(p.bytesLoaded),
                p.loadMilliseconds, static_cast<unsigned long long>(p.hostEvictions),
                static_cast<unsigned long long>(p.textureUploads),
                static_cast<unsigned long long>(p.textureEvictions),
                static_cast<unsigned long long>(p.loadFailures));
    return 0;
}

int run(cli::Arguments& args) {
    if (args.empty()) return cli::usageError(usage);
    const std::string what = args.take();
    if (what == "-h" || what == "--help") {
        std::printf(usage, "");
        return 0;
    }
    if (args.empty()) return cli::usageError(usage);
    const std::string target = args.take();
    if (what == "generate") {
        int side = 2048, chunk = 64;
        while (!args.empty()) {
            const std::string option = args.take();
            if (option == "--side")
                side = args.intValue(option, 2, 65536);
            else if (option == "--chunk")
                chunk = args.intValue(option, 4, 1024);
            else
                return cli::usageError(usage);
        }
        return generate(target, side, chunk);
    }
    if (what != "bench") return cli::usageError(usage);
    BenchOptions o;
    o.pyramid = target;
    while (!args.empty()) {
        const std::string option = args.take();
        if (option == "--size") {
            const glm::ivec2 s = cli::parseSize(args.value(option));
            o.width = s.x;
            o.height = s.y;
        } else if (option == "--frames") {
            o.frames = args.intValue(option, 1, 100000);
        } else if (option == "--memory") {
            o.memoryMiB = std::uint32_t(args.intValue(option, 1, 1 << 20));
        } else if (option == "--texture") {
            o.textureMiB = std::uint32_t(args.intValue(option, 1, 4095));
        } else if (option == "--crop") {
            o.crop = args.intValue(option, 1, 65536);
        } else if (option == "--pixels") {
            o.pixels = std::stod(args.value(option));
        } else if (option == "--error-target") {
            o.errorTarget = std::stod(args.value(option));
            if (!(o.errorTarget >= 0.0 && o.errorTarget <= 255.0))
                throw Error("--error-target wants 0..255 (1/255 units), got " +
                            std::to_string(o.errorTarget));
        } else if (option == "--images") {
            o.images = args.value(option);
        } else {
            return cli::usageError(usage);
        }
    }
    return bench(o);
}

} // namespace

int main(int argc, char** argv) {
    return volsg::cli::runTool("volsg-ooc", argc, argv, run);
}
