// libFuzzer target: glTF through the GltfModel node, as a scene loads it: binary .glb or
// .gltf JSON (the loader tells them by the magic). The scratch folder holds buffer.bin for
// external URIs; any URI leading out of it must be refused, never read.
#include <volsg/core/Error.h>
#include <volsg/gltf/GltfAsset.h>
#include <volsg/nodes/GltfModel.h>

#include "FuzzScratch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace volsg;
    const bool binary = size >= 4 && data[0] == 'g' && data[1] == 'l' && data[2] == 'T';
    const std::string path = fuzz::FuzzScratch::instance().write(
        binary ? "input.glb" : "input.gltf", fuzz::asText(data, size));
    try {
        const ref_ptr<GltfModel> model = GltfModel::create();
        model->fileName = path;
        const GltfAsset& asset = model->asset();
        (void)asset.bounds;
    } catch (const Error&) {
    }
    return 0;
}
