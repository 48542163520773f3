// libFuzzer target: binary Inventor files (docs/SCENE-FORMAT.md section 1.9) through
// readSceneFromString. The first byte picks the header (odd: V2.1, even: V2.0) so the fuzzer
// spends its effort on the nodes; every graph read is written back as text and evaluated once
// (connections, engines, animated nodes).
#include <volsg/core/Error.h>
#include <volsg/engines/Evaluator.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>

#include "FuzzScratch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    std::string file = (data[0] & 1) ? "#Inventor V2.1 binary  \n" : "#Inventor V2.0 binary  \n";
    file.append(reinterpret_cast<const char*>(data + 1), size - 1);
    try {
        const volsg::ref_ptr<volsg::Node> root = volsg::readSceneFromString(file, "<fuzz>");
        volsg::ConnectionEvaluator evaluator([](const std::string&) {});
        evaluator.evaluate(*root, 0.25);
        evaluator.evaluate(*root, 1.5);
        (void)volsg::writeSceneToString(*root);
    } catch (const volsg::Error&) {
        // The documented outcome for bad input; anything else (a crash, another exception,
        // a sanitizer report, a leak, a hang) is a finding.
    }
    return 0;
}
