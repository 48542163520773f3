// The Volume node's 3D-texture slicing against the reference ray caster (docs/SCENE-FORMAT.md 4):
// render modes, opacity correction, precision, data types and grid shapes.
#include "SlicingTestSupport.h"

#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/volume/TestVolumes.h>

using namespace volsg;
using namespace volsg::test;

namespace {

/// A soft sphere 24^3 of rising opacity: the interactive frames' volume.
RayCastVolume softSphere() {
    return volumeOf(makeSoftSphere(24, VoxelType::UByte),
                    transferFunction({{0, 0}, {1, 0.7}}, {{0, 1}, {1, 0.4}}));
}

} // namespace

TEST_CASE_FIXTURE(GlFixture,
                  "DVR through the Volume node matches the reference with a perspective camera") {
    auto root = Separator::create();
    auto data = VolumeData::create();
    data->generator = VolumeData::SOFT_SPHERE;
    data->dimensions = glm::vec3(24.0f);
    auto tf = TransferFunction::create();
    const TransferFunction1D function =
        transferFunction({{0, 0}, {0.2, 0.05}, {1, 0.6}}, {{0, 1}, {1, 0.2}}, {{0, 0.3}, {1, 0.9}});
    setNodeFields(*tf, function);
    auto volume = Volume::create();
    volume->errorTarget = 0.0f; // the fixed rule this test checks (ErrorTargetTest: targets)
    root->addChild(data);
    root->addChild(tf);
    root->addChild(volume);

    const int size = 64;
    auto camera = perspectiveAt({20, 15, 40}, 0.7f, 10.0f, 100.0f);
    RenderOptions options;
    options.width = options.height = size;
    options.camera = camera;
    options.background = glm::vec3(0.1f, 0.2f, 0.3f);
    const Image gl = renderer.render(*root, options);

    const Image ref = referenceImage(rayCamera(*camera, size, size),
                                     {volumeOf(data->grid(), function)}, glm::dvec3(0.1, 0.2, 0.3));
    keepImage(gl, "dvr-perspective-gl");
    keepImage(ref, "dvr-perspective-ref");
    checkDifference(difference(gl, ref), 0.1, 0.5,
                    std::to_string(volume->slicingStats().planes) + " planes: ");
    // Two planes per voxel along the view: 24 voxels across a box seen from a corner-ish
    // direction, whose depth extent is between 24 and 24 * sqrt(3) voxels.
    CHECK(volume->slicingStats().planes >= 48);
    CHECK(volume->slicingStats().planes <= 84);
}

TEST_CASE_FIXTURE(GlFixture, "DVR with an orthographic camera matches the reference") {
    const RayCastVolume v =
        volumeOf(makeGrid({20, 20, 20}, VoxelType::UByte, glm::dvec3(1.0), blob),
                 transferFunction({{0.2, 0}, {0.6, 0.5}}, {{0, 0.2}, {1, 1}}));
    auto camera = orthographicAt({30, -20, 25}, 40.0f, 5.0f, 100.0f);
    const Comparison c = compareGrid(*&renderer, v, {}, *camera, 64, glm::vec3(0.0f, 0.0f, 0.2f));
    keepImage(c.gl, "dvr-ortho-gl");
    checkDifference(c.difference, 0.1, 1.0);
}

TEST_CASE_FIXTURE(GlFixture, "MIP, MINIP and AVERAGE match the reference") {
    RayCastVolume v =
        volumeOf(makeGrid({20, 18, 16}, VoxelType::UByte, glm::dvec3(1.0), blob),
                 transferFunction({{0, 0}, {1, 1}}, {{0, 0}, {1, 1}}, {{0, 1}, {1, 0}}));
    auto camera = framing(*v.data, {0.4f, 0.3f, 1.0f});
    for (const VolumeRenderMode mode :
         {VolumeRenderMode::MIP, VolumeRenderMode::MINIP, VolumeRenderMode::AVERAGE}) {
        v.mode = mode;
        const Comparison c = compareGrid(renderer, v, {}, *camera, 48, glm::vec3(0.2f, 0.1f, 0.0f));
        keepImage(c.gl, "mode-" + std::to_string(int(mode)));
        // MIP/MINIP: extremes of the trilinear field between two planes are missed by up to
        // the field's change over half a plane spacing.
        checkDifference(c.difference, 0.5, 6.0, "mode " + std::to_string(int(mode)) + ": ");
        // The projection is not empty: the volume covers the middle of the image.
        CHECK(c.gl.at(24, 24) != glm::vec4(0.2f, 0.1f, 0.0f, 1.0f));
    }
}

