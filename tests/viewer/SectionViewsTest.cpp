// The viewer's section views: their cameras frame the volume as the geometry says, a pixel of a
// section view maps to the voxel on its plane and back, the cursor moves every plane on the
// volume, and the three views share one copy of the data and tables in the renderer.
#include <doctest/doctest.h>

#include "support/Offscreen.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <volsg/context/OSMesaContext.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/OrthoSlice.h>
#include <volsg/nodes/Transform.h>
#include <volsg/render/Renderer.h>

#include "view/SectionViews.h"

using namespace volsg;

namespace {

/// A 32 x 16 x 8 ramp (0 .. 65535 along x) with cells 0.5 x 1 x 2 (extent 16 x 16 x 16), moved by
/// (1, 2, 3), with a scene OrthoSlice along y and one along z.
const char* kScene = R"(#Inventor V2.1 ascii
Separator {
  OrthographicCamera { position 0 0 40 height 20 nearDistance 1 farDistance 80 focalDistance 40 }
  Transform { translation 1 2 3 }
  VolumeData { generator RAMP16 dimensions 32 16 8 spacing 0.5 1 2 }
  TransferFunction { dataRange 0 65535 red [ 0 0, 1 1 ] green [ 0 0, 1 1 ] blue [ 0 0, 1 1 ]
                     alpha [ 0 1, 1 1 ] }
  DEF sliceY OrthoSlice { axis Y sliceNumber 2 }
  DEF sliceZ OrthoSlice { axis Z sliceNumber 1 }
}
)";

using volsg::test::Offscreen;

} // namespace

TEST_CASE("a section view pixel maps to the voxel on its plane and back") {
    auto root = readSceneFromString(kScene);
    SectionViews views;
    REQUIRE(views.attach(*root));
    CHECK(views.grid().dimensions() == glm::ivec3(32, 16, 8));
    // The cursor starts in the middle, and on the scene's slices along their axes (y 2, z 1):
    // attaching moves no plane of the scene.
    CHECK(views.cursor() == glm::ivec3(16, 2, 1));
    REQUIRE(views.sceneSlices().size() == 2);
    CHECK(views.sceneSlices()[0]->sliceNumber() == 2);
    // Axial (along z) at 200 x 100: the 16 x 16 box is limited by its height, 1.06 * 16 high,
    // so a pixel is 16.96 / 100 world units; radiological: x (to the patient's right) runs
    // left on the screen, y (anterior) up, centred on the box's centre.
    const double unit = 1.06 * 16.0 / 100.0;
    for (const glm::dvec2 pixel :
         {glm::dvec2(100.0, 50.0), glm::dvec2(60.5, 20.25), glm::dvec2(140.0, 93.0)}) {
        CAPTURE(pixel.x);
        const double x = (100.0 - pixel.x) * unit, y = (50.0 - pixel.y) * unit; // local
        const glm::ivec3 expected(int(std::floor((x + 8.0) / 0.5)), int(std::floor(y + 8.0)), 1);
        const auto voxel = views.voxelAtPixel(SectionViews::Axial, pixel, 200, 100);
        REQUIRE(voxel);
        CHECK(*voxel == expected);
        // Back: the voxel's centre shows within half a cell of the pixel.
        const glm::dvec2 back = views.pixelOf(SectionViews::Axial, views.worldOf(*voxel), 200, 100);
        CHECK(std::abs(back.x - pixel.x) <= 0.25 / unit + 1e-6);
        CHECK(std::abs(back.y - pixel.y) <= 0.5 / unit + 1e-6);
    }
    // Outside the box (the margin at the left of the wide view): no voxel.
    CHECK_FALSE(views.voxelAtPixel(SectionViews::Axial, {10.0, 50.0}, 200, 100));
    // Sagittal (along x, seen from the patient's left): y (anterior) runs left, z up; the plane
    // is the cursor's x.
    const auto sagittal = views.voxelAtPixel(SectionViews::Sagittal, {80.0, 10.0}, 100, 100);
    REQUIRE(sagittal);
    CHECK(sagittal->x == 16);
    CHECK(sagittal->y == int(std::floor((50.0 - 80.0) * unit + 8.0)));
    CHECK(sagittal->z == int(std::floor(((50.0 - 10.0) * unit + 8.0) / 2.0)));
    // World coordinates include the volume's transform.
    const glm::dvec3 centre = views.worldOf({0, 0, 0});
    CHECK(glm::length(centre - glm::dvec3(1.0 - 8.0 + 0.25, 2.0 - 8.0 + 0.5, 3.0 - 8.0 + 1.0)) <
          1e-9);
    CHECK(views.voxelAtWorld(centre) == glm::ivec3(0));
}

