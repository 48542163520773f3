// volsg-view's error-target slider under Xvfb: dragging it sets the volume nodes' errorTarget
// (saved with the scene), and ctrl+z puts the old target back. Skips itself without xvfb-run.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <volsg/actions/SearchAction.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Volume.h>

#include "ViewerTestSupport.h"
#include "support/TempDir.h"

using namespace volsg;
namespace fs = std::filesystem;

namespace {

float savedErrorTarget(const fs::path& scene) {
    ref_ptr<Node> root = readScene(scene.string());
    const auto volumes = findAll(*root, Volume::classType());
    REQUIRE(volumes.size() == 1);
    return static_cast<Volume*>(volumes.front())->errorTarget();
}

} // namespace

TEST_CASE("the error-target slider sets the volumes' target, and undo restores it") {
    if (!haveXvfbRun()) {
        MESSAGE("xvfb-run is not installed: the viewer error-target test is skipped");
        return;
    }
    const volsg::test::TempDir temp("volsg-view-target");
    const fs::path& dir = temp.path();
    const fs::path scene = dir / "scene.iv", looser = dir / "looser.iv", undone = dir / "undone.iv";
    std::ofstream(scene) << "#Inventor V2.1 ascii\n"
                            "Separator {\n"
                            "  VolumeData { generator SOFT_SPHERE dimensions 16 16 16 }\n"
                            "  TransferFunction { alpha [ 0 0, 1 0.6 ] }\n"
                            "  Volume { }\n"
                            "}\n";
    {
        std::ofstream script(dir / "script.txt");
        script << "wait 1\n"
               // The slider is logarithmic from 0.1 to 8/255: near its right end is about 6.
               << "drag left errorTarget:0.5,0.5 errorTarget:0.95,0.5 2\n"
               << "wait 1\n"
               << "save " << looser.string() << "\n"
               << "move 5 5\n"
               << "key z ctrl\n"
               << "wait 1\n"
               << "save " << undone.string() << "\n"
               << "quit\n";
    }
    std::string log;
    const int status =
        runViewerScript(scene.string(), "--size 900x500", (dir / "script.txt").string(), log);
    INFO("viewer output: " << log);
    REQUIRE(status == 0);
    CHECK(savedErrorTarget(looser) > 4.0f);
    CHECK(savedErrorTarget(undone) == doctest::Approx(0.5f));
}
