// libFuzzer target: NRRD volumes (readNrrd). The first byte picks attached (.nrrd) or detached
// (.nhdr, which may name the scratch folder's data.raw or data.raw.gz); the rest is the file.
#include <volsg/volumeio/VolumeReader.h>

#include "FuzzScratch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    volsg::fuzz::readVolumeHeader(data, size, "input.nrrd", "input.nhdr", &volsg::readNrrd);
    return 0;
}
