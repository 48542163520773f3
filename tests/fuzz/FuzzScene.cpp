// libFuzzer target: Inventor ASCII scene text through readSceneFromString, and every graph it
// accepts written back out (the writer sees whatever the reader let through).
#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>

#include "FuzzScratch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const volsg::ref_ptr<volsg::Node> root =
            volsg::readSceneFromString(volsg::fuzz::asText(data, size), "<fuzz>");
        (void)volsg::writeSceneToString(*root);
    } catch (const volsg::Error&) {
        // The documented outcome for bad input; anything else (a crash, another exception,
        // a sanitizer report, a leak, a hang) is a finding.
    }
    return 0;
}
