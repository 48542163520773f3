// The VolumeSeries node: file-pattern series read from NRRD and raw files, clear errors for
// malformed fields, lazy clipping across cached steps, and the Volume (texture) path.
#include <doctest/doctest.h>

#include <volsg/actions/SearchAction.h>
#include <volsg/context/OSMesaContext.h>
#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeObject.h>
#include <volsg/nodes/VolumeSeries.h>
#include <volsg/render/Renderer.h>
#include <volsg/shearwarp/VoxelObject.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace volsg;

namespace {

template <class T> T* findNode(Node& root) {
    const std::vector<Node*> found = findAll(root, T::classType());
    return found.empty() ? nullptr : static_cast<T*>(found.front());
}

/// A fresh folder under the temp folder, removed with the object.
struct TempFolder {
    std::filesystem::path path;
    explicit TempFolder(const std::string& name)
        : path(std::filesystem::temp_directory_path() / name) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempFolder() { std::filesystem::remove_all(path); }
};

/// 4x3x2 UByte voxels whose values say the step: value = 10 * step + index % 10.
std::vector<std::uint8_t> stepVoxels(int step) {
    std::vector<std::uint8_t> v(24);
    for (std::size_t i = 0; i < v.size(); ++i)
        v[i] = std::uint8_t(10 * step + int(i % 10));
    return v;
}

void writeFile(const std::filesystem::path& path, const std::string& header,
               const std::vector<std::uint8_t>& voxels) {
    std::ofstream out(path, std::ios::binary);
    out << header;
    out.write(reinterpret_cast<const char*>(voxels.data()), std::streamsize(voxels.size()));
}

/// The MOVING_SPHERE series (32^3 in [-1, 1]^3) under an orthographic camera, shear-warp.
std::string sphereSeriesScene(int step, const std::string& clipPlane) {
    return "#Inventor V2.1 ascii\nSeparator {\n"
           "  OrthographicCamera { position 0 0 5 height 2.5 nearDistance 1 farDistance 9 }\n"
           "  VolumeSeries { timeGenerator MOVING_SPHERE dimensions 32 32 32 "
           "spacing 0.0625 0.0625 0.0625 timeSteps 0 5 step " +
           std::to_string(step) + " }\n  ClipPlane { plane " + clipPlane +
           " }\n"
           "  ShearWarpVolume { optimize FALSE\n"
           "    TransferFunction { alpha [ 0 0, 0.1 0, 1 0.8 ] }\n"
           "    VolumeObject { } }\n}\n";
}

RenderOptions smallOptions() {
    RenderOptions options;
    options.width = options.height = 64;
    return options;
}

double maxDifference(const Image& a, const Image& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 4; ++c)
            worst = std::max(worst, double(std::abs(a.pixels[i][c] - b.pixels[i][c])));
    return worst;
}

/// Brightness-weighted mean x of an image (pixels), -1 when black.
double centroidX(const Image& image) {
    double sum = 0.0, weighted = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec4& p = image.pixels[std::size_t(y) * image.width + x];
            const double w = p.r + p.g + p.b;
            sum += w;
            weighted += w * x;
        }
    return sum > 0.0 ? weighted / sum : -1.0;
}

} // namespace

