// A paged volume under the Volume's error target: the quadrature is chosen by the error model
// on the stand-in and carried to the finest level drawn, and the converged image meets the
// target against the reference ray caster of the full-resolution volume (in memory).
#include "slicing/SlicingTestSupport.h"
#include "support/TempDir.h"

#include <cmath>
#include <fstream>

#include <volsg/actions/SearchAction.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/paging/PagedVolume.h>
#include <volsg/volumeio/OmeZarrPyramid.h>

using namespace volsg;
using namespace volsg::test;

namespace {

/// The scene around a 64^3 pyramid of 16^3 chunks; `dataFields` pages it or not.
std::string sceneText(const std::string& dataFields, const std::string& volumeFields) {
    return "#Inventor V2.1 ascii\nSeparator {\n"
           "  PerspectiveCamera { position 0.5 0.3 2.6 heightAngle 0.75 nearDistance 0.5 "
           "farDistance 8 }\n"
           "  Transform { rotation 1 1 0 0.5 }\n"
           "  VolumeData { fileName \"ml.zarr\" " +
           dataFields +
           " }\n"
           "  TransferFunction { red [ 0 1, 1 0.3 ] green [ 0 0.2, 1 0.9 ] blue [ 0 0.1, 1 1 ]\n"
           "    alpha [ 0 0, 0.3 0, 0.6 0.3, 1 0.8 ] }\n"
           "  Volume { " +
           volumeFields + " }\n}\n";
}

ref_ptr<Node> readScene(const TempDir& dir, const std::string& name, const std::string& text) {
    const std::string file = dir.file(name);
    std::ofstream(file) << text;
    return volsg::readScene(file);
}

/// Writes Marschner-Lobb 64^3 (8-bit) as dir/ml.zarr, a pyramid of `chunk`^3 chunks.
void writeMarschnerLobbPyramid(const TempDir& dir, int chunk) {
    PyramidOptions pyramid;
    pyramid.chunk = chunk;
    writeOmeZarrPyramid(*makeMarschnerLobb(64, VoxelType::UByte), dir.file("ml.zarr"), pyramid);
}

Volume& volumeOf(Node& root) {
    const std::vector<Node*> found = findAll(root, Volume::classType(), true);
    REQUIRE(found.size() == 1);
    return *static_cast<Volume*>(found.front());
}

/// Renders `scene` until its paged Volume has converged (at most 200 frames).
Image renderConverged(Renderer& renderer, Node& scene, const RenderOptions& options) {
    Image image;
    for (int frame = 0; frame < 200; ++frame) {
        image = renderer.render(scene, options);
        if (volumeOf(scene).slicingStats().paging.converged) break;
        const std::vector<Node*> data = findAll(scene, VolumeData::classType(), true);
        static_cast<VolumeData*>(data.front())->pagedVolume()->cache().waitIdle(50);
    }
    return image;
}

} // namespace

TEST_CASE_FIXTURE(GlFixture, "a paged volume meets its error target with planes chosen on the "
                             "stand-in") {
    const TempDir dir("volsg-paged-target");
    writeMarschnerLobbPyramid(dir, 16);

    RenderOptions options;
    options.width = options.height = 96;
    // memoryBudget 1 (MiB) keeps a stand-in of at most 64 KiB: level 1 (32^3), so the model
    // sees half the resolution the converged frame draws.
    ref_ptr<Node> paged =
        readScene(dir, "paged.iv", sceneText("paging ON memoryBudget 1", "lodPixels 0.25"));
    const Image image = renderConverged(renderer, *paged, options);
    const SlicingStats stats = volumeOf(*paged).slicingStats();
    REQUIRE(stats.paging.paged);
    REQUIRE(stats.paging.converged);
    CHECK(stats.paging.finestLevel == 0);
    REQUIRE(stats.errorTarget > 0.0);
    CHECK(stats.predictedRmse <= stats.errorTarget);

    // The reference: the same file read whole, by the CPU ray caster.
    ref_ptr<Node> whole = readScene(dir, "whole.iv", sceneText("paging OFF", ""));
    const Image reference = renderReference(*whole, options);
    const double measured = difference(image, reference).rmse;
    // The fixed rule it replaced: two planes per voxel of level 0, one sample each.
    ref_ptr<Node> fixed = readScene(
        dir, "fixed.iv", sceneText("paging ON memoryBudget 1", "lodPixels 0.25 errorTarget 0"));
    const Image fixedImage = renderConverged(renderer, *fixed, options);
    keepImage(image, "paged-target");
    keepImage(reference, "paged-target-reference");
    MESSAGE("paged at errorTarget 0.5: "
            << stats.planes << " planes x " << stats.samplesPerPlane << " samples, predicted "
            << stats.predictedRmse / k8Bit << "/255, measured " << measured / k8Bit
            << "/255; the fixed rule: " << volumeOf(*fixed).slicingStats().planes
            << " planes, measured " << difference(fixedImage, reference).rmse / k8Bit << "/255");
    CHECK(measured <= stats.errorTarget);
    // Fewer planes than the fixed rule draws.
    CHECK(stats.planes < volumeOf(*fixed).slicingStats().planes / 2);
}

