// libFuzzer target: DICOM files (readDicomSeries through GDCM). The input is one file of a
// series in the scratch folder, which holds no other DICOM file, so the series is that file.
#include <volsg/volumeio/VolumeReader.h>

#include "FuzzScratch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path =
        volsg::fuzz::FuzzScratch::instance().write("input.dcm", volsg::fuzz::asText(data, size));
    try {
        (void)volsg::readDicomSeries(path, volsg::fuzz::fuzzVolumeByteLimit)->minMax();
    } catch (const volsg::Error&) {
    }
    return 0;
}
