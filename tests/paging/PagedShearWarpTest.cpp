// A ShearWarpVolume on a paged volume: the level the view asks for (its voxels at most a pixel)
// is read whole in the background, the stand-in drawn meanwhile, as fine as the memory budget
// allows; converged, the image is the in-memory shear-warp image of that level.
#include "slicing/SlicingTestSupport.h"
#include "support/TempDir.h"

#include <chrono>
#include <fstream>
#include <thread>

#include <volsg/actions/SearchAction.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/paging/PagedVolume.h>
#include <volsg/volumeio/OmeZarrPyramid.h>

using namespace volsg;
using namespace volsg::test;

namespace {

/// A Marschner-Lobb pyramid of `side`^3 voxels in 16^3 chunks, ml.zarr in the folder.
void writePyramid(const TempDir& dir, int side) {
    PyramidOptions pyramid;
    pyramid.chunk = 16;
    writeOmeZarrPyramid(*makeMarschnerLobb(side, VoxelType::UByte), dir.file("ml.zarr"), pyramid);
}

/// An orthographic view `height` units high of the pyramid (its box is [-1, 1]^3).
ref_ptr<Node> scene(const TempDir& dir, const std::string& name, const std::string& dataFields,
                    double height) {
    const std::string file = dir.file(name);
    std::ofstream(file) << "#Inventor V2.1 ascii\nSeparator {\n"
                           "  OrthographicCamera { position 0 0 5 height "
                        << height
                        << " nearDistance 1 farDistance 10 }\n"
                           "  Transform { rotation 1 1 0 0.6 }\n"
                           "  VolumeData { fileName \"ml.zarr\" "
                        << dataFields
                        << " }\n"
                           "  TransferFunction { red [ 0 1, 1 0.3 ] green [ 0 0.2, 1 0.9 ] "
                           "blue [ 0 0.1, 1 1 ] alpha [ 0 0, 0.3 0, 0.6 0.3, 1 0.8 ] }\n"
                           "  ShearWarpVolume { threads 1 }\n}\n";
    return readScene(file);
}

ShearWarpVolume& shearWarpOf(Node& root) {
    const std::vector<Node*> found = findAll(root, ShearWarpVolume::classType(), true);
    REQUIRE(found.size() == 1);
    return *static_cast<ShearWarpVolume*>(found.front());
}

/// Renders until the node's level stops loading (at most about 10 s).
Image renderConverged(Renderer& renderer, Node& root, const RenderOptions& options, int& frames) {
    Image image = renderer.render(root, options);
    for (frames = 1; shearWarpOf(root).lastQuality().refining && frames < 1000; ++frames) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        image = renderer.render(root, options);
    }
    return image;
}

} // namespace

TEST_CASE_FIXTURE(GlFixture, "shear-warp of a paged volume loads the level the view asks for") {
    const TempDir dir("volsg-paged-sw");
    writePyramid(dir, 64);
    RenderOptions options;
    options.width = options.height = 96;
    // memoryBudget 1 (MiB): the stand-in is level 1 (32^3), level 0 (64^3) fits the budget.
    // 2.4 units over 96 pixels: a level-0 voxel (1/32) is 1.25 pixels, so the view asks for
    // level 0.
    ref_ptr<Node> paged = scene(dir, "paged.iv", "paging ON memoryBudget 1", 2.4);
    const Image first = renderer.render(*paged, options);
    const ShearWarpVolume::Quality before = shearWarpOf(*paged).lastQuality();
    CHECK(before.wantedLevel == 0);
    CHECK(before.pagedLevel >= 0);
    int frames = 0;
    const Image converged = renderConverged(renderer, *paged, options, frames);
    const ShearWarpVolume::Quality after = shearWarpOf(*paged).lastQuality();
    REQUIRE_FALSE(after.refining);
    CHECK(after.pagedLevel == 0);
    CHECK(after.levelError.empty());

    ref_ptr<Node> inMemory = scene(dir, "memory.iv", "paging OFF", 2.4);
    const Image want = renderer.render(*inMemory, options);
    const ImageDifference d = difference(converged, want);
    MESSAGE("first frame at level " << before.pagedLevel << ", level 0 after " << frames
                                    << " frames: max " << d.max / k8Bit << "/255 from in memory");
    // The same voxels, lists and view: the same image.
    CHECK(d.max <= 1e-6);
    if (before.pagedLevel > 0) CHECK(difference(first, want).rmse > 0.0);
}

TEST_CASE_FIXTURE(GlFixture, "shear-warp of a paged volume: far away a coarse level, and the "
                             "memory budget caps the level") {
    const TempDir dir("volsg-paged-sw");
    writePyramid(dir, 128);
    RenderOptions options;
    options.width = options.height = 96;
    {
        // 8 units over 96 pixels: a level-1 voxel (1/32) is 0.375 pixels, level 2's 0.75.
        ref_ptr<Node> far = scene(dir, "far.iv", "paging ON memoryBudget 1", 8.0);
        int frames = 0;
        renderConverged(renderer, *far, options, frames);
        const ShearWarpVolume::Quality q = shearWarpOf(*far).lastQuality();
        CHECK(q.wantedLevel == 2);
        CHECK(q.pagedLevel == 2);
    }
    {
        // Close: the view asks for level 0 (128^3, 2 MiB), more than half of what the bricks of
        // a 1 MiB budget may take; level 1 (256 KiB) is drawn.
        ref_ptr<Node> close = scene(dir, "close.iv", "paging ON memoryBudget 1", 2.4);
        int frames = 0;
        renderConverged(renderer, *close, options, frames);
        const ShearWarpVolume::Quality q = shearWarpOf(*close).lastQuality();
        CHECK(q.wantedLevel == 0);
        CHECK(q.pagedLevel == 1);
        CHECK_FALSE(q.refining);
    }
}