TEST_CASE_FIXTURE(GlFixture, "a paged frame's predicted error includes its level of detail, "
                             "measured on the levels held whole") {
    const TempDir dir("volsg-paged-lod");
    writeMarschnerLobbPyramid(dir, 8);
    RenderOptions options;
    options.width = options.height = 48;
    // The same planes on both sides, so the difference is the level of detail's.
    const std::string planes = "numPlanes 128 samplesPerPlane 1 ";
    ref_ptr<Node> whole = readScene(dir, "whole.iv", sceneText("paging OFF", planes));
    const Image inMemory = renderer.render(*whole, options);

    // memoryBudget 16 (MiB) keeps a stand-in of up to 1 MiB: level 0 (256 KiB), so every level
    // the frame draws is measured against level 0 itself.
    for (const double lodPixels : {3.0, 6.0}) {
        CAPTURE(lodPixels);
        ref_ptr<Node> paged =
            readScene(dir, "paged.iv",
                      sceneText("paging ON memoryBudget 16",
                                planes + "lodPixels " + std::to_string(lodPixels)));
        const Image image = renderConverged(renderer, *paged, options);
        const SlicingStats stats = volumeOf(*paged).slicingStats();
        REQUIRE(stats.paging.converged);
        REQUIRE(stats.paging.measuredFrom == 0);
        CHECK(stats.paging.finestLevel >= 1);
        const double measured = difference(image, inMemory).rmse;
        MESSAGE("levels " << stats.paging.finestLevel << ".." << stats.paging.coarsestLevel
                          << ": level of detail predicted " << stats.paging.lodRmse / k8Bit
                          << "/255, measured against level 0 in memory " << measured / k8Bit
                          << "/255; quadrature " << stats.quadratureRmse / k8Bit << "/255");
        REQUIRE(measured > 1.0 * k8Bit); // coarse enough to matter
        // On this volume the model's rays see about twice the difference the slicer's image
        // shows (on the chest CT and a 160^3 Marschner-Lobb volume, 0.6-1.3 times:
        // lib/volsg/paging/README.md).
        CHECK(stats.paging.lodRmse >= 0.5 * measured);
        CHECK(stats.paging.lodRmse <= 2.5 * measured);
        CHECK(stats.predictedRmse ==
              doctest::Approx(std::hypot(stats.quadratureRmse, stats.paging.lodRmse)));
        CHECK_FALSE(stats.meetsTarget); // 0.5/255 is far below what these levels give
    }

    // Drawn at level 0: no level-of-detail error, the prediction is the quadrature's.
    ref_ptr<Node> fine = readScene(
        dir, "fine.iv", sceneText("paging ON memoryBudget 16", planes + "lodPixels 0.25"));
    renderConverged(renderer, *fine, options);
    const SlicingStats stats = volumeOf(*fine).slicingStats();
    REQUIRE(stats.paging.converged);
    CHECK(stats.paging.coarsestLevel == 0);
    CHECK(stats.paging.lodRmse == 0.0);
    CHECK(stats.predictedRmse == stats.quadratureRmse);
}
