// volsg-pack: extracts the ShearWarpVolume objects of a scene and writes them with the whole
// visualization to a compact voxel-list file (.vsgv, lib/volsg/voxelfile/README.md) that
// volsg-view and volsg-render open without the volume.
#include <cstdio>
#include <filesystem>
#include <string>

#include "CommandLine.h"
#include "TerminalProgress.h"
#include <volsg/io/AtomicFile.h>
#include <volsg/io/SceneReader.h>
#include <volsg/voxelfile/VoxelFile.h>
#include <volsg/voxelfile/VoxelFileScene.h>

namespace {

const char* usage =
    "usage: volsg-pack SCENE -o OUT.vsgv [--scene OUT.iv]\n"
    "  writes the voxel lists of every ShearWarpVolume in SCENE with the scene's cameras,\n"
    "  lights, transforms, transfer functions, clipping and node fields; volsg-view and\n"
    "  volsg-render open OUT.vsgv directly, without the volume files\n"
    "  --scene  also write a plain scene file whose ShearWarpVolumes name OUT.vsgv in their\n"
    "           voxelFile field (relative to the scene file's folder)\n";

int run(volsg::cli::Arguments& args) {
    std::string scene, output, companion;
    volsg::cli::Options table;
    table.text({"-o", "--output"}, output).text("--scene", companion);
    if (!table.read(args, usage, volsg::cli::sceneOperand(scene))) return 0;
    if (scene.empty() || output.empty()) return volsg::cli::usageError(usage);
    volsg::cli::TerminalProgress progress("volsg-pack");
    progress.stage(0.0, "reading " + scene);
    volsg::ref_ptr<volsg::Node> root = volsg::readScene(scene);
    progress.stage(0.2, "extracting the objects");
    const volsg::VoxelFileContent content = volsg::packScene(*root);
    progress.stage(0.8, "writing " + output);
    volsg::writeVoxelFile(output, content);
    progress.finish();
    std::size_t voxels = 0;
    for (const volsg::PackedObject& o : content.objects)
        voxels += o.voxels->voxelCount();
    const auto bytes = std::filesystem::file_size(output);
    std::printf("%s: %zu objects, %zu voxels, %ju bytes (%.2f bytes per voxel)\n", output.c_str(),
                content.objects.size(), voxels, bytes,
                voxels ? double(bytes) / double(voxels) : 0.0);
    if (!companion.empty()) {
        namespace fs = std::filesystem;
        const fs::path from = fs::absolute(companion).parent_path();
        const std::string reference = fs::relative(fs::absolute(output), from).generic_string();
        volsg::writeFileAtomically(companion, volsg::companionSceneText(content, reference));
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return volsg::cli::runTool("volsg-pack", argc, argv, run);
}