TEST_CASE("a file-pattern series reads the NRRD and raw files written by the test") {
    TempFolder folder("volsg-series-files-test");
    for (int s = 0; s < 3; ++s)
        writeFile(folder.path /
                      ("step_" + std::string(s < 10 ? "000" : "00") + std::to_string(s) + ".nrrd"),
                  "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 3 2\nspacings: 1 2 3\n"
                  "encoding: raw\n\n",
                  stepVoxels(s));
    for (int s = 7; s <= 8; ++s)
        writeFile(folder.path / ("raw" + std::to_string(s) + ".bin"), "", stepVoxels(s));
    const std::string scene = "#Inventor V2.1 ascii\nSeparator {\n"
                              "  VolumeSeries { fileName \"step_%04d.nrrd\" timeSteps 0 2 }\n"
                              "  VolumeSeries { fileName \"raw%d.bin\" timeSteps 7 8 step 1 "
                              "dimensions 4 3 2 dataType UBYTE }\n"
                              "  VolumeSeries { fileNames [ \"raw8.bin\", \"raw7.bin\" ] "
                              "dimensions 4 3 2 }\n}\n";
    { std::ofstream(folder.path / "series.iv") << scene; }
    const ref_ptr<Node> root = readScene((folder.path / "series.iv").string());
    auto* nrrd = static_cast<VolumeSeries*>(root->children()->at(0).get());
    auto* raw = static_cast<VolumeSeries*>(root->children()->at(1).get());
    auto* listed = static_cast<VolumeSeries*>(root->children()->at(2).get());
    CHECK(nrrd->stepCount() == 3);
    CHECK(raw->stepCount() == 2);
    CHECK(listed->stepCount() == 2);
    for (int s = 0; s < 3; ++s) {
        nrrd->step = s;
        const ref_ptr<const VolumeGrid> grid = nrrd->grid();
        REQUIRE(grid);
        CHECK(grid->dimensions() == glm::ivec3(4, 3, 2));
        CHECK(grid->spacing() == glm::dvec3(1.0, 2.0, 3.0));
        const auto expected = stepVoxels(s);
        CHECK(std::vector<std::uint8_t>(grid->data<std::uint8_t>().begin(),
                                        grid->data<std::uint8_t>().end()) == expected);
    }
    CHECK(raw->grid()->value(0, 0, 0) == 80.0); // step 1 is file number 8
    CHECK(listed->grid()->value(5) == 85.0);    // step 0 is the first name: raw8.bin
    listed->step = 1;
    CHECK(listed->grid()->value(5) == 75.0);
    raw->step = 99; // clamped to the last step
    CHECK(raw->shownStep() == 1);

    // The fields round-trip through the writer.
    const ref_ptr<Node> again = readSceneFromString(writeSceneToString(*root));
    auto* back = static_cast<VolumeSeries*>(again->children()->at(1).get());
    CHECK(back->fileName() == "raw%d.bin");
    CHECK(back->timeSteps() == glm::vec2(7.0f, 8.0f));

    nrrd->timeSteps = glm::vec2(0.0f, 3.0f); // a new source: its cache starts empty
    nrrd->step = 3;                          // step_0003.nrrd was never written
    CHECK_THROWS_WITH_AS(nrrd->grid(), doctest::Contains("step_0003.nrrd"), Error);
    nrrd->step = 2;
    CHECK(nrrd->grid()->value(0) == 20.0);
}

TEST_CASE("malformed series fields are clear errors") {
    const auto gridOf = [](const std::string& fields) {
        const ref_ptr<Node> root =
            readSceneFromString("#Inventor V2.1 ascii\nVolumeSeries { " + fields + " }\n");
        return static_cast<VolumeSeries&>(*root).grid();
    };
    const std::pair<const char*, const char*> cases[] = {
        {"fileName \"a%s.raw\" timeSteps 0 3", "series file pattern"},
        {"fileName \"a%n.raw\" timeSteps 0 3", "series file pattern"},
        {"fileName \"%d%d%d\" timeSteps 0 3", "more than one conversion"},
        {"fileName \"a%d.raw\" timeSteps 0 1000000000", "at most"},
        {"fileName \"a%d.raw\" timeSteps 5 2", "before the first"},
        {"fileName \"a%d.raw\" timeSteps 0.5 2", "whole numbers"},
        {"timeGenerator MOVING_SPHERE dimensions 8 8 9", "cubic"},
        {"", "VolumeSeries needs"},
    };
    for (const auto& c : cases) { // not a structured binding: CAPTURE's lambda captures it
        const char* fields = c.first;
        CAPTURE(fields);
        CHECK_THROWS_WITH_AS(gridOf(fields), doctest::Contains(c.second), Error);
    }
}

