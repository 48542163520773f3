// Inventor's draggers drawn at rest (nodes/volsg/nodes/Dragger.h): Coin's default geometry
// reads with our reader, every dragger type keeps and writes back its fields, the motion
// matrix places the parts, bounding boxes and picks go through the parts, and a
// Translate1Dragger's pixels land where a closed form says. The comparison of every dragger
// type's image with Coin3D's is the ctest DraggersAgreeWithCoin (tests/draggers/*.iv).
#include <doctest/doctest.h>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/actions/PickAction.h>
#include <volsg/context/OSMesaContext.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/image/Image.h>
#include <volsg/io/GraphCompare.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/nodes/BuiltinNodes.h>
#include <volsg/nodes/Dragger.h>
#include <volsg/nodes/DraggerCatalog.h>
#include <volsg/render/Renderer.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace volsg;

namespace {

ref_ptr<Node> read(const std::string& body) {
    return readSceneFromString("#Inventor V2.1 ascii\n" + body, "<string>");
}

bool boxNear(const Box3& b, glm::dvec3 lo, glm::dvec3 hi, double eps = 1e-5) {
    return glm::all(glm::lessThanEqual(glm::abs(b.min - lo), glm::dvec3(eps))) &&
           glm::all(glm::lessThanEqual(glm::abs(b.max - hi), glm::dvec3(eps)));
}

} // namespace

TEST_CASE("every embedded file of Coin's dragger geometry reads with our reader") {
    const auto folder =
        std::filesystem::path(VOLSG_SOURCE_DIR) / "nodes/volsg/nodes/draggerDefaults";
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (entry.path().extension() != ".iv") continue;
        const std::string name = entry.path().filename().string();
        CAPTURE(name);
        std::ifstream in(entry.path(), std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        CHECK(draggerDefaultFile(name) == text.str());
        CHECK_NOTHROW(readSceneFromString(draggerDefaultFile(name), name));
        ++files;
    }
    CHECK(files == 21);
}

TEST_CASE("a Translate1Dragger at rest: its arrow's box, moved by translation") {
    CHECK(boxNear(computeBoundingBox(*read("Translate1Dragger { }")), {-1.5, -0.25, -0.25},
                  {1.5, 0.25, 0.25}));
    CHECK(boxNear(computeBoundingBox(*read("Translate1Dragger { translation 2 1 0 }")),
                  {0.5, 0.75, -0.25}, {3.5, 1.25, 0.25}));
}
