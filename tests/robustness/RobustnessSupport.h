#pragma once
// Shared by the robustness tests: loading any input format by its extension the way a user's
// file reaches the library, and a scratch folder per process.

#include <filesystem>
#include <string>

#include <unistd.h>

#include <volsg/core/Error.h>
#include <volsg/gltf/GltfAsset.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/GltfModel.h>
#include <volsg/volumeio/VolumeReader.h>

#include "../support/TempDir.h"

namespace volsg::test {

/// Reads `path` with the reader its extension names (.iv scene, .nrrd/.nhdr, .mha/.mhd, .gltf/
/// .glb through a GltfModel node, .png, .pfm; anything else a 4x4x4 UBYTE raw volume). Bad
/// input must come back as volsg::Error; anything else escapes to the test.
inline void loadByExtension(const std::filesystem::path& path) {
    const std::string ext = path.extension().string();
    const std::string name = path.string();
    if (ext == ".iv") {
        (void)readScene(name);
    } else if (ext == ".nrrd" || ext == ".nhdr") {
        (void)readNrrd(name);
    } else if (ext == ".mha" || ext == ".mhd") {
        (void)readMetaImage(name);
    } else if (ext == ".gltf" || ext == ".glb") {
        const ref_ptr<GltfModel> model = GltfModel::create();
        model->fileName = name;
        (void)model->asset();
    } else if (ext == ".png") {
        (void)readPng(name);
    } else if (ext == ".pfm") {
        (void)readPfm(name);
    } else {
        RawVolumeLayout layout;
        layout.dimensions = {4, 4, 4};
        (void)readRawVolume(name, layout);
    }
}

/// The error message loading `path` gives, or "" when it loads.
inline std::string loadError(const std::filesystem::path& path) {
    try {
        loadByExtension(path);
    } catch (const Error& e) {
        return e.what();
    }
    return {};
}

/// A fresh folder of this process under the build's temporary directory (ctest runs test
/// cases in parallel processes).
inline std::filesystem::path robustnessScratch(const std::string& name) {
    const std::filesystem::path dir = processScratch("volsg-robustness") / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace volsg::test
