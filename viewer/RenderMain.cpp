// volsg-render: renders a scene file (or any data file volsg opens, in the scene built for it)
// headless to PNG or PFM, or writes it back as a scene file.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include "CommandLine.h"
#include "TerminalProgress.h"
#include "VolumeReport.h"
#include <volsg/context/Context.h>
#include <volsg/core/Error.h>
#include <volsg/engines/Evaluator.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/render/Renderer.h>
#include <volsg/render/StereoRenderer.h>
#include <volsg/sortlast/MpiLaunch.h>
#include <volsg/volumescene/ReferenceScene.h>
#include <volsg/volumescene/SceneForFile.h>
#ifdef VOLSG_HAVE_MPI
#include "SortLastRender.h"
#include <volsg/sortlast/MpiSession.h>
#endif

namespace {

/// How long a still image waits for a paged volume's bricks.
constexpr double kMaxPagingWaitSeconds = 600.0;

const char* usage =
    "usage: volsg-render FILE -o OUT.png|OUT.pfm|OUT.iv [--size WxH] [--backend osmesa|egl]\n"
    "  (FILE: a scene file, a .vsgv voxel-list file written by volsg-pack, a volume\n"
    "   (.nrrd .nhdr .mhd .mha .nii .nii.gz, a DICOM folder or file, raw with the options\n"
    "   below) or a glTF model (.gltf .glb), shown in the scene built for it; -o OUT.iv\n"
    "   writes that scene)\n"
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
    "  --time T      the scene time in seconds for engines, connections and animated nodes\n"
    "                (default 0: what the scene shows when it starts)\n"
    "  --interactive the frame the viewer draws while the user drags: volumes use their\n"
    "                interactive settings (Volume.interactivePlanes,\n"
    "                ShearWarpVolume.interactiveSliceStep)\n"
    "  --verbose     print per volume node the settings it drew with and the error it predicts\n"
    "                against the rendering model (Volume.errorTarget)\n"
    "Across processes (sort-last, lib/volsg/sortlast/README.md), started by mpirun:\n"
    "  mpirun -np N volsg-render FILE -o OUT.png [--mpi-timing]\n"
    "                each process draws its share of the opaque shapes (composited by depth)\n"
    "                and its part of the Volume node (a k-d split of its box; DVR only, one\n"
    "                Volume, no transparent shapes); rank 0 composites the parts in visibility\n"
    "                order over the opaque image and writes OUT; from an OME-Zarr\n"
    "                volume with errorTarget 0 each process reads only its own chunks (a paged\n"
    "                pyramid: only its own bricks); without mpirun one process draws\n"
    "                everything (no MPI start-up)\n"
    "  --mpi-own-chunks  under an error target too, each process reads only its own chunks\n"
    "                of an OME-Zarr volume: the frame meets the target but is not one\n"
    "                process's within 1/255 (slabs end at the parts' faces)\n"
    "  --mpi-timing  rank 0 prints each process's read and render times and the compositing\n"
    "                time\n"
    "  --mpi-composite reduce|reduce-scatter  how the parts combine: MPI_Reduce to rank 0\n"
    "                (default), or MPI_Reduce_scatter_block then MPI_Gather (each process\n"
    "                composites 1/N of the image)\n"
    "%s";

double parseTime(const std::string& text) {
    char* end = nullptr;
    const double t = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !(t >= 0.0) || !(t <= 1e9))
        throw volsg::Error("--time wants seconds between 0 and 1e9, got '" + text + "'");
    return t;
}

double parseTolerance(const std::string& text) {
    char* end = nullptr;
    const double t = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !(t > 0.0) || !(t < 1.0))
        throw volsg::Error("--tolerance wants a number between 0 and 1, got '" + text + "'");
    return t;
}

#ifdef VOLSG_HAVE_MPI
/// The MPI session when started by mpirun (null otherwise), and whether the processes have
/// joined the collective failure check (renderSortLast): a failure before it must join it.
const volsg::MpiSession* mpiSession = nullptr;
bool sortLastStarted = false;
#endif

