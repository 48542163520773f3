// The viewer's window layout under Xvfb: with the panels shown, in both layouts, every view's
// rectangle (from WindowLayout, the layout code itself) shows the rendered view, not a panel,
// and the panel column shows no view; clicks go to what is under the mouse (a click in the
// axial view moves the cursor and never edits the transfer function, a click on the
// transfer-function canvas edits it and never moves the camera). Skips without xvfb-run.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <volsg/actions/SearchAction.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/OrthoSlice.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/volume/VolumeGrid.h>

#include "ViewerTestSupport.h"
#include "view/WindowLayout.h"

using namespace volsg;
namespace fs = std::filesystem;

namespace {

const glm::vec3 kMagenta(1.0f, 0.0f, 1.0f); // --background 1,0,1: no panel has this colour

bool isBackground(const Image& image, int x, int y) {
    const glm::vec3 d = glm::abs(glm::vec3(image.at(x, y)) - kMagenta);
    return std::max(d.r, std::max(d.g, d.b)) <= 2.0f / 255.0f;
}

int backgroundIn(const Image& image, const PixelRect& r) {
    int count = 0;
    for (int y = r.y; y < r.y + r.height; ++y)
        for (int x = r.x; x < r.x + r.width; ++x)
            count += isBackground(image, x, y);
    return count;
}

/// The view's corners (4 px in) show the background: nothing else is drawn there, so a panel
/// over the view would show.
void checkViewCorners(const Image& image, const PixelRect& r) {
    for (const auto& corner : {std::pair{r.x + 4, r.y + 4}, {r.x + r.width - 5, r.y + 4}}) {
        const int x = corner.first, y = corner.second; // CAPTURE cannot take a binding
        CAPTURE(x);
        CAPTURE(y);
        CHECK(isBackground(image, x, y));
    }
}

} // namespace

TEST_CASE("panels dock in a side column that never covers a view, and clicks go where they land") {
    if (!haveXvfbRun()) {
        MESSAGE("xvfb-run is not installed: the viewer layout test is skipped");
        return;
    }
    const fs::path dir =
        fs::temp_directory_path() / ("volsg-view-layout-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string scene = std::string(VOLSG_SOURCE_DIR) + "/tests/viewer/views-scene.iv";
    auto file = [&](const char* name) { return (dir / name).string(); };
    {
        std::ofstream script(file("script.txt"));
        script << "wait 1\n"
               << "screenshot " << file("single.png") << "\n"
               << "layout four\n"
               << "wait 1\n"
               << "screenshot " << file("four.png") << "\n"
               << "click left view:axial:0.25,0.5\n" // the axial view's left half
               << "wait 1\n"
               << "screenshot " << file("four-clicked.png") << "\n"
               << "save " << file("after-axial-click.iv") << "\n"
               << "click left tf:0.5,0.8\n" // a new alpha point
               << "wait 1\n"
               << "save " << file("after-tf-click.iv")
               << "\n"
               // A left drag in a section view is window/level: 10% of the view to the right.
               << "drag left view:sagittal:0.5,0.5 view:sagittal:0.6,0.5 4\n"
               << "wait 1\n"
               << "save " << file("after-section-drag.iv") << "\n"
               << "quit\n";
    }
    std::string log;
    const int status =
        runViewerScript(scene, "--size 1280x800 --background 1,0,1", file("script.txt"), log);
    INFO("viewer output: " << log);
    REQUIRE(status == 0);

    const Image single = readPng(file("single.png")), four = readPng(file("four.png"));
    REQUIRE(single.width == 1280);
    REQUIRE(single.height == 800);
    for (const ViewLayout mode : {ViewLayout::Single, ViewLayout::Four}) {
        const Image& image = mode == ViewLayout::Single ? single : four;
        const WindowLayout layout = layoutWindow({1280, 800}, true, mode);
        CAPTURE(int(mode));
        REQUIRE(!layout.panels.empty());
        // The panel column shows panels only: no pixel of the views' background.
        CHECK(backgroundIn(image, layout.panels) == 0);
        for (int v = 0; v < layout.viewCount; ++v) {
            const PixelRect& r = layout.views[std::size_t(v)];
            CAPTURE(v);
            CHECK(!r.overlaps(layout.panels));
            checkViewCorners(image, r);
            // Most of a view is background around the volume or slice, and its middle is the
            // rendered volume (not the background, not a panel).
            const int inView = backgroundIn(image, r);
            CHECK(inView > r.width * r.height / 5);
            CHECK(inView < r.width * r.height);
            CHECK_FALSE(isBackground(image, r.x + r.width / 2 + 7, r.y + r.height / 2 + 7));
        }
    }

    // The click in the axial view moved the cursor: the crosshair in the coronal view moves
    // (its x), the panel column is as it was. It left the transfer function alone; the click
    // on the canvas added one alpha point and moved no camera.
    const Image clicked = readPng(file("four-clicked.png"));
    const WindowLayout four4 = layoutWindow({1280, 800}, true, ViewLayout::Four);
    const PixelRect coronal = four4.views[2];
    CHECK(changedPixels(four, clicked, 2.0f / 255.0f, coronal.x, coronal.y,
                        coronal.x + coronal.width, coronal.y + coronal.height - 24) > 100);
    ref_ptr<Node> afterAxial = readScene(file("after-axial-click.iv"));
    ref_ptr<Node> afterTf = readScene(file("after-tf-click.iv"));
    ref_ptr<Node> original = readScene(scene);
    auto tfOf = [](Node& root) { return static_cast<TransferFunction*>(findByName(root, "tf")); };
    auto cameraOf = [](Node& root) { return static_cast<Camera*>(findByName(root, "camera")); };
    REQUIRE(tfOf(*afterAxial));
    REQUIRE(tfOf(*afterTf));
    CHECK(tfOf(*afterAxial)->alpha.getValues() == tfOf(*original)->alpha.getValues());
    CHECK(tfOf(*afterAxial)->red.getValues() == tfOf(*original)->red.getValues());
    CHECK(tfOf(*afterTf)->alpha.size() == tfOf(*original)->alpha.size() + 1);
    CHECK(tfOf(*afterTf)->red.getValues() == tfOf(*original)->red.getValues());
    CHECK(cameraOf(*afterTf)->position() == cameraOf(*afterAxial)->position());
    CHECK(cameraOf(*afterTf)->orientation().angle == cameraOf(*afterAxial)->orientation().angle);
    // The drag widened the function's range [0, 255] by a tenth of the data's span, about the
    // same level, and moved no cursor plane (the scene's axial slice stayed).
    ref_ptr<Node> afterDrag = readScene(file("after-section-drag.iv"));
    auto* data = static_cast<VolumeData*>(findAll(*original, VolumeData::classType()).front());
    const auto [lo, hi] = data->grid()->minMax();
    const glm::vec2 range = tfOf(*afterDrag)->dataRange();
    const double pixel = (hi - lo) / 448.0; // one pixel of the drag in data units
    CHECK(std::abs((range.y - range.x) - (255.0 + 0.1 * (hi - lo))) < 2.0 * pixel);
    CHECK(std::abs(0.5 * (range.x + range.y) - 127.5) < 1e-3);
    auto sliceOf = [](Node& root) { return static_cast<OrthoSlice*>(findByName(root, "sliceZ")); };
    CHECK(sliceOf(*afterDrag)->sliceNumber() == sliceOf(*afterTf)->sliceNumber());
    fs::remove_all(dir);
}
