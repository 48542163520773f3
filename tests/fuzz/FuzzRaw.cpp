// libFuzzer target: headerless raw volumes, plain or gzip (readRawVolume). The first 6 bytes
// choose the layout the scene would give (dimensions 1..16 each, voxel type, byte order,
// header skip); the rest is the file.
#include <volsg/core/Error.h>
#include <volsg/volumeio/VolumeReader.h>

#include "FuzzScratch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace volsg;
    if (size < 6) return 0;
    RawVolumeLayout layout;
    layout.dimensions = glm::ivec3(data[0] % 16 + 1, data[1] % 16 + 1, data[2] % 16 + 1);
    layout.type = VoxelType(data[3] % 4);
    layout.bigEndian = (data[3] & 0x80) != 0;
    layout.headerSkip = data[4] % 64;
    layout.spacing = glm::dvec3(1.0, 0.5 + data[5] % 4, 2.0);
    const std::string path =
        fuzz::FuzzScratch::instance().write("input.raw", fuzz::asText(data + 6, size - 6));
    try {
        const ref_ptr<VolumeGrid> grid = readRawVolume(path, layout, fuzz::fuzzVolumeByteLimit);
        (void)grid->minMax();
    } catch (const Error&) {
    }
    return 0;
}
