#include "TargetCases.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "ImageError.h"
#include "PrintfFormat.h"
#include <volsg/actions/SearchAction.h>
#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/volumescene/ReferenceScene.h>

namespace volsg::bench {

namespace {

namespace fs = std::filesystem;

constexpr const char* kTargetCaseVolume = "SUITE_VOLUME";

/// Opacity per L0 given for side 64 in a box about 2 units wide, for `side` voxels in it.
double opacityFor(double alphaAt64, int side) {
    return 1.0 - std::pow(1.0 - alphaAt64, 64.0 / double(side));
}

enum class View { Ortho, Perspective, Inside };

std::string camera(View v) {
    switch (v) {
    case View::Ortho:
        return "  OrthographicCamera { position 0 1.2 4 orientation 1 0 0 -0.2914567944778671 "
               "height 3.4843 nearDistance 2 farDistance 6.5 focalDistance 4.18 }\n";
    case View::Perspective:
        return "  PerspectiveCamera { position 0 1.2 4 orientation 1 0 0 -0.2914567944778671 "
               "heightAngle 0.9 nearDistance 2 farDistance 6.5 focalDistance 4.18 }\n";
    case View::Inside:
        return "  PerspectiveCamera { position 0 0.1 0.35 heightAngle 0.9 nearDistance 0.05 "
               "farDistance 5 focalDistance 1 }\n";
    }
    return {};
}

std::string scene(const std::string& what, View v, const std::string& data,
                  const std::string& transfer, const std::string& volumeFields = "") {
    return "#Inventor V2.1 ascii\n# volsg-bench error-target sweep: " + what + "\nSeparator {\n" +
           camera(v) + data + transfer + "  DEF " + kTargetCaseVolume + " Volume { " +
           volumeFields + " }\n}\n";
}

std::string ml(int n, const char* type = "UBYTE") {
    return printfFormat("  VolumeData { generator MARSCHNER_LOBB dimensions %g %g %g ", n, n, n) +
           "dataType " + type + " }\n";
}

std::string colourRamp() {
    return "red [ 0 0.1, 0.5 0.9, 1 1 ]  green [ 0 0.3, 0.5 0.6, 1 0.9 ]  "
           "blue [ 0 1, 0.5 0.4, 1 0.1 ]";
}

/// 37 x 23 x 19 USHORT, spacing 1 x 1.5 x 2.5 (scaled so the box is about 2 units): a smooth
/// blob exp(-(r / 0.5)^2) over the box's normalised coordinates, full 16-bit range.
std::string writeAnisotropicBlob(const fs::path& dir) {
    const int nx = 37, ny = 23, nz = 19;
    const double sx = 1.0, sy = 1.5, sz = 2.5;
    std::vector<std::uint16_t> voxels(std::size_t(nx) * ny * nz);
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const double x = ((i + 0.5) * sx / (nx * sx)) * 2.0 - 1.0;
                const double y = ((j + 0.5) * sy / (ny * sy)) * 2.0 - 1.0;
                const double z = ((k + 0.5) * sz / (nz * sz)) * 2.0 - 1.0;
                const double r2 = x * x + y * y + z * z;
                voxels[std::size_t(i) + std::size_t(nx) * (std::size_t(j) + std::size_t(ny) * k)] =
                    std::uint16_t(std::lround(65535.0 * std::exp(-r2 / 0.25)));
            }
    const fs::path file = dir / "aniso-blob-37x23x19-u16.raw";
    std::ofstream(file, std::ios::binary)
        .write(reinterpret_cast<const char*>(voxels.data()), std::streamsize(voxels.size() * 2));
    return file.string();
}

/// n^3 UBYTE: a soft sphere (1 - r / 0.45 n) plus uniform noise of +-12 levels (fixed seed).
std::string writeNoisySphere(const fs::path& dir, int n) {
    std::vector<std::uint8_t> voxels(std::size_t(n) * n * n);
    std::uint32_t h = 12345u;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double c = 0.5 * (n - 1);
                const double r =
                    std::sqrt((i - c) * (i - c) + (j - c) * (j - c) + (k - c) * (k - c));
                h ^= h << 13;
                h ^= h >> 17;
                h ^= h << 5;
                const double noise = (double(h % 25u) - 12.0);
                const double v = 255.0 * std::max(0.0, 1.0 - r / (0.45 * n)) + noise;
                voxels[std::size_t(i) + std::size_t(n) * (std::size_t(j) + std::size_t(n) * k)] =
                    std::uint8_t(std::clamp(std::lround(v), 0L, 255L));
            }
    const fs::path file = dir / printfFormat("noisy-sphere-%g-u8.raw", n);
    std::ofstream(file, std::ios::binary)
        .write(reinterpret_cast<const char*>(voxels.data()), std::streamsize(voxels.size()));
    return file.string();
}

} // namespace

