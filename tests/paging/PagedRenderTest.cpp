// A volume paged from its pyramid: the first frame draws what is at hand, later frames refine
// as bricks arrive, the converged image equals the in-memory render of level 0, and the host
// and texture budgets hold at every frame.
#include "slicing/SlicingTestSupport.h"
#include "support/TempDir.h"

#include <chrono>
#include <fstream>
#include <functional>
#include <thread>

#include <volsg/core/Error.h>
#include <volsg/nodes/Light.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/paging/PagedVolume.h>
#include <volsg/volumeio/OmeZarrPyramid.h>
#include <volsg/volumeio/VolumeReader.h>

using namespace volsg;
using namespace volsg::test;

namespace {

/// A 64^3 UByte Marschner-Lobb volume written as a pyramid of 16^3 chunks (levels 64, 32, 16).
std::string writeTestPyramid(const TempDir& dir) {
    const std::string folder = dir.file("ml.zarr");
    PyramidOptions options;
    options.chunk = 16;
    writeOmeZarrPyramid(*makeMarschnerLobb(64, VoxelType::UByte), folder, options);
    return folder;
}

TransferFunction1D testFunction() {
    return transferFunction({{0, 0}, {0.3, 0.0}, {0.6, 0.3}, {1, 0.8}}, {{0, 1}, {1, 0.3}},
                            {{0, 0.2}, {1, 0.9}});
}

/// A pyramid file drawn through the nodes: a light, VolumeData (paged or not), the test
/// transfer function and a Volume with fixed planes (the same quadrature paged or not) and
/// level 0 everywhere.
struct FileScene {
    ref_ptr<Separator> root = Separator::create();
    ref_ptr<VolumeData> data = VolumeData::create();
    ref_ptr<Volume> volume = Volume::create();

    FileScene(const std::string& folder, VolumeData::Paging paging) {
        auto light = DirectionalLight::create();
        light->direction = glm::vec3(-1.0f, -0.6f, -0.4f);
        root->addChild(light);
        data->fileName = folder;
        data->paging = paging;
        root->addChild(data);
        auto transfer = TransferFunction::create();
        setNodeFields(*transfer, testFunction());
        root->addChild(transfer);
        volume->errorTarget = 0.0f;
        volume->numPlanes = 160;
        volume->lodPixels = 0.25f;
        root->addChild(volume);
    }