int run(volsg::cli::Arguments& args) {
    std::string scene, output;
    volsg::RenderOptions options;
    volsg::Backend backend = volsg::Backend::OSMesa;
    bool reference = false, verbose = false;
    volsg::RayCastOptions rayOptions;
    volsg::StereoOptions stereo;
    volsg::OpenFileOptions open;
    stereo.mode = volsg::StereoMode::Off;
    double time = 0.0;
    bool mpiTiming = false, mpiOwnChunks = false;
    std::string mpiComposite = "reduce";
    volsg::cli::Options table;
    table.text({"-o", "--output"}, output)
        .size("--size", options.width, options.height)
        .value("--backend", [&](const std::string& v) { backend = volsg::parseBackend(v); })
        .color("--background", options.background)
        .flag("--reference", reference)
        .flag("--interactive", options.interactive)
        .flag("--verbose", verbose)
        .flag("--mpi-timing", mpiTiming)
        .flag("--mpi-own-chunks", mpiOwnChunks)
        .value("--mpi-composite", [&](const std::string& v) { mpiComposite = v; })
        .value("--tolerance",
               [&](const std::string& v) { rayOptions.tolerance = parseTolerance(v); })
        .value("--time", [&](const std::string& v) { time = parseTime(v); })
        .value("--stereo", [&](const std::string& v) { stereo.mode = volsg::parseStereoMode(v); })
        .fraction("--eye-separation", stereo.separationFraction)
        .rawVolume(open);
    const std::string help = volsg::cli::withRawUsage(usage);
    if (!table.read(args, help.c_str(), volsg::cli::sceneOperand(scene))) return 0;
    if (scene.empty() || output.empty()) return volsg::cli::usageError(help.c_str());
    volsg::cli::checkRawLayout(open);
    const std::string ext = volsg::cli::extensionOf(output);
    if (ext != ".png" && ext != ".pfm" && ext != ".iv")
        throw volsg::Error("output '" + output + "' must end in .png, .pfm or .iv");

    // Stages of a run on a terminal: reading (a large volume takes seconds), then rendering.
    volsg::cli::TerminalProgress progress("volsg-render");
    progress.stage(0.0, "reading " + scene);
    // A .vsgv (volsg-pack) opens as its stored scene, a data file in the scene built for it.
    volsg::ref_ptr<volsg::Node> root = volsg::readSceneForFile(scene, open);
    if (ext == ".iv") {
#ifdef VOLSG_HAVE_MPI
        if (mpiSession && mpiSession->rank() != 0) return 0;
#endif
        volsg::writeSceneToFile(output, *root);
        return 0;
    }
    // Connected fields take their sources' values, and engines and animated nodes run, at the
    // scene time asked for (Coin evaluates them when a field is read; the picture is the same).
    volsg::evaluateConnections(*root, time);
    progress.stage(0.4, reference ? "rendering the reference" : "rendering");
    auto context = volsg::Context::createOffscreen(backend);
    if (reference && stereo.mode != volsg::StereoMode::Off)
        throw volsg::Error("--reference and --stereo cannot be combined");
    if (reference) {
        volsg::RayCastResult details;
        const volsg::Image image = volsg::renderReference(*root, options, &details, rayOptions);
        progress.stage(0.95, "writing " + output);
        volsg::writeImage(output, image);
        progress.finish();
        std::printf("reference: error bound %.3g (tolerance %.3g, %s, at most %d halvings)\n",
                    details.errorBound, rayOptions.tolerance,
                    details.converged ? "converged" : "NOT converged everywhere",
                    details.maxHalvingsUsed);
        return 0;
    }
    volsg::Renderer renderer;
#ifdef VOLSG_HAVE_MPI
    if (mpiSession) {
        if (reference || stereo.mode != volsg::StereoMode::Off)
            throw volsg::Error("--reference and --stereo render in one process, not under mpirun");
        sortLastStarted = true;
        volsg::cli::SortLastReport report;
        report.timing = mpiTiming;
        report.ownChunksUnderTarget = mpiOwnChunks;
        if (mpiComposite == "reduce-scatter")
            report.method = volsg::CompositeMethod::ReduceScatter;
        else if (mpiComposite != "reduce")
            throw volsg::Error("--mpi-composite wants reduce or reduce-scatter, got '" +
                               mpiComposite + "'");
        report.sceneFile = scene;
        const volsg::Image image =
            volsg::cli::renderSortLast(renderer, *root, options, *mpiSession, report);
        if (mpiSession->rank() != 0) return 0;
        volsg::writeImage(output, image);
        if (verbose)
            for (const std::string& line : volsg::cli::volumeQualityLines(*root))
                std::printf("%s\n", line.c_str());
        return 0;
    }
#endif
    if (mpiTiming || mpiOwnChunks || mpiComposite != "reduce")
        throw volsg::Error(
            "--mpi-timing, --mpi-own-chunks and --mpi-composite apply to a run under mpirun");
    volsg::Image image = volsg::renderStereo(renderer, *root, options, stereo);
    // A paged volume draws what is loaded and asks for the rest: a still image is rendered
    // again as bricks arrive until nothing more is wanted (this tool is not interactive).
    if (volsg::cli::volumesRefining(*root)) {
        const auto started = std::chrono::steady_clock::now();
        int frames = 1;
        auto seconds = [&] {
            return std::chrono::duration<double>(std::chrono::steady_clock::now() - started)
                .count();
        };
        while (volsg::cli::volumesRefining(*root) && seconds() < kMaxPagingWaitSeconds) {
            progress.stage(0.5, "loading bricks of the paged volume");
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            image = volsg::renderStereo(renderer, *root, options, stereo);
            ++frames;
        }
        const bool converged = !volsg::cli::volumesRefining(*root);
        for (const std::string& line : volsg::cli::pagingErrors(*root))
            std::fprintf(stderr, "volsg-render: %s\n", line.c_str());
        std::fprintf(stderr, "volsg-render: %s after %d frames and %.2f s of loading bricks\n",
                     converged ? "the paged volume converged" : "gave up waiting for bricks",
                     frames, seconds());
    }
    progress.stage(0.95, "writing " + output);
    volsg::writeImage(output, image);
    if (verbose)
        for (const std::string& line : volsg::cli::volumeQualityLines(*root))
            std::printf("%s\n", line.c_str());
    return 0;
}