std::vector<TargetCaseSpec> targetCaseSpecs(const std::string& dataDir, bool large) {
    const fs::path dir(dataDir);
    fs::create_directories(dir);
    std::vector<TargetCaseSpec> out;
    const double s64 = 2.0 / 64.0;
    const std::string spacing64 = printfFormat(" spacing %.9g %.9g %.9g }\n", s64, s64, s64);

    // The second case: 37x23x19 USHORT, spacing 1 x 1.5 x 2.5, one narrow spike
    // (0 -> 0.9 -> 0 over 10% of the range), perspective, 128 x 128.
    const double a = 2.0 / 47.5;
    out.push_back({"issue-spike-u16-37x23x19-persp",
                   scene("anisotropic USHORT, narrow spike", View::Perspective,
                         "  VolumeData { fileName \"" + writeAnisotropicBlob(dir) +
                             "\" dimensions 37 23 19 dataType USHORT" +
                             printfFormat(" spacing %.9g %.9g %.9g }\n", a, 1.5 * a, 2.5 * a),
                         "  TransferFunction { red [ 0 1 ] green [ 0 0.7 ] blue [ 0 0.3 ] "
                         "alpha [ 0 0, 0.45 0, 0.5 0.9, 0.55 0, 1 0 ] }\n")});
    out.push_back({"ml64-smooth-persp",
                   scene("Marschner-Lobb 64, smooth ramp", View::Perspective, ml(64),
                         "  TransferFunction { " + colourRamp() +
                             printfFormat(" alpha [ 0 0, 1 %.6g ] }\n", opacityFor(0.06, 64)))});
    out.push_back(
        {"ml64-step-ortho",
         scene("Marschner-Lobb 64, steep step", View::Ortho, ml(64),
               "  TransferFunction { " + colourRamp() +
                   printfFormat(" alpha [ 0 0, 0.5 0, 0.5 %.6g, 1 %.6g ] }\n", 0.15, 0.15))});
    out.push_back({"ml64-spike-persp",
                   scene("Marschner-Lobb 64, narrow spike", View::Perspective, ml(64),
                         "  TransferFunction { red [ 0 1 ] green [ 0 0.6 ] blue [ 0 0.2 ] "
                         "alpha [ 0 0, 0.475 0, 0.5 0.6, 0.525 0, 1 0 ] }\n")});
    out.push_back(
        {"ml64-spikes-inside",
         scene("Marschner-Lobb 64, three spikes, camera inside", View::Inside, ml(64),
               "  TransferFunction { " + colourRamp() +
                   " alpha [ 0 0, 0.2 0, 0.22 0.4, 0.24 0, 0.5 0, 0.52 0.4, 0.54 0, 0.8 0, "
                   "0.82 0.4, 0.84 0, 1 0 ] }\n")});
    out.push_back({"noisy64-ramp-persp",
                   scene("noisy soft sphere 64, smooth ramp", View::Perspective,
                         "  VolumeData { fileName \"" + writeNoisySphere(dir, 64) +
                             "\" dimensions 64 64 64" + spacing64,
                         "  TransferFunction { red [ 0 0.9 ] green [ 0 0.9 ] blue [ 0 0.9 ] "
                         "alpha [ 0 0, 0.3 0, 1 0.08 ] }\n")});
    out.push_back({"ml64-u16-1pct-persp",
                   scene("Marschner-Lobb 64 USHORT, a feature in 1% of the range",
                         View::Perspective, ml(64, "USHORT"),
                         "  TransferFunction { red [ 0 1 ] green [ 0 0.5 ] blue [ 0 0.8 ] "
                         "alpha [ 0 0, 0.495 0, 0.5 0.6, 0.505 0, 1 0 ] }\n")});
    out.push_back({"labelled64-persp",
                   scene("labelled 64, one transfer function per tag", View::Perspective,
                         "  VolumeData { generator LABELLED dimensions 64 64 64" + spacing64,
                         "  TransferFunction { red [ 0 0.7 ] green [ 0 0.7 ] blue [ 0 0.7 ] "
                         "alpha [ 0 0, 1 0.01 ] }\n"
                         "  TransferFunction { tag 1 red [ 0 1 ] green [ 0 0.2 ] blue [ 0 0.1 ] "
                         "alpha [ 0 0, 1 0.15 ] }\n"
                         "  TransferFunction { tag 2 red [ 0 0.2 ] green [ 0 0.9 ] blue [ 0 0.3 ] "
                         "alpha [ 0 0, 0.3 0, 0.35 0.3, 0.4 0, 1 0 ] }\n"
                         "  TransferFunction { tag 3 red [ 0 0.2 ] green [ 0 0.4 ] blue [ 0 1 ] "
                         "alpha [ 0 0.03 ] }\n")});
    out.push_back({"ml32-spike-ortho",
                   scene("Marschner-Lobb 32, narrow spike", View::Ortho, ml(32),
                         "  TransferFunction { red [ 0 1 ] green [ 0 0.6 ] blue [ 0 0.2 ] " +
                             printfFormat("alpha [ 0 0, 0.475 0, 0.5 %.6g, 0.525 0, 1 0 ] }\n",
                                          opacityFor(0.6, 32)))});
    out.push_back(
        {"ml64-mip-persp", scene("Marschner-Lobb 64, MIP", View::Perspective, ml(64),
                                 "  TransferFunction { " + colourRamp() + " alpha [ 0 0, 1 1 ] }\n",
                                 "renderMode MIP")});
    if (large) {
        out.push_back({"ml128-smooth-persp",
                       scene("Marschner-Lobb 128, smooth ramp", View::Perspective, ml(128),
                             "  TransferFunction { " + colourRamp() +
                                 printfFormat(" alpha [ 0 0, 1 %.6g ] }\n", opacityFor(0.06, 128))),
                       256, 256});
        // The first case: 256^3 uint8, 8% of the voxels visible (a soft sphere above
        // v = 0.406), grey ramp, orthographic, 512 x 512.
        const double s256 = 2.0 / 256.0;
        out.push_back(
            {"issue-grey-ramp-256-ortho",
             scene("soft sphere 256, 8% visible, grey ramp", View::Ortho,
                   printfFormat("  VolumeData { generator SOFT_SPHERE dimensions 256 256 256 "
                                "spacing %.9g %.9g %.9g }\n",
                                s256, s256, s256),
                   "  TransferFunction { red [ 0 0, 1 1 ] green [ 0 0, 1 1 ] blue [ 0 0, 1 1 ] " +
                       printfFormat("alpha [ 0 0, 0.406 0, 1 %.6g ] }\n", opacityFor(0.3, 256))),
             512, 512, 4, 2});
    }
    return out;
}