TEST_CASE("moving the cursor moves the section planes and the scene's slices on the volume") {
    auto root = readSceneFromString(kScene);
    SectionViews views;
    REQUIRE(views.attach(*root));
    REQUIRE(views.sceneSlices().size() == 2);
    views.setCursor({3, 11, 6});
    auto* sliceY = views.sceneSlices()[0].get();
    auto* sliceZ = views.sceneSlices()[1].get();
    CHECK(sliceY->sliceNumber() == 11);
    CHECK(sliceZ->sliceNumber() == 6);
    views.setCursor({-4, 99, 7}); // clamped to the grid
    CHECK(views.cursor() == glm::ivec3(0, 15, 7));
    CHECK(sliceY->sliceNumber() == 15);
    // Moving the volume moves the views with it (update follows the scene's edits).
    auto* transform = static_cast<Transform*>(root->children()->at(1).get());
    transform->translation = glm::vec3(-1.0f, 2.0f, 3.0f);
    const glm::dvec3 before = views.worldOf({0, 0, 0});
    REQUIRE(views.update(*root));
    CHECK(glm::length(views.worldOf({0, 0, 0}) - before - glm::dvec3(-2.0, 0.0, 0.0)) < 1e-6);
    CHECK(views.cursor() == glm::ivec3(0, 15, 7)); // the same volume: the cursor stays
}

TEST_CASE("the three section views share one data texture and one table in the renderer") {
    Offscreen gl;
    auto root = readSceneFromString(kScene);
    SectionViews views;
    REQUIRE(views.attach(*root));
    RenderOptions o;
    o.width = 64;
    o.height = 64;
    // Separators' render caches are per Separator (each view's graph has its own); the GPU
    // entries counted here are the programs and the volume's data and tables.
    o.debug.renderCaching = false;
    auto renderSections = [&](int count, bool withScene) {
        gl.renderer.beginViewGroup();
        if (withScene) {
            o.camera = nullptr;
            gl.renderer.render(*root, o);
        }
        for (int s = 0; s < count; ++s) {
            o.camera = views.camera(s, 1.0);
            gl.renderer.render(views.graph(s), o);
        }
        gl.renderer.endViewGroup();
        return gl.renderer.stats().cachedEntries;
    };
    const std::size_t one = renderSections(1, false);
    CHECK(one >= 2); // the slice program and the volume's data, at least
    // Three views: the same GPU entries (keyed by the USE'd nodes); with the scene's own slices
    // in the same group, still nothing more.
    CHECK(renderSections(3, false) == one);
    CHECK(renderSections(3, true) == one);
}

TEST_CASE("a section view shows the volume's box where its camera puts it") {
    Offscreen gl;
    auto root = readSceneFromString(kScene);
    SectionViews views;
    REQUIRE(views.attach(*root));
    RenderOptions o;
    o.width = 100;
    o.height = 50;
    o.background = glm::vec3(1.0f, 0.0f, 1.0f); // magenta: no ramp grey looks like it
    o.camera = views.camera(SectionViews::Coronal, 2.0);
    const Image image = gl.renderer.render(views.graph(SectionViews::Coronal), o);
    // Coronal: x left (radiological), z up; the 16 x 16 box is 16 / (1.06 * 16) of the height.
    const double half = 0.5 * 50.0 / 1.06;
    int wrong = 0;
    for (int y = 0; y < 50; ++y)
        for (int x = 0; x < 100; ++x) {
            const double dx = std::abs(x + 0.5 - 50.0), dy = std::abs(y + 0.5 - 25.0);
            const glm::vec4 c = image.at(x, y);
            const bool magenta = c.r > 0.99f && c.g < 0.01f && c.b > 0.99f;
            if (dx < half - 1.0 && dy < half - 1.0 && magenta) ++wrong;    // inside: the slice
            if ((dx > half + 1.0 || dy > half + 1.0) && !magenta) ++wrong; // outside: nothing
        }
    CHECK(wrong == 0);
    // Grey rises with x (the ramp, towards the patient's right): the screen's left is brighter.
    CHECK(image.at(35, 25).r > image.at(65, 25).r);
}

namespace {

/// Mean red of a rectangle of an image.
double meanRed(const Image& image, int x0, int y0, int x1, int y1) {
    double sum = 0.0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            sum += image.at(x, y).r;
    return sum / double((x1 - x0) * (y1 - y0));
}

} // namespace

