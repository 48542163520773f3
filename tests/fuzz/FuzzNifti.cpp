// libFuzzer target: NIfTI volumes (readNifti). The first byte picks .nii (voxels in the file)
// or .hdr (a header whose ni1/ni2 magic names an .img beside it: none exists here, so that
// path ends in its error); the rest is the file, plain or gzip.
#include <volsg/volumeio/VolumeReader.h>

#include "FuzzScratch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    volsg::fuzz::readVolumeHeader(data, size, "input.nii", "input.hdr", &volsg::readNifti);
    return 0;
}