SweepCase loadTargetCase(const TargetCaseSpec& spec, const RenderDebug& debug,
                         const std::string& referenceDir) {
    SweepCase c;
    c.name = spec.name;
    c.root = readSceneFromString(spec.text, spec.name + ".iv");
    Node* named = findByName(*c.root, kTargetCaseVolume);
    c.volume = named && named->isA<Volume>() ? static_cast<Volume*>(named) : nullptr;
    if (!c.volume) throw Error("sweep case " + spec.name + " has no " + kTargetCaseVolume);
    c.options.width = spec.width;
    c.options.height = spec.height;
    c.options.debug = debug;
    c.views = makeOrbitViews(*c.root, c.options, spec.frames, spec.errorFrames);
    const std::vector<RayCastVolume> volumes = collectVolumes(*c.root);
    const VolumeGrid& grid = *volumes.at(0).data;
    c.diagonalL0 = glm::length(grid.extent()) / grid.smallestSpacing();
    RayCastOptions rayOptions;
    for (const int index : c.views.errorIndices) {
        const fs::path file =
            referenceDir.empty()
                ? fs::path()
                : fs::path(referenceDir) /
                      (spec.name + printfFormat("-%gx%g-orbit%g-view%g.pfm", spec.width,
                                                spec.height, spec.frames, index));
        if (!file.empty() && fs::exists(file)) {
            c.reference.push_back(readPfm(file.string()));
            continue;
        }
        RenderOptions options = c.options;
        options.camera = c.views.cameras[std::size_t(index)];
        RayCastResult details;
        renderReference(*c.root, options, &details, rayOptions);
        if (!file.empty()) {
            fs::create_directories(referenceDir);
            writePfm(file.string(), details.image);
        }
        c.reference.push_back(std::move(details.image));
    }
    return c;
}

} // namespace volsg::bench