TEST_CASE_FIXTURE(GlFixture,
                  "opacity correction converges to the reference as the plane count grows") {
    const RayCastVolume v = marschnerLobbVolume();
    auto camera = framing(*v.data, {0.3f, 0.5f, 1.0f});
    std::vector<double> errors;
    for (const int planes : {64, 128, 256, 512}) {
        SlicingSettings s;
        s.numPlanes = planes;
        const Comparison c = compareGrid(renderer, v, s, *camera, 48);
        CHECK(c.stats.planes == planes);
        errors.push_back(c.difference.rmse);
        MESSAGE(planes << " planes: rmse " << c.difference.rmse * 255 << "/255, max "
                       << c.difference.max * 255 << "/255");
    }
    CHECK(errors[1] < errors[0]);
    CHECK(errors[2] < errors[1]);
    CHECK(errors[3] < errors[2] * 1.05);
    CHECK(errors[3] < 0.1 * k8Bit);
}

TEST_CASE_FIXTURE(GlFixture,
                  "a smooth transfer function at two planes per voxel is within 1/255 RMSE") {
    const RayCastVolume v =
        volumeOf(makeMarschnerLobb(21, VoxelType::UByte),
                 transferFunction({{0, 0}, {1, 0.5}}, {{0, 0.2}, {1, 1}}, {{0, 0.5}, {1, 0.5}}));
    auto camera = framing(*v.data, {-0.5f, 0.4f, 1.0f});
    const Comparison c = compareGrid(renderer, v, {}, *camera, 64);
    checkDifference(c.difference, 1.0, 2.0, "planes " + std::to_string(c.stats.planes) + ": ");
}

// Found by fuzz-scenegraph: numPlanes 16777216 on a 3-voxel volume drew 65536 full-screen
// planes (half a minute a frame on llvmpipe). Planes are bounded as a density too.
TEST_CASE_FIXTURE(GlFixture, "numPlanes is bounded at 64 samples per voxel along the view") {
    const RayCastVolume v = volumeOf(makeConstant({4, 4, 4}, VoxelType::UByte, 255.0),
                                     transferFunction({{0, 0.3}, {1, 0.3}}, {{0, 1}, {1, 1}}));
    auto camera = orthographicAt({0, 0, 40}, 12.0f, 1.0f, 100.0f);
    SlicingSettings s;
    s.numPlanes = 16777216;
    const Comparison c = compareGrid(renderer, v, s, *camera, 32);
    // Seen along z the box is 4 voxels deep: 256 planes, and the image still the reference's.
    CHECK(c.stats.planes == 256);
    CHECK(c.difference.max < 2 * k8Bit);
    s.samplesPerPlane = 4;
    CHECK(compareGrid(renderer, v, s, *camera, 32).stats.planes == 64);
}

TEST_CASE_FIXTURE(GlFixture,
                  "a thousand planes of alpha 0.002 accumulate within 1/255 of the reference") {
    // A 16-voxel-deep constant volume seen along z by an orthographic camera, cut by 1000
    // planes: each slab is 0.016 voxels, and A is chosen so that its alpha is 0.002.
    const double slabAlpha = 0.002;
    const double A = 1.0 - std::pow(1.0 - slabAlpha, 1.0 / 0.016);
    const RayCastVolume v = volumeOf(makeConstant({8, 8, 16}, VoxelType::UByte, 255.0),
                                     transferFunction({{0, A}, {1, A}}, {{0, 1}, {1, 1}}));
    auto camera = orthographicAt({0, 0, 40}, 12.0f, 1.0f, 100.0f);
    SlicingSettings s;
    s.numPlanes = 1000;
    const Comparison c = compareGrid(renderer, v, s, *camera, 32);
    CHECK(c.stats.planes == 1000);
    // Inside the box's footprint every ray crosses 1000 slabs: 1 - 0.998^1000.
    const double expected = 1.0 - std::pow(1.0 - slabAlpha, 1000.0);
    const glm::vec4 centre = c.gl.at(16, 16);
    MESSAGE("centre " << centre.r << " expected " << expected << ", rmse "
                      << c.difference.rmse * 255 << "/255, max " << c.difference.max * 255);
    CHECK(std::abs(centre.r - expected) < 0.25 * k8Bit);
    CHECK(c.difference.max < k8Bit);
}