TEST_CASE("a clip change costs no extraction until a step is shown, then matches a fresh render") {
    OSMesaContext context;
    Renderer renderer;
    const ref_ptr<Node> root = readSceneFromString(sphereSeriesScene(0, "1 0 0 -0.9"));
    auto* series = findNode<VolumeSeries>(*root);
    auto* plane = findNode<ClipPlane>(*root);
    auto* object = findNode<VolumeObject>(*root);
    REQUIRE((series && plane && object));
    for (int s = 0; s < 6; ++s) { // view every step once: all six are cached
        series->step = s;
        renderer.render(*root, smallOptions());
    }
    series->cache().waitUntilIdle();
    const SeriesCacheStats before = series->cache().stats();
    CHECK(before.extractions == 6u);
    CHECK(before.spills == 0u);

    const ExtractionSpec spec =
        object->extractionSpec(findNode<TransferFunction>(*root)->function());
    std::vector<std::uint64_t> clipKeys;
    for (int s = 0; s < 6; ++s) {
        const ref_ptr<VoxelObject> cached = series->cache().peek(s, spec);
        REQUIRE(cached);
        REQUIRE(cached->hasRenderList(2));
        clipKeys.push_back(cached->renderList(2).clipKey);
    }

    plane->plane = Plane{glm::vec3(1.0f, 0.0f, 0.0f), 0.1f}; // cut the sphere
    renderer.render(*root, smallOptions());                  // step 5 is shown: only it updates
    series->cache().waitUntilIdle();
    CHECK(series->cache().stats().extractions == before.extractions);
    for (int s = 0; s < 5; ++s) // the other cached steps were not touched
        CHECK(series->cache().peek(s, spec)->renderList(2).clipKey == clipKeys[std::size_t(s)]);
    CHECK(series->cache().peek(5, spec)->renderList(2).clipKey != clipKeys[5]);

    series->step = 2;
    const Image browsed = renderer.render(*root, smallOptions());
    CHECK(series->cache().stats().extractions == before.extractions);
    CHECK(series->cache().peek(2, spec)->renderList(2).clipKey != clipKeys[2]);
    CHECK(series->cache().peek(3, spec)->renderList(2).clipKey == clipKeys[3]);

    Renderer freshRenderer;
    const ref_ptr<Node> fresh = readSceneFromString(sphereSeriesScene(2, "1 0 0 0.1"));
    const Image expected = freshRenderer.render(*fresh, smallOptions());
    CHECK(maxDifference(browsed, expected) <= 1e-6);
    // And the clip really cut: the fresh image is not the unclipped one.
    const ref_ptr<Node> unclipped = readSceneFromString(sphereSeriesScene(2, "1 0 0 -0.9"));
    CHECK(maxDifference(freshRenderer.render(*unclipped, smallOptions()), expected) > 0.05);
}

TEST_CASE("the Volume node shows the series' steps: the sphere moves to +x") {
    OSMesaContext context;
    Renderer renderer;
    const ref_ptr<Node> root = readSceneFromString(
        "#Inventor V2.1 ascii\nSeparator {\n"
        "  OrthographicCamera { position 0 0 5 height 2.5 nearDistance 1 farDistance 9 }\n"
        "  VolumeSeries { timeGenerator MOVING_SPHERE dimensions 32 32 32 "
        "spacing 0.0625 0.0625 0.0625 timeSteps 0 4 }\n"
        "  TransferFunction { alpha [ 0 0, 0.05 0, 1 1 ] }\n"
        "  Volume { }\n}\n");
    auto* series = findNode<VolumeSeries>(*root);
    // The sphere's centre moves from x = 0.35 n to 0.65 n voxels: -0.3 to +0.3 in local
    // units (n = 32, spacing 1/16); 64 pixels span 2.5 units, so 25.6 pixels per unit.
    const double expectedCentre[2] = {32.0 - 0.3 * 25.6, 32.0 + 0.3 * 25.6};
    for (int i = 0; i < 2; ++i) {
        series->step = i == 0 ? 0 : 4;
        const double cx = centroidX(renderer.render(*root, smallOptions()));
        // Pixel x of a pixel centre is x + 0.5: the centroid of the centres is 0.5 less.
        CHECK(std::abs(cx - (expectedCentre[i] - 0.5)) <= 1.0);
    }
    CHECK(series->cache().stats().gridLoads >= 2u);
}