TEST_CASE("section views are head up, radiological (patient's left on the right), and flip") {
    // A 16^3 volume asymmetric along every axis: + 40 on the patient's left (x < 8), + 80
    // anterior (y >= 8), + 120 superior (z >= 8), so each quadrant of a view has its own grey.
    // Stored as the viewer's convention says (z inferior to superior), or head first (z
    // reversed, as VTK's headsq) with the patient axes saying so.
    for (const bool headFirst : {false, true}) {
        CAPTURE(headFirst);
        const std::string path = (std::filesystem::temp_directory_path() /
                                  ("volsg-sections-" + std::to_string(getpid()) + ".raw"))
                                     .string();
        {
            std::ofstream out(path, std::ios::binary);
            for (int z = 0; z < 16; ++z)
                for (int y = 0; y < 16; ++y)
                    for (int x = 0; x < 16; ++x)
                        out.put(char(10 + 40 * (x < 8) + 80 * (y >= 8) +
                                     120 * ((headFirst ? 15 - z : z) >= 8)));
        }
        Offscreen gl;
        RenderOptions o;
        o.width = 64;
        o.height = 64;
        auto root =
            readSceneFromString("#Inventor V2.1 ascii\n"
                                "Separator {\n"
                                "  VolumeData { fileName \"" +
                                path +
                                "\" dimensions 16 16 16 }\n"
                                "  TransferFunction { dataRange 0 255 alpha [ 0 1, 1 1 ] }\n"
                                "  OrthoSlice { }\n"
                                "}\n");
        SectionViews views;
        REQUIRE(views.attach(*root));
        // Every plane through the patient's left, posterior, inferior (or superior, head first:
        // each plane's content is the same either way).
        views.setCursor({5, 5, 5});
        if (headFirst) {
            // Unknown to the views, a head-first volume comes out feet up...
            o.camera = views.camera(SectionViews::Coronal, 1.0);
            const Image wrong = gl.renderer.render(views.graph(SectionViews::Coronal), o);
            CHECK(meanRed(wrong, 8, 8, 56, 28) < meanRed(wrong, 8, 36, 56, 56));
            // ... and head up once its axes are known.
            views.setPatientAxes(PatientAxes{{1.0, 1.0, -1.0}});
        }
        auto render = [&](int section) {
            o.camera = views.camera(section, 1.0);
            return gl.renderer.render(views.graph(section), o);
        };
        // The quadrants' greys (the box fills 64 / 1.06 pixels, centred): top/bottom and
        // screen-left/screen-right halves, sampled away from the middle and the margin.
        struct Halves {
            double top, bottom, left, right;
        };
        auto halves = [&](const Image& image) {
            return Halves{meanRed(image, 8, 8, 56, 28), meanRed(image, 8, 36, 56, 56),
                          meanRed(image, 8, 8, 28, 56), meanRed(image, 36, 8, 56, 56)};
        };
        const double superior = 120.0 / 255.0, anterior = 80.0 / 255.0, left = 40.0 / 255.0;
        for (const bool flipped : {false, true}) {
            CAPTURE(flipped);
            views.setFlipped(flipped);
            const double side = flipped ? -1.0 : 1.0; // radiological: + on the screen's right
            const Halves coronal = halves(render(SectionViews::Coronal));
            CHECK(coronal.top - coronal.bottom ==
                  doctest::Approx(superior).epsilon(0.02)); // head up
            CHECK(coronal.right - coronal.left == doctest::Approx(side * left).epsilon(0.02));
            const Halves sagittal = halves(render(SectionViews::Sagittal));
            CHECK(sagittal.top - sagittal.bottom == doctest::Approx(superior).epsilon(0.02));
            // Radiological sagittal: anterior on the screen's left.
            CHECK(sagittal.left - sagittal.right == doctest::Approx(side * anterior).epsilon(0.02));
            const Halves axial = halves(render(SectionViews::Axial));
            CHECK(axial.top - axial.bottom ==
                  doctest::Approx(anterior).epsilon(0.02)); // anterior up
            CHECK(axial.right - axial.left == doctest::Approx(side * left).epsilon(0.02));
            // Pixels and voxels agree with the picture: the top-right pixel of the coronal view is
            // superior, and on the patient's left when radiological.
            const auto voxel = views.voxelAtPixel(SectionViews::Coronal, {50.0, 10.0}, 64, 64);
            REQUIRE(voxel);
            CHECK((voxel->z >= 8) == !headFirst);
            CHECK((voxel->x < 8) == !flipped);
        }
        std::filesystem::remove(path);
    }
}