#ifdef VOLSG_HAVE_MPI
/// volsg-render as one of the processes mpirun started: a failure is said once, by the lowest
/// failing rank, and every process exits with 1.
int runUnderMpi(int argc, char** argv) {
    volsg::MpiSession session(argc, argv);
    mpiSession = &session;
    try {
        volsg::cli::Arguments args(argc, argv);
        return run(args);
    } catch (const volsg::cli::ReportedElsewhere&) {
        return 1;
    } catch (const std::exception& e) {
        try {
            if (!sortLastStarted) volsg::cli::agreeOnFailure(session, true, e.what());
            throw;
        } catch (const volsg::cli::ReportedElsewhere&) {
            return 1;
        } catch (const std::exception& reported) {
            std::fprintf(stderr, "volsg-render: %s\n", reported.what());
            return 1;
        }
    }
}
#endif

} // namespace

int main(int argc, char** argv) {
    // Only a launcher's environment starts MPI: a plain run pays nothing for it.
    if (volsg::mpiLaunchSize() > 0) {
#ifdef VOLSG_HAVE_MPI
        return runUnderMpi(argc, argv);
#else
        if (volsg::mpiLaunchSize() > 1) {
            std::fprintf(stderr, "volsg-render: started by mpirun, but built without MPI: "
                                 "each process would render the whole frame\n");
            return 1;
        }
#endif
    }
    return volsg::cli::runTool("volsg-render", argc, argv, run);
}