TEST_CASE_FIXTURE(GlFixture, "opacity near 1 gives finite pixels without banding") {
    // Fully opaque everywhere: each pixel shows the colour at the box's front face, a ramp in
    // x, over a blue background.
    const RayCastVolume v = volumeOf(
        makeRamp({32, 8, 8}, VoxelType::UShort, 0, 0.0, 65535.0),
        transferFunction({{0, 1}, {1, 1}}, {{0, 0}, {1, 1}}, {{0, 0}, {1, 1}}, {{0, 0}, {1, 0}}));
    auto camera = orthographicAt({0, 0, 30}, 34.0f, 1.0f, 100.0f);
    const Comparison c = compareGrid(renderer, v, {}, *camera, 64, glm::vec3(0.0f, 0.0f, 1.0f));
    CHECK(allFinite(c.gl));
    MESSAGE("rmse " << c.difference.rmse * 255 << "/255, max " << c.difference.max * 255);
    CHECK(c.difference.max < 0.1 * k8Bit);
    // Along the middle row the red ramp rises steadily: no step larger than twice the mean.
    const int y = 32;
    int first = 0, last = 63;
    while (first < 63 && c.gl.at(first, y).b > 0.5f)
        ++first;
    while (last > 0 && c.gl.at(last, y).b > 0.5f)
        --last;
    REQUIRE(last - first > 40);
    const double mean = (c.gl.at(last, y).r - c.gl.at(first, y).r) / double(last - first);
    CHECK(mean > 0.0);
    for (int x = first; x < last; ++x) {
        const double step = c.gl.at(x + 1, y).r - c.gl.at(x, y).r;
        CHECK(step >= 0.0);
        CHECK(step < 2.0 * mean);
    }
}

TEST_CASE_FIXTURE(GlFixture, "interactive and still frames are both near the reference") {
    const RayCastVolume v = softSphere();
    auto camera = framing(*v.data, {1.0f, 0.2f, 0.6f});
    const Comparison still = compareGrid(renderer, v, {}, *camera, 48);
    const Comparison moving = compareGrid(renderer, v, {}, *camera, 48, glm::vec3(0.0f), true);
    MESSAGE("still " << still.stats.planes << " planes rmse " << still.difference.rmse * 255
                     << "/255");
    CHECK(moving.stats.planes == (still.stats.planes + 3) / 4);
    CHECK(still.difference.rmse < 0.25 * k8Bit);
    checkDifference(moving.difference, 1.0, 4.0,
                    "interactive " + std::to_string(moving.stats.planes) + " planes: ");
}

TEST_CASE_FIXTURE(GlFixture,
                  "the viewer's interactive plane scale lowers the interactive plane count only") {
    const RayCastVolume v = softSphere();
    auto camera = framing(*v.data, {1.0f, 0.2f, 0.6f});
    auto root = Separator::create();
    auto node = GridVolume::create();
    node->description = v;
    node->settings.interactivePlanes = 40;
    root->addChild(node);
    RenderOptions options;
    options.width = options.height = 32;
    options.camera = camera;
    options.interactivePlaneScale = 0.25;
    renderer.render(*root, options);
    const int still = node->stats.planes;
    options.interactive = true;
    renderer.render(*root, options);
    CHECK(node->stats.planes == 10); // 40 interactive planes x 0.25
    options.interactivePlaneScale = 1.0;
    renderer.render(*root, options);
    CHECK(node->stats.planes == 40);
    CHECK(still > 40); // the still frame ignores the scale
    // However slow the frames, the scale leaves at least 8 planes (no seams of 2-3 slabs) ...
    options.interactivePlaneScale = 1.0 / 64.0;
    renderer.render(*root, options);
    CHECK(node->stats.planes == 8);
    // ... unless fewer were asked for.
    node->settings.interactivePlanes = 5;
    renderer.render(*root, options);
    CHECK(node->stats.planes == 5);
}

TEST_CASE_FIXTURE(GlFixture, "16-bit data over its full range matches the reference") {
    // Over the whole range, and over a narrow window near the top (5000 of 65535: 19 steps of
    // 8-bit data), sampled finely so that what remains is the data path's precision.
    RayCastVolume v =
        volumeOf(makeFullRange16(20), transferFunction({{0, 0}, {1, 0.6}}, {{0, 0}, {1, 1}}));
    auto camera = framing(*v.data, {0.2f, -0.3f, 1.0f});
    const Comparison wide = compareGrid(renderer, v, {}, *camera, 48);
    TransferFunction1D narrow = transferFunction({{0, 0}, {1, 0.9}}, {{0, 1}, {1, 0}});
    narrow.setDataRange(60000.0, 65000.0);
    v.transferFunctions[-1] = narrow;
    SlicingSettings fine;
    fine.numPlanes = 400;
    const Comparison window = compareGrid(renderer, v, fine, *camera, 48);
    keepImage(window.gl, "16bit-window");
    MESSAGE("full range rmse " << wide.difference.rmse * 255 << "/255");
    CHECK(wide.difference.rmse < 0.25 * k8Bit);
    checkDifference(window.difference, 0.1, 1.0, "window: ");
}

