// libFuzzer target: the compact voxel-list file (.vsgv) through readVoxelFile, its entry point
// for untrusted bytes; whatever it accepts is encoded again (the writer sees it too).
#include <volsg/core/Error.h>
#include <volsg/voxelfile/VoxelFile.h>

#include "FuzzScratch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const volsg::VoxelFileContent content = volsg::readVoxelFile(
            std::span<const std::byte>(reinterpret_cast<const std::byte*>(data), size), "<fuzz>");
        (void)volsg::encodeVoxelFile(content);
    } catch (const volsg::Error&) {
    }
    return 0;
}
