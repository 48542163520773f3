// volsg-pyramid: writes any volume volsg reads as an OME-Zarr multiscale pyramid
// (lib/volsg/volumeio/OMEZARR.md), which volsg and other OME-Zarr readers (python-zarr in the
// tests) open.
#include <cstdio>
#include <string>

#include "CommandLine.h"
#include "TerminalProgress.h"
#include <volsg/volumeio/OmeZarrPyramid.h>
#include <volsg/volumeio/VolumeReader.h>

namespace {

const char* usage =
    "usage: volsg-pyramid VOLUME -o OUT.zarr [--chunk N] [--compressor zstd|zlib|gzip|blosc|none]\n"
    "                    [--labels] [--unit NAME]\n"
    "  (VOLUME: .nrrd .nhdr .mhd .mha .nii .nii.gz, a DICOM folder or file, an OME-Zarr\n"
    "   folder, or raw with the options below)\n"
    "  writes OUT.zarr (a new folder): level 0 the volume, each next level halving every axis\n"
    "  (the mean of 2x2x2 voxels) until the longest axis fits one chunk\n"
    "  --chunk N       chunk edge in voxels (default 64)\n"
    "  --compressor C  chunk compressor (default zstd; blosc: lz4 with byte shuffle)\n"
    "  --labels        label data: the most frequent of the 2x2x2 labels (ties: the smallest)\n"
    "                  instead of their mean, so no label is invented\n"
    "  --unit NAME     the axes' unit in the metadata (default millimeter for files that place\n"
    "                  the volume in patient space: NRRD, MetaImage, NIfTI, DICOM; else none)\n"
    "%s";

int run(volsg::cli::Arguments& args) {
    std::string input, output, compressor = "zstd", unit;
    bool unitGiven = false;
    volsg::OpenFileOptions open;
    volsg::PyramidOptions options;
    volsg::cli::Options table;
    table.text({"-o", "--output"}, output)
        .integer("--chunk", options.chunk, 1, 4096)
        .text("--compressor", compressor)
        .flag("--labels", options.labels)
        .value("--unit",
               [&](const std::string& v) {
                   unit = v;
                   unitGiven = true;
               })
        .rawVolume(open);
    const std::string help = volsg::cli::withRawUsage(usage);
    if (!table.read(args, help.c_str(), volsg::cli::sceneOperand(input))) return 0;
    volsg::cli::checkRawLayout(open);
    if (input.empty() || output.empty()) return volsg::cli::usageError(help.c_str());
    options.codec = volsg::ZarrCodec::named(compressor);

    volsg::cli::TerminalProgress progress("volsg-pyramid");
    progress.stage(0.0, "reading " + input);
    const volsg::ref_ptr<volsg::VolumeGrid> grid =
        volsg::readVolume(input, open.raw ? &*open.raw : nullptr);
    options.unit = unitGiven ? unit : grid->geometry().known ? "millimeter" : "";
    const auto levels = volsg::writeOmeZarrPyramid(*grid, output, options, [&](double done) {
        progress.stage(0.1 + 0.9 * done, "writing " + output);
    });
    progress.finish();
    for (std::size_t l = 0; l < levels.size(); ++l) {
        const volsg::PyramidLevel& level = levels[l];
        std::printf("%s/%zu: %dx%dx%d %s, spacing %g %g %g, %ju chunks, %ju bytes\n",
                    output.c_str(), l, level.dimensions.x, level.dimensions.y, level.dimensions.z,
                    volsg::voxelTypeName(grid->type()), level.spacing.x, level.spacing.y,
                    level.spacing.z, std::uintmax_t(level.chunkFiles),
                    std::uintmax_t(level.storedBytes));
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return volsg::cli::runTool("volsg-pyramid", argc, argv, run);
}
