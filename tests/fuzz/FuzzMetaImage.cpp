// libFuzzer target: MetaImage volumes (readMetaImage). The first byte picks .mha (data in the
// file) or .mhd (which may name the scratch folder's data.raw); the rest is the file.
#include <volsg/volumeio/VolumeReader.h>

#include "FuzzScratch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    volsg::fuzz::readVolumeHeader(data, size, "input.mha", "input.mhd", &volsg::readMetaImage);
    return 0;
}