TEST_CASE_FIXTURE(GlFixture, "SHORT and FLOAT data match the reference") {
    auto camera = perspectiveAt({10, 20, 40}, 0.6f, 10.0f, 100.0f);
    for (const VoxelType type : {VoxelType::Short, VoxelType::Float}) {
        TransferFunction1D tf = transferFunction({{0.3, 0}, {0.8, 0.7}}, {{0, 0.5}, {1, 1}});
        if (type == VoxelType::Short) tf.setDataRange(-100.0, 32767.0);
        const RayCastVolume v = volumeOf(makeGrid({16, 16, 16}, type, glm::dvec3(1.0), blob), tf);
        const Comparison c = compareGrid(renderer, v, {}, *camera, 48);
        checkDifference(c.difference, 0.25, 1.5, std::string(voxelTypeName(type)) + ": ");
    }
}

TEST_CASE_FIXTURE(GlFixture, "NaN and infinite float voxels are replaced as the reference does") {
    auto grid = makeGrid({12, 12, 12}, VoxelType::Float, glm::dvec3(1.0), blob);
    grid->setValue(3, 4, 5, std::numeric_limits<double>::quiet_NaN());
    grid->setValue(6, 6, 6, std::numeric_limits<double>::infinity());
    grid->setValue(8, 3, 7, -std::numeric_limits<double>::infinity());
    const RayCastVolume v =
        volumeOf(grid, transferFunction({{0, 0.1}, {1, 0.9}}, {{0, 1}, {1, 0}}));
    auto camera = framing(*v.data, {0.3f, 0.2f, 1.0f});
    const Comparison c = compareGrid(renderer, v, {}, *camera, 48);
    CHECK(allFinite(c.gl));
    checkDifference(c.difference, 0.25, 2.0);
}

TEST_CASE_FIXTURE(GlFixture, "anisotropic spacing 1 1.5 2.5 matches the reference") {
    const RayCastVolume v =
        volumeOf(makeGrid({20, 14, 9}, VoxelType::UByte, glm::dvec3(1.0, 1.5, 2.5), blob),
                 transferFunction({{0.2, 0}, {0.7, 0.6}}, {{0, 0.3}, {1, 1}}));
    for (const glm::vec3 direction : {glm::vec3(0, 0, 1), glm::vec3(1, 0.7, 0.4)}) {
        auto camera = framing(*v.data, direction);
        const Comparison c = compareGrid(renderer, v, {}, *camera, 48);
        checkDifference(c.difference, 0.25, 1.5, "planes " + std::to_string(c.stats.planes) + ": ");
    }
}

TEST_CASE_FIXTURE(GlFixture, "NPOT 37x23x19, 1x1xN and Nx1x1 volumes match the reference") {
    const glm::ivec3 shapes[] = {{37, 23, 19}, {1, 1, 29}, {31, 1, 1}};
    for (const glm::ivec3 dims : shapes) {
        // Thin dimensions get a wide spacing so the box is not a needle.
        const glm::dvec3 spacing(dims.x == 1 ? 12.0 : 1.0, dims.y == 1 ? 12.0 : 1.0,
                                 dims.z == 1 ? 12.0 : 1.0);
        const auto grid = makeGrid(dims, VoxelType::UByte, spacing, [](const glm::dvec3& p) {
            return 0.5 + 0.4 * std::sin(2.5 * p.x + 1.7 * p.z) * std::cos(1.3 * p.y);
        });
        const RayCastVolume v =
            volumeOf(grid, transferFunction({{0, 0.05}, {1, 0.5}}, {{0, 0}, {1, 1}}));
        auto camera = framing(*v.data, {0.5f, 0.6f, 1.0f});
        const Comparison c = compareGrid(renderer, v, {}, *camera, 48);
        const std::string name =
            std::to_string(dims.x) + "x" + std::to_string(dims.y) + "x" + std::to_string(dims.z);
        keepImage(c.gl, "shape-" + name);
        checkDifference(c.difference, 0.25, 1.5, name + ": ");
    }
}