    /// Still frames until the paged volume's frame converged (one frame when not paged).
    Image converge(Renderer& renderer, const RenderOptions& render, int& frames) {
        Image image = renderer.render(*root, render);
        for (frames = 1; volume->slicingStats().paging.paged &&
                         !volume->slicingStats().paging.converged && frames < 400;
             ++frames) {
            if (const auto paged = data->pagedVolume()) paged->cache().waitIdle(50);
            image = renderer.render(*root, render);
        }
        return image;
    }
};

/// A 64^3 Marschner-Lobb pyramid of 8^3 chunks (levels 64, 32, 16, 8): bricks of 14 cells,
/// five a side on level 0.
std::string writeSmallChunkPyramid(const TempDir& dir) {
    const std::string folder = dir.file("ml8.zarr");
    PyramidOptions options;
    options.chunk = 8;
    writeOmeZarrPyramid(*makeMarschnerLobb(64, VoxelType::UByte), folder, options);
    return folder;
}

/// The paged and the in-memory render of the same file, both converged, as `set` makes them.
ImageDifference pagedAgainstInMemory(Renderer& renderer, const std::string& folder,
                                     const std::string& name,
                                     const std::function<void(Volume&)>& set) {
    FileScene paged(folder, VolumeData::ON);
    FileScene inMemory(folder, VolumeData::OFF);
    set(*paged.volume);
    set(*inMemory.volume);
    RenderOptions render;
    render.width = render.height = 96;
    render.camera = framing(*inMemory.data->grid(), {1.0f, 0.4f, 0.7f});
    int frames = 0;
    const Image want = inMemory.converge(renderer, render, frames);
    const Image got = paged.converge(renderer, render, frames);
    REQUIRE(paged.data->pagedVolume());
    const PagingStats& s = paged.volume->slicingStats().paging;
    REQUIRE(s.converged);
    CHECK(s.finestLevel == 0);
    CHECK(s.coarsestLevel == 0);
    CHECK(s.bricksDrawn >= 27); // seams along every axis
    // The guard widens for lighting and pre-integration only; textures stay 16^3 either way
    // (bricks of 14 cells, or 12 with the wide guard).
    const SlicingStats& drawn = paged.volume->slicingStats();
    const bool wide = paged.volume->lighting() || paged.volume->preIntegrated();
    CHECK(paged.data->pagedVolume()->wideGuard() == wide);
    CHECK(paged.data->pagedVolume()->layout().brickCells() == (wide ? 12 : 14));
    CHECK(drawn.brickTexels == glm::ivec3(16));
    CHECK(drawn.preIntegrated == paged.volume->preIntegrated());
    CHECK(inMemory.volume->slicingStats().preIntegrated == paged.volume->preIntegrated());
    keepImage(got, name + "-paged");
    keepImage(want, name + "-in-memory");
    Image magnified(got.width, got.height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    for (std::size_t i = 0; i < got.pixels.size(); ++i) // 1/255 off shows as 32/255
        magnified.pixels[i] =
            glm::vec4(32.0f * glm::abs(glm::vec3(got.pixels[i] - want.pixels[i])), 1.0f);
    keepImage(magnified, name + "-difference-x32");
    const ImageDifference d = difference(got, want);
    MESSAGE(name << ": " << s.bricksDrawn << " bricks of level 0 after " << frames
                 << " frames; against the in-memory render rmse " << d.rmse / k8Bit << "/255, max "
                 << d.max / k8Bit << "/255 at " << d.x << ", " << d.y);
    return d;
}

} // namespace

TEST_CASE_FIXTURE(GlFixture, "a lit paged volume is seamless: it equals the lit in-memory render") {
    const TempDir dir("volsg-paged");
    const std::string folder = writeSmallChunkPyramid(dir);
    const ImageDifference d =
        pagedAgainstInMemory(renderer, folder, "paged-lit", [](Volume& v) { v.lighting = true; });
    // Central differences read the same voxels on both sides of every seam: float rounding of
    // the brick-local texture coordinates only.
    CHECK(d.max < 1.0 * k8Bit);
    CHECK(d.rmse < 0.1 * k8Bit);
}

TEST_CASE_FIXTURE(GlFixture, "pre-integrated and unlit paged volumes equal their in-memory "
                             "renders") {
    const TempDir dir("volsg-paged");
    const std::string folder = writeSmallChunkPyramid(dir);
    const ImageDifference unlit =
        pagedAgainstInMemory(renderer, folder, "paged-unlit", [](Volume&) {});
    CHECK(unlit.max < 1.0 * k8Bit);
    CHECK(unlit.rmse < 0.1 * k8Bit);
    const ImageDifference pre = pagedAgainstInMemory(renderer, folder, "paged-pre-integrated",
                                                     [](Volume& v) { v.preIntegrated = true; });
    CHECK(pre.max < 1.0 * k8Bit);
    CHECK(pre.rmse < 0.1 * k8Bit);
}

TEST_CASE_FIXTURE(GlFixture, "lighting turned on later widens the guard: the bricks load again "
                             "and the image is seamless") {
    const TempDir dir("volsg-paged");
    const std::string folder = writeTestPyramid(dir); // chunks of 16: 16^3 textures
    PagedVolumeOptions options;
    options.standInBytes = 16 * 16 * 16; // level 2 kept whole: levels 0 and 1 load
    options.chunkCacheBytes = 16 * 16 * 16 * 4;
    options.hostBudget = 1 << 20;
    auto paged = std::make_shared<PagedVolume>(folder, options);
    const ref_ptr<const VolumeGrid> full = readOmeZarr(folder, 0);

    auto light = DirectionalLight::create();
    light->direction = glm::vec3(-1.0f, -0.6f, -0.4f);
    auto root = Separator::create();
    root->addChild(light);
    auto node = GridVolume::create();
    node->description = volumeOf(paged->standIn(), testFunction());
    node->description.paged = paged;
    node->settings.numPlanes = 160;
    node->settings.lodPixels = 0.25;
    node->settings.textureBudget = 300 * 16 * 16 * 16 * 2;
    root->addChild(node);
    auto inMemory = Separator::create();
    inMemory->addChild(light);
    auto whole = GridVolume::create();
    whole->description = volumeOf(full, testFunction());
    whole->settings.numPlanes = 160;
    inMemory->addChild(whole);
    RenderOptions render;
    render.width = render.height = 96;
    render.camera = framing(*full, {1.0f, 0.4f, 0.7f});
    auto converge = [&] {
        Image image = renderer.render(*root, render);
        for (int frames = 1; !node->stats.paging.converged && frames < 400; ++frames) {
            paged->cache().waitIdle(50);
            image = renderer.render(*root, render);
        }
        REQUIRE(node->stats.paging.converged);
        CHECK(node->stats.paging.finestLevel == 0);
        CHECK(node->stats.paging.coarsestLevel == 0);
        return image;
    };

    const Image unlit = converge();
    CHECK_FALSE(paged->wideGuard()); // unlit: the narrow guard, 16^3 textures, as always
    CHECK(paged->layout().brickCells() == 14);
    CHECK(node->stats.brickTexels == glm::ivec3(16));
    const std::uint64_t unlitLoads = node->stats.paging.bricksLoaded;
    CHECK(difference(unlit, renderer.render(*inMemory, render)).max < 1.0 * k8Bit);

    node->settings.lighting = true;
    whole->settings.lighting = true;
    const Image lit = converge();
    CHECK(paged->wideGuard());
    CHECK(paged->layout().brickCells() == 12); // two voxels fewer: still 16^3 textures
    CHECK(node->stats.brickTexels == glm::ivec3(16));
    CHECK(node->stats.paging.textureBytes <= node->stats.paging.textureBudget);
    CHECK(node->stats.paging.bricksLoaded > unlitLoads); // loaded again, with the wide guard
    const Image want = renderer.render(*inMemory, render);
    keepImage(lit, "paged-lit-later");
    const ImageDifference d = difference(lit, want);
    MESSAGE("lit after unlit: rmse " << d.rmse / k8Bit << "/255, max " << d.max / k8Bit
                                     << "/255 against the in-memory render");
    CHECK(d.max < 1.0 * k8Bit);
    CHECK(d.rmse < 0.1 * k8Bit);
}

TEST_CASE_FIXTURE(GlFixture,
                  "a paged volume refines to the in-memory render within its host and texture "
                  "budgets") {
    const TempDir dir("volsg-paged");
    const std::string folder = writeTestPyramid(dir);
    PagedVolumeOptions options;
    options.standInBytes = 16 * 16 * 16; // level 2 kept whole: levels 0 and 1 page
    options.chunkCacheBytes = 16 * 16 * 16 * 4;
    options.hostBudget = 120 * 1024; // some 25 bricks of level 0 (16^3): evictions happen
    options.loaderThreads = 2;
    auto paged = std::make_shared<PagedVolume>(folder, options);
    REQUIRE(paged->standInLevel() == 2);
    const ref_ptr<VolumeGrid> full = readOmeZarr(folder, 0);
    CHECK(paged->standIn()->extent() == full->extent());

    auto root = Separator::create();
    auto node = GridVolume::create();
    node->description = volumeOf(paged->standIn(), testFunction());
    node->description.paged = paged;
    node->settings.numPlanes = 160;
    node->settings.lodPixels = 0.25; // level 0 everywhere at this size
    // Bricks of 14 cells (16^3 texels with the guards): all 125 of level 0 and their 27 + 8
    // ancestors (kept as fallbacks), as R16 texels.
    REQUIRE(paged->layout().brickCells() == 14);
    node->settings.textureBudget = (125 + 27 + 8) * 16 * 16 * 16 * 2;
    root->addChild(node);
    const int size = 96;
    RenderOptions render;
    render.width = render.height = size;
    render.camera = framing(*full, {1.0f, 0.4f, 0.7f});

    const Image first = renderer.render(*root, render);
    const PagingStats firstStats = node->stats.paging;
    REQUIRE(firstStats.paged);
    CHECK(firstStats.finestLevel == 2); // only the stand-in's bricks, without waiting
    CHECK_FALSE(firstStats.converged);
    Image last = first;
    int frames = 1;
    for (; frames < 400 && !node->stats.paging.converged; ++frames) {
        paged->cache().waitIdle(50);
        render.interactive = frames % 3 == 1; // interactive frames refine too, never waiting
        last = renderer.render(*root, render);
        const PagingStats& s = node->stats.paging;
        CHECK(s.bricksDrawn > 0); // at least the roots, whatever the upload allowance left
        CHECK(s.hostBytes <= s.hostBudget);
        CHECK(s.textureBytes <= s.textureBudget);
        if (s.hostBytes > s.hostBudget || s.textureBytes > s.textureBudget) break;
    }
    render.interactive = false;
    last = renderer.render(*root, render);
    REQUIRE(node->stats.paging.converged);
    CHECK(node->stats.paging.finestLevel == 0);
    CHECK(node->stats.paging.coarsestLevel == 0);
    CHECK(node->stats.paging.hostEvictions > 0); // the host budget was tight, and held
    CHECK(paged->cache().stats().peakBytes <= paged->cache().stats().budgetBytes);

    auto inMemory = Separator::create();
    auto whole = GridVolume::create();
    whole->description = volumeOf(full, testFunction());
    whole->settings.numPlanes = 160;
    inMemory->addChild(whole);
    const Image want = renderer.render(*inMemory, render);
    keepImage(first, "paged-first");
    keepImage(last, "paged-converged");
    keepImage(want, "paged-in-memory");
    const ImageDifference converged = difference(last, want);
    const ImageDifference coarse = difference(first, want);
    MESSAGE("coarse rmse " << coarse.rmse / k8Bit << "/255, converged " << converged.rmse / k8Bit
                           << "/255 (max " << converged.max / k8Bit << ") after " << frames
                           << " frames");
    // Same voxels, same planes, bricks of one level whose guard voxels make seams exact: the
    // images differ by float rounding of the brick-local texture coordinates only.
    CHECK(converged.rmse < 0.1 * k8Bit);
    CHECK(converged.max < 1.0 * k8Bit);
    CHECK(coarse.rmse > 4.0 * converged.rmse); // the first frame was coarse indeed
}

TEST_CASE_FIXTURE(GlFixture, "an unreadable chunk leaves its bricks coarse, says where, and "
                             "the frame still converges") {
    const TempDir dir("volsg-paged");
    const std::string folder = writeTestPyramid(dir);
    {
        std::ofstream corrupt(folder + "/0/1/1/1", std::ios::binary | std::ios::trunc);
        corrupt << "not a zstd frame";
    }
    PagedVolumeOptions options;
    options.standInBytes = 16 * 16 * 16;
    options.chunkCacheBytes = 16 * 16 * 16 * 4;
    options.hostBudget = 1 << 20;
    auto paged = std::make_shared<PagedVolume>(folder, options);
    auto root = Separator::create();
    auto node = GridVolume::create();
    node->description = volumeOf(paged->standIn(), testFunction());
    node->description.paged = paged;
    node->settings.lodPixels = 0.25;
    root->addChild(node);
    RenderOptions render;
    render.width = render.height = 64;
    render.camera = framing(*paged->standIn(), {1.0f, 0.4f, 0.7f});
    int frames = 0;
    do {
        paged->cache().waitIdle(50);
        renderer.render(*root, render);
    } while (!node->stats.paging.converged && ++frames < 400);
    const PagingStats& s = node->stats.paging;
    CHECK_MESSAGE(s.converged, "after " << frames << " frames: " << s.wanted << " wanted, "
                                        << s.queued << " queued, " << s.loading << " loading, "
                                        << s.loadFailures << " failed, levels " << s.finestLevel
                                        << ".." << s.coarsestLevel);
    CHECK(node->stats.paging.loadFailures > 0);
    CHECK(node->stats.paging.coarsestLevel >= 1); // the bricks of the bad chunk: their parents
    CHECK(node->stats.paging.firstError.find("0/1/1/1") != std::string::npos);
    CHECK(node->stats.paging.firstError.find("zstd") != std::string::npos);
}

TEST_CASE("VolumeData pages an OME-Zarr pyramid when asked or when level 0 exceeds its budget") {
    const TempDir dir("volsg-paged");
    const std::string folder = writeTestPyramid(dir);
    auto data = VolumeData::create();
    data->fileName = folder;
    CHECK_FALSE(data->pagedVolume()); // 256 KiB fit the default 1 GiB: read whole
    CHECK(data->grid()->dimensions() == glm::ivec3(64));
    data->paging = VolumeData::ON;
    REQUIRE(data->pagedVolume());
    CHECK(data->grid()->extent() == readOmeZarr(folder, 0)->extent());
    CHECK(data->localBounds().max.x == doctest::Approx(0.5 * data->grid()->extent().x));
    data->paging = VolumeData::OFF;
    CHECK_FALSE(data->pagedVolume());
    // A budget too small for the coarse levels and a few bricks is one error naming the image.
    data->paging = VolumeData::ON;
    data->memoryBudget = 0u;
    std::string error;
    try {
        data->grid();
    } catch (const Error& e) {
        error = e.what();
    }
    CHECK(error.find("host memory budget of 0 bytes") != std::string::npos);
    CHECK(error.find("ml.zarr") != std::string::npos);
}
