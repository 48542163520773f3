// volsg-view's saving under Xvfb: a commented scene without a camera, rotated and saved,
// keeps its comments and the text of every untouched node byte for byte and gains a camera
// holding the view; Save As writes a second file and later saves go there; the screenshot key
// never overwrites a file (volsg-view-N.png, N the first free number) and the viewer says
// where each went. Skips itself without xvfb-run.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

#include <volsg/actions/SearchAction.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Camera.h>

#include "ViewerTestSupport.h"

using namespace volsg;
namespace fs = std::filesystem;

namespace {

std::string readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

const char* kScene = "#Inventor V2.1 ascii\n"
                     "# No camera here: the viewer makes one, and saving must keep it.\n"
                     "Separator {\n"
                     "  VolumeData { generator SOFT_SPHERE   dimensions 16 16 16 }  # odd spacing\n"
                     "  DEF tf TransferFunction {\n"
                     "    alpha [ 0 0,\n"
                     "            1 0.6 ]   # the opacity ramp\n"
                     "  }\n"
                     "  Volume { numPlanes 24 }\n"
                     "}\n";

} // namespace

TEST_CASE("saving keeps comments and untouched text, adds the camera, Save As, screenshots") {
    if (!haveXvfbRun()) {
        MESSAGE("xvfb-run is not installed: the viewer save test is skipped");
        return;
    }
    const fs::path dir =
        fs::temp_directory_path() / ("volsg-view-save-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path scene = dir / "scene.iv", other = dir / "other.iv";
    std::ofstream(scene, std::ios::binary) << kScene;
    std::ofstream(dir / "volsg-view-1.png", std::ios::binary) << "an earlier screenshot";
    {
        std::ofstream script(dir / "script.txt");
        script << "wait 1\n"
               << "drag left view:3d:0.4,0.5 view:3d:0.6,0.5 2\n" // orbit: the camera turns
               << "key s ctrl\n"                                  // save the scene itself
               << "wait 1\n"
               << "key p\n" // volsg-view-2.png: 1 exists
               << "wait 1\n"
               << "key p\n" // volsg-view-3.png
               << "wait 1\n"
               << "save " << other.string() << "\n" // Save As
               << "wait 1\n"
               << "scroll 1 view:3d:0.5,0.5\n" // dolly, then save: to other.iv now
               << "key s ctrl\n"
               << "wait 1\n"
               << "quit\n";
    }
    const std::string viewer = std::string(VOLSG_BINARY_DIR) + "/viewer/volsg-view";
    const std::string command = "cd " + dir.string() + " && " + sanitizerEnvironment() +
                                "XDG_CONFIG_HOME='" + testConfigHome() +
                                "' xvfb-run -a -s '-screen 0 1280x800x24' " + viewer + " " +
                                scene.string() + " --size 640x400 --script " +
                                (dir / "script.txt").string() + " > log.txt 2>&1";
    const int status = std::system(command.c_str());
    const std::string log = readAll(dir / "log.txt");
    INFO("viewer output: " << log);
    REQUIRE(status == 0);

    // The scene's own file: the original text with a camera after the root's '{', nothing else
    // changed (the comments, the double space and the list's line break included).
    const std::string saved = readAll(scene);
    const std::string head = "Separator {\n";
    const std::size_t cameraAt = saved.find(head) + head.size();
    REQUIRE(saved.compare(cameraAt, 21, "  PerspectiveCamera {") == 0);
    const std::size_t cameraEnd = saved.find("\n  }\n", cameraAt) + 5;
    std::string withoutCamera = saved;
    withoutCamera.erase(cameraAt, cameraEnd - cameraAt);
    CHECK(withoutCamera == kScene);
    ref_ptr<Node> root = readScene(scene.string());
    const auto cameras = findAll(*root, Camera::classType());
    REQUIRE(cameras.size() == 1);
    const auto& camera = *static_cast<Camera*>(cameras.front());
    CHECK(camera.orientation().angle > 0.05f); // the orbit
    CHECK(camera.focalDistance() > 0.0f);

    // Save As wrote other.iv, and the next save went there (the dolly), not to scene.iv.
    CHECK(readAll(scene) == saved);
    ref_ptr<Node> second = readScene(other.string());
    const auto& camera2 = *static_cast<Camera*>(findAll(*second, Camera::classType()).front());
    CHECK(camera2.focalDistance() < camera.focalDistance());
    CHECK(readAll(other).find("# the opacity ramp") != std::string::npos);

    // Screenshots: 1 untouched, 2 and 3 new, and the log says where each went.
    CHECK(readAll(dir / "volsg-view-1.png") == "an earlier screenshot");
    CHECK(readPng((dir / "volsg-view-2.png").string()).width == 640);
    CHECK(readPng((dir / "volsg-view-3.png").string()).width == 640);
    CHECK(log.find("screenshot saved to " + (dir / "volsg-view-2.png").string()) !=
          std::string::npos);
    CHECK(log.find("screenshot saved to " + (dir / "volsg-view-3.png").string()) !=
          std::string::npos);
    CHECK(log.find("comments and layout kept") != std::string::npos);
    fs::remove_all(dir);
}
