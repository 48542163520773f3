// volsg-render: renders a scene file headless to PNG or PFM, or writes it back as a scene file.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "CommandLine.h"
#include "VolumeReport.h"
#include <volsg/context/Context.h>
#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/render/Renderer.h>
#include <volsg/render/StereoRenderer.h>
#include <volsg/volumescene/ReferenceScene.h>
#include <volsg/voxelfile/VoxelFileScene.h>

namespace {

const char* usage =
    "usage: volsg-render SCENE -o OUT.png|OUT.pfm|OUT.iv [--size WxH] [--backend osmesa|egl]\n"
    "  (SCENE: a scene file or a .vsgv voxel-list file written by volsg-pack)\n"
    "                    [--background R,G,B] [--reference [--tolerance T]]\n"
    "                    [--stereo anaglyph|side-by-side [--eye-separation F]]\n"
    "                    [--interactive] [--verbose]\n"
    "  --reference   render the volumes with the CPU reference ray caster (docs/SCENE-FORMAT.md\n"
    "                section 4) over GL's opaque geometry; prints the error bound reached\n"
    "  --tolerance   the reference's per-pixel convergence tolerance (default 1e-4)\n"
    "  --stereo      a stereo pair of the scene camera: red-cyan anaglyph (red = left eye) or\n"
    "                the two eyes side by side (left eye left, each half the width), zero\n"
    "                parallax at the camera's focalDistance\n"
    "  --eye-separation  the eye separation as a fraction of focalDistance (default 1/30)\n"
    "  --interactive the frame the viewer draws while the user drags: volumes use their\n"
    "                interactive settings (Volume.interactivePlanes,\n"
    "                ShearWarpVolume.interactiveSliceStep)\n"
    "  --verbose     print per volume node the settings it drew with and the error it predicts\n"
    "                against the rendering model (Volume.errorTarget)\n";

double parseTolerance(const std::string& text) {
    char* end = nullptr;
    const double t = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !(t > 0.0) || !(t < 1.0))
        throw volsg::Error("--tolerance wants a number between 0 and 1, got '" + text + "'");
    return t;
}

int run(volsg::cli::Arguments& args) {
    std::string scene, output;
    volsg::RenderOptions options;
    volsg::Backend backend = volsg::Backend::OSMesa;
    bool reference = false, verbose = false;
    volsg::RayCastOptions rayOptions;
    volsg::StereoOptions stereo;
    stereo.mode = volsg::StereoMode::Off;
    volsg::cli::Options table;
    table.text({"-o", "--output"}, output)
        .size("--size", options.width, options.height)
        .value("--backend", [&](const std::string& v) { backend = volsg::parseBackend(v); })
        .color("--background", options.background)
        .flag("--reference", reference)
        .flag("--interactive", options.interactive)
        .flag("--verbose", verbose)
        .value("--tolerance",
               [&](const std::string& v) { rayOptions.tolerance = parseTolerance(v); })
        .value("--stereo", [&](const std::string& v) { stereo.mode = volsg::parseStereoMode(v); })
        .fraction("--eye-separation", stereo.separationFraction);
    if (!table.read(args, usage, volsg::cli::sceneOperand(scene))) return 0;
    if (scene.empty() || output.empty()) return volsg::cli::usageError(usage);
    const std::string ext = volsg::cli::extensionOf(output);
    if (ext != ".png" && ext != ".pfm" && ext != ".iv")
        throw volsg::Error("output '" + output + "' must end in .png, .pfm or .iv");

    // A .vsgv (volsg-pack) opens as its stored scene.
    volsg::ref_ptr<volsg::Node> root = volsg::readSceneOrVoxelFile(scene);
    if (ext == ".iv") {
        volsg::writeSceneToFile(output, *root);
        return 0;
    }
    auto context = volsg::Context::createOffscreen(backend);
    if (reference && stereo.mode != volsg::StereoMode::Off)
        throw volsg::Error("--reference and --stereo cannot be combined");
    if (reference) {
        volsg::RayCastResult details;
        volsg::writeImage(output, volsg::renderReference(*root, options, &details, rayOptions));
        std::printf("reference: error bound %.3g (tolerance %.3g, %s, at most %d halvings)\n",
                    details.errorBound, rayOptions.tolerance,
                    details.converged ? "converged" : "NOT converged everywhere",
                    details.maxHalvingsUsed);
        return 0;
    }
    volsg::Renderer renderer;
    volsg::writeImage(output, volsg::renderStereo(renderer, *root, options, stereo));
    if (verbose)
        for (const std::string& line : volsg::cli::volumeQualityLines(*root))
            std::printf("%s\n", line.c_str());
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return volsg::cli::runTool("volsg-render", argc, argv, run);
}