namespace {

/// A 3-step MOVING_SPHERE series (32^3) drawn by the Volume node, shown at `step`.
std::string textureSeriesScene(int step) {
    return "#Inventor V2.1 ascii\nSeparator {\n"
           "  OrthographicCamera { position 0 0 5 height 2.5 nearDistance 1 farDistance 9 }\n"
           "  VolumeSeries { timeGenerator MOVING_SPHERE dimensions 32 32 32 "
           "spacing 0.0625 0.0625 0.0625 timeSteps 0 2 prefetch 1 step " +
           std::to_string(step) +
           " }\n"
           "  TransferFunction { alpha [ 0 0, 0.05 0, 1 1 ] }\n"
           "  Volume { }\n}\n";
}

} // namespace

TEST_CASE("a staged texture upload renders the same image as a direct one, bit for bit") {
    // Whole volume in one texture, and bricked (the slicer's texture-size hook: 32^3 in 12^3
    // textures), so the staged buffer's per-brick offsets are exercised too.
    for (const int limit : {0, 12}) {
        CAPTURE(limit);
        RenderOptions options = smallOptions();
        options.debug.max3DTextureSize = limit;
        OSMesaContext context;
        Renderer renderer;
        const ref_ptr<Node> root = readSceneFromString(textureSeriesScene(0));
        auto* series = findNode<VolumeSeries>(*root);
        auto* volume = findNode<Volume>(*root);
        renderer.render(*root, options); // step 0, uploaded directly
        CHECK(volume->slicingStats().stagedUploads == 0u);
        for (int step = 1; step <= 2; ++step) {
            CAPTURE(step);
            series->cache().waitUntilIdle(); // the next step's grid is prefetched
            renderer.render(*root, options); // ... and staged after this frame
            series->step = step;
            const Image staged = renderer.render(*root, options);
            const SlicingStats& stats = volume->slicingStats();
            CHECK(stats.brickUploads >= 1u);
            if (limit) CHECK(stats.bricksTotal > 1);
            CHECK(stats.stagedUploads == stats.brickUploads); // every upload came from the buffer
            // ... into the last step's textures (same layout): whole, none was allocated
            // anew; bricked, as many as the last step had non-empty bricks of each size.
            if (limit) {
                CHECK(stats.refilledTextures > 0u);
                CHECK(stats.refilledTextures <= stats.brickUploads);
            } else {
                CHECK(stats.refilledTextures == stats.brickUploads);
            }

            // The same step in a fresh renderer: its first frame uploads directly.
            Renderer freshRenderer;
            const ref_ptr<Node> freshRoot = readSceneFromString(textureSeriesScene(step));
            const Image direct = freshRenderer.render(*freshRoot, options);
            CHECK(findNode<Volume>(*freshRoot)->slicingStats().stagedUploads == 0u);
            CHECK(findNode<Volume>(*freshRoot)->slicingStats().refilledTextures == 0u);
            CHECK(findNode<Volume>(*freshRoot)->slicingStats().brickUploads == stats.brickUploads);
            CHECK(centroidX(staged) > 0.0);              // the sphere is in the image
            CHECK(maxDifference(staged, direct) == 0.0); // bit for bit
        }
    }
}
