// A paged volume's bricks leave out the air they hold: each brick's slices are cut to the box
// of its own empty-space cells that may emit (grown by the samples' reach). The image is the
// one drawn without it, for DVR (one sample and several a plane) and MIP, and fewer fragments
// are drawn.
#include "slicing/SlicingTestSupport.h"
#include "support/TempDir.h"

#include <chrono>
#include <thread>

#include <volsg/paging/PagedVolume.h>
#include <volsg/volumeio/OmeZarrPyramid.h>

using namespace volsg;
using namespace volsg::test;

namespace {

/// Renders until the paged volume converged.
Image converged(Renderer& renderer, Node& root, GridVolume& node, PagedVolume& paged,
                const RenderOptions& options) {
    Image image = renderer.render(root, options);
    for (int frame = 0; frame < 400 && !node.stats.paging.converged; ++frame) {
        paged.cache().waitIdle(50);
        image = renderer.render(root, options);
    }
    REQUIRE(node.stats.paging.converged);
    return image;
}

} // namespace

TEST_CASE_FIXTURE(GlFixture, "paged bricks cut to their emitting cells draw the same image") {
    const TempDir dir("volsg-paged-air");
    // A soft sphere in a 64^3 box of 16^3 chunks: the bricks at its rim are part air.
    PyramidOptions pyramid;
    pyramid.chunk = 16;
    writeOmeZarrPyramid(*makeSoftSphere(64, VoxelType::UByte), dir.file("sphere.zarr"), pyramid);
    PagedVolumeOptions pagedOptions;
    pagedOptions.standInBytes = 16 * 16 * 16; // level 2 whole: levels 0 and 1 page
    auto paged = std::make_shared<PagedVolume>(dir.file("sphere.zarr"), pagedOptions);

    struct Case {
        const char* name;
        VolumeRenderMode mode;
        int samplesPerPlane;
        double planeSpacingL0; ///< 0: the fixed rule
    };
    for (const Case c : {Case{"DVR, one sample a plane", VolumeRenderMode::DVR, 1, 0.0},
                         Case{"DVR, 16 samples a plane", VolumeRenderMode::DVR, 16, 6.0},
                         Case{"MIP, 4 samples a plane", VolumeRenderMode::MIP, 4, 3.0}}) {
        CAPTURE(c.name);
        auto root = Separator::create();
        auto node = GridVolume::create();
        // Opaque above 0.55 only: the sphere's outer shell of the data is air.
        node->description =
            volumeOf(paged->standIn(), transferFunction({{0, 0}, {0.55, 0}, {0.7, 0.3}, {1, 0.9}},
                                                        {{0, 1}, {1, 0.3}}, {{0, 0.2}, {1, 0.9}}));
        node->description.paged = paged;
        node->description.mode = c.mode;
        node->settings.lodPixels = 0.25; // level 0 everywhere at this size
        node->settings.samplesPerPlane = c.samplesPerPlane;
        node->settings.fixedSamplesPerPlane = true;
        node->settings.planeSpacingL0 = c.planeSpacingL0;
        if (c.planeSpacingL0 > 0.0) node->settings.numPlanes = int(64 * 1.7 / c.planeSpacingL0);
        root->addChild(node);
        RenderOptions options;
        options.width = options.height = 96;
        options.camera = framing(*paged->standIn(), {1.0f, 0.5f, 0.8f});

        node->settings.skipEmptyCells = true;
        const Image cut = converged(renderer, *root, *node, *paged, options);
        const SlicingStats withCut = node->stats;
        node->settings.skipEmptyCells = false;
        const Image whole = converged(renderer, *root, *node, *paged, options);
        const SlicingStats without = node->stats;
        const ImageDifference d = difference(cut, whole);
        MESSAGE(std::string(c.name)
                << ": " << withCut.bricksTrimmed << " of " << withCut.paging.bricksDrawn
                << " bricks trimmed, slice triangles " << withCut.sliceTriangles << " against "
                << without.sliceTriangles << "; max " << d.max / k8Bit << "/255");
        CHECK(withCut.paging.finestLevel == 0);
        CHECK(withCut.bricksTrimmed > 0);
        CHECK(without.bricksTrimmed == 0);
        CHECK(withCut.sliceTriangles < without.sliceTriangles);
        // Only the air is left out: the same fragments that emit, the same image.
        CHECK(d.max <= 1e-5);
        double brightest = 0.0;
        for (const glm::vec4& p : cut.pixels)
            brightest = std::max(brightest, double(p.r));
        CHECK(brightest > 0.1);
    }
}
