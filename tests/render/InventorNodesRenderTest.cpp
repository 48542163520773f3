// The Inventor transform, grouping, kit and file nodes drawn, against closed-form pixel
// expectations. Every scene looks down -Z through an OrthographicCamera 5 units high into a
// 100 x 100 image: 20 pixels per unit, x = -2.5 at the left edge, y = 2.5 at the top. Edges at
// multiples of 0.05 units fall on pixel boundaries, so the covered rectangles are exact
// (tolerance 0 pixels); colours come from emissive materials (black diffuse and ambient), so
// they are exact too.
#include <doctest/doctest.h>

#include "support/Offscreen.h"

#include <volsg/context/OSMesaContext.h>
#include <volsg/core/Error.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/BuiltinNodes.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/Separator.h>
#include <volsg/render/Renderer.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace volsg;

namespace {

using volsg::test::Offscreen;

constexpr int kSize = 100;
constexpr double kPixelsPerUnit = 20.0;

const char* const kCamera =
    "OrthographicCamera { position 0 0 5 height 5 nearDistance 1 farDistance 20 }\n";

std::string emissive(const char* rgb) {
    return std::string("Material { diffuseColor 0 0 0 ambientColor 0 0 0 emissiveColor ") + rgb +
           " }\n";
}

Image render(Offscreen& gl, Node& root) {
    RenderOptions options;
    options.width = kSize;
    options.height = kSize;
    return gl.renderer.render(root, options);
}

Image renderText(Offscreen& gl, const std::string& body, const std::string& fileName = "<string>") {
    ref_ptr<Node> root =
        readSceneFromString("#Inventor V2.1 ascii\nSeparator {\n" + body + "}\n", fileName);
    return render(gl, *root);
}

/// Covered pixels (not the black background): min x, min y, max x, max y; -1s when none.
glm::ivec4 coveredRect(const Image& image) {
    glm::ivec4 r(-1);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (glm::vec3(image.at(x, y)) == glm::vec3(0.0f)) continue;
            if (r.x < 0) r = {x, y, x, y};
            r = {std::min(r.x, x), std::min(r.y, y), std::max(r.z, x), std::max(r.w, y)};
        }
    return r;
}

/// The pixels an axis-aligned world rectangle [x0, x1] x [y0, y1] covers (edges on pixel
/// boundaries).
glm::ivec4 expectedRect(double x0, double y0, double x1, double y1) {
    const auto column = [](double x) { return int(std::lround((x + 2.5) * kPixelsPerUnit)); };
    const auto row = [](double y) { return int(std::lround((2.5 - y) * kPixelsPerUnit)); };
    return {column(x0), row(y1), column(x1) - 1, row(y0) - 1};
}

/// The colour at world (x, y).
glm::vec3 colorAt(const Image& image, double x, double y) {
    const int column = int(std::floor((x + 2.5) * kPixelsPerUnit));
    const int row = int(std::floor((2.5 - y) * kPixelsPerUnit));
    return glm::vec3(image.at(column, row));
}

/// Runs of covered columns along the image row through world y.
std::vector<glm::ivec2> coveredRuns(const Image& image, double y) {
    const int row = int(std::floor((2.5 - y) * kPixelsPerUnit));
    std::vector<glm::ivec2> runs;
    for (int x = 0; x < image.width; ++x) {
        if (glm::vec3(image.at(x, row)) == glm::vec3(0.0f)) continue;
        if (!runs.empty() && runs.back().y == x - 1)
            runs.back().y = x;
        else
            runs.push_back({x, x});
    }
    return runs;
}

bool sameImage(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.pixels == b.pixels;
}

const glm::vec3 kRed(1, 0, 0), kGreen(0, 1, 0);

std::filesystem::path freshFolder(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("volsg-inventor-render-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

void writeText(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

} // namespace

TEST_CASE("Translation moves a cube's silhouette by translation x 20 pixels") {
    Offscreen gl;
    const std::string cube = emissive("1 0 0") + "Cube { width 1 height 1 depth 1 }\n";
    const Image still = renderText(gl, kCamera + cube);
    const Image moved =
        renderText(gl, kCamera + std::string("Translation { translation 0.5 -0.75 0 }\n") + cube);
    CHECK(coveredRect(still) == expectedRect(-0.5, -0.5, 0.5, 0.5));
    // 0.5 units right = 10 pixels, 0.75 down = 15 pixels.
    CHECK(coveredRect(moved) == expectedRect(0.0, -1.25, 1.0, -0.25));
    CHECK(coveredRect(moved) - coveredRect(still) == glm::ivec4(10, 15, 10, 15));
}

TEST_CASE("DrawStyle LINES draws a cube's and a face set's polygon edges, not their diagonals") {
    // Coin draws cubes as quads and face sets as polygons: in line mode no triangulation
    // diagonal shows. A 2 x 2 square seen straight on: its border is drawn, its centre (on the
    // diagonal of both triangles) is not.
    Offscreen gl;
    for (const std::string& shape :
         {std::string("Cube { width 2 height 2 depth 0 }\n"),
          std::string("Coordinate3 { point [ -1 -1 0, 1 -1 0, 1 1 0, -1 1 0 ] }\n"
                      "IndexedFaceSet { coordIndex [ 0, 1, 2, 3, -1 ] }\n")}) {
        CAPTURE(shape);
        const Image image =
            renderText(gl, kCamera + emissive("0 1 0") + "DrawStyle { style LINES }\n" + shape);
        // A line on a pixel boundary may fall on either side: 1 pixel of tolerance.
        const glm::ivec4 border = coveredRect(image) - expectedRect(-1.0, -1.0, 1.0, 1.0);
        CHECK(glm::all(glm::lessThanEqual(glm::abs(border), glm::ivec4(1))));
        CHECK(colorAt(image, 0.0, 0.0) == glm::vec3(0.0f));
        CHECK(colorAt(image, 0.5, 0.5) == glm::vec3(0.0f));
        CHECK(colorAt(image, -0.5, -0.5) == glm::vec3(0.0f));
    }
}

TEST_CASE("of two shapes at the same depth the later one shows, as Coin's GL_LEQUAL") {
    Offscreen gl;
    const std::string square = "Coordinate3 { point [ -1 -1 0, 1 -1 0, 1 1 0, -1 1 0 ] }\n"
                               "IndexedFaceSet { coordIndex [ 0, 1, 2, 3, -1 ] }\n";
    const Image image =
        renderText(gl, kCamera + emissive("1 0 0") + square + emissive("0 1 0") + square);
    CHECK(colorAt(image, 0.0, 0.0) == kGreen);
}

TEST_CASE("SOLID counter-clockwise faces are culled from behind in LINES style too, as in Coin") {
    Offscreen gl;
    const std::string hints = "ShapeHints { vertexOrdering COUNTERCLOCKWISE shapeType SOLID "
                              "}\nDrawStyle { style LINES }\n";
    const std::string coords = "Coordinate3 { point [ -1 -1 0, 1 -1 0, 1 1 0, -1 1 0 ] }\n";
    // Facing the camera: its edges are drawn. From behind: nothing.
    const Image front = renderText(gl, kCamera + emissive("0 1 0") + hints + coords +
                                           "IndexedFaceSet { coordIndex [ 0, 1, 2, 3, -1 ] }\n");
    const Image back = renderText(gl, kCamera + emissive("0 1 0") + hints + coords +
                                          "IndexedFaceSet { coordIndex [ 0, 3, 2, 1, -1 ] }\n");
    CHECK(coveredRect(front).x >= 0);
    CHECK(coveredRect(back).x < 0);
    // A Sphere drawn as lines (GL's line mode, no outline) loses its back half's edges: fewer
    // covered pixels than without the hints.
    const auto count = [](const Image& image) {
        int n = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                n += glm::vec3(image.at(x, y)) != glm::vec3(0.0f);
        return n;
    };
    const Image culled = renderText(gl, kCamera + emissive("0 1 0") + hints + "Sphere { }\n");
    const Image all =
        renderText(gl, kCamera + emissive("0 1 0") + "DrawStyle { style LINES }\nSphere { }\n");
    CHECK(count(culled) < count(all));
}

TEST_CASE("Rotation and RotationXYZ turn a 2 x 1 box's silhouette into 1 x 2") {
    Offscreen gl;
    const std::string box = emissive("0 1 0") + "Cube { width 2 height 1 depth 0.5 }\n";
    CHECK(coveredRect(renderText(gl, kCamera + box)) == expectedRect(-1.0, -0.5, 1.0, 0.5));
    const glm::ivec4 turned = expectedRect(-0.5, -1.0, 0.5, 1.0);
    CHECK(coveredRect(renderText(gl, kCamera +
                                         std::string("Rotation { rotation 0 0 1 "
                                                     "1.5707963 }\n") +
                                         box)) == turned);
    CHECK(coveredRect(renderText(gl, kCamera +
                                         std::string("RotationXYZ { axis Z angle "
                                                     "1.5707963 }\n") +
                                         box)) == turned);
    // About X by 90 degrees the box's depth (0.5) becomes its height; the default axis is X.
    CHECK(coveredRect(renderText(gl, kCamera + std::string("RotationXYZ { angle 1.5707963 }\n") +
                                         box)) == expectedRect(-1.0, -0.25, 1.0, 0.25));
    // About Y: its depth becomes its width.
    CHECK(coveredRect(renderText(gl, kCamera +
                                         std::string("RotationXYZ { axis Y angle "
                                                     "1.5707963 }\n") +
                                         box)) == expectedRect(-0.25, -0.5, 0.25, 0.5));
}

TEST_CASE("Scale 2 doubles a silhouette's width exactly in an orthographic view") {
    Offscreen gl;
    const std::string cube = emissive("1 1 1") + "Cube { width 1 height 1 depth 1 }\n";
    const glm::ivec4 one = coveredRect(renderText(gl, kCamera + cube));
    const glm::ivec4 two =
        coveredRect(renderText(gl, kCamera + std::string("Scale { scaleFactor 2 1 1 }\n") + cube));
    CHECK(one == expectedRect(-0.5, -0.5, 0.5, 0.5));
    CHECK(two == expectedRect(-1.0, -0.5, 1.0, 0.5));
    CHECK(two.z - two.x + 1 == 2 * (one.z - one.x + 1)); // 40 pixels for 20
    CHECK(two.w - two.y == one.w - one.y);
}

TEST_CASE("Units CENTIMETERS under METERS scales by 0.01, and the next unit by its ratio") {
    Offscreen gl;
    // 200 cm = 2 m wide, 100 cm high.
    const std::string cm = "Units { units CENTIMETERS }\n" + emissive("1 0 0") +
                           "Cube { width 200 height 100 depth 100 }\n";
    CHECK(coveredRect(renderText(gl, kCamera + std::string("Units { units METERS }\n") + cm)) ==
          expectedRect(-1.0, -0.5, 1.0, 0.5));
    CHECK(coveredRect(renderText(gl, kCamera + cm)) == expectedRect(-1.0, -0.5, 1.0, 0.5));
    // Then MILLIMETERS: the ratio to centimetres (0.1); 1000 mm = 1 m.
    CHECK(coveredRect(renderText(gl, kCamera +
                                         std::string("Units { units CENTIMETERS }\n"
                                                     "Units { units MILLIMETERS }\n") +
                                         emissive("1 0 0") +
                                         "Cube { width 1000 height 1000 depth 1000 }\n")) ==
          expectedRect(-0.5, -0.5, 0.5, 0.5));
    // A Separator ends the unit's scope: the second cube is in metres again.
    const Image scoped =
        renderText(gl, kCamera + std::string("Separator { Units { units INCHES } }\n") +
                           emissive("1 0 0") + "Cube { width 1 height 1 depth 1 }\n");
    CHECK(coveredRect(scoped) == expectedRect(-0.5, -0.5, 0.5, 0.5));
}

TEST_CASE("TransformSeparator keeps the material change after it but not the translation") {
    Offscreen gl;
    const Image image = renderText(gl, kCamera +
                                           std::string("TransformSeparator {\n"
                                                       "  Translation { translation 1 0 0 "
                                                       "}\n") +
                                           emissive("1 0 0") +
                                           "}\n"
                                           "Cube { width 1 height 1 depth 1 }\n");
    CHECK(coveredRect(image) == expectedRect(-0.5, -0.5, 0.5, 0.5));
    CHECK(colorAt(image, 0.0, 0.0) == kRed);
}

TEST_CASE("LOD draws the child for the camera's distance to its center") {
    Offscreen gl;
    const auto scene = [](double cameraZ, const char* center) {
        return "OrthographicCamera { position 0 0 " + std::to_string(cameraZ) +
               " height 5 nearDistance 0.5 farDistance 40 }\n"
               "LOD { range [ 6, 12 ] center " +
               center + "\n" + "  Separator {\n" + emissive("1 0 0") +
               "    Cube { width 1 height 1 depth 1 } }\n"
               "  Separator {\n" +
               emissive("0 1 0") + "    Cube { width 2 height 2 depth 1 } }\n}\n";
    };
    // Distance 5 < 6: the first child; 8 is in [6, 12): the second; 15 is past the last range,
    // clamped to the last child (the second).
    const Image near = renderText(gl, scene(5.0, "0 0 0"));
    CHECK(coveredRect(near) == expectedRect(-0.5, -0.5, 0.5, 0.5));
    CHECK(colorAt(near, 0.0, 0.0) == kRed);
    const Image middle = renderText(gl, scene(8.0, "0 0 0"));
    CHECK(coveredRect(middle) == expectedRect(-1.0, -1.0, 1.0, 1.0));
    CHECK(colorAt(middle, 0.0, 0.0) == kGreen);
    CHECK(colorAt(renderText(gl, scene(15.0, "0 0 0")), 0.0, 0.0) == kGreen);
    // center moves the point the distance is measured to: 5 - (-3) = 8.
    CHECK(colorAt(renderText(gl, scene(5.0, "0 0 -3")), 0.0, 0.0) == kGreen);
}

TEST_CASE("LevelOfDetail draws the child for the projected area of its children's box") {
    Offscreen gl;
    // The children's box is 2 x 2 (x, y): 40 x 40 = 1600 square pixels at 20 pixels per unit,
    // 80 x 80 = 6400 with an orthographic height of 2.5 (40 pixels per unit).
    const auto scene = [](const char* height, const char* areas) {
        return std::string("OrthographicCamera { position 0 0 5 height ") + height +
               " nearDistance 1 farDistance 20 }\n"
               "LevelOfDetail { screenArea [ " +
               areas + " ]\n" + "  Separator {\n" + emissive("1 0 0") +
               "    Cube { width 2 height 2 depth 2 } }\n"
               "  Separator {\n" +
               emissive("0 1 0") + "    Cube { width 1 height 1 depth 1 } }\n}\n";
    };
    CHECK(colorAt(renderText(gl, scene("5", "1000")), 0.0, 0.0) == kRed);   // 1600 > 1000
    CHECK(colorAt(renderText(gl, scene("5", "2000")), 0.0, 0.0) == kGreen); // 1600 < 2000
    CHECK(colorAt(renderText(gl, scene("2.5", "2000")), 0.0, 0.0) == kRed); // 6400 > 2000
    // The threshold is strict: an area equal to screenArea is not above it.
    CHECK(colorAt(renderText(gl, scene("5", "1600")), 0.0, 0.0) == kGreen);
    CHECK(colorAt(renderText(gl, scene("5", "1599")), 0.0, 0.0) == kRed);
}

TEST_CASE("Array draws its children at the computed offsets for FIRST, CENTER and LAST") {
    Offscreen gl;
    const auto scene = [](const char* fields) {
        return kCamera + std::string("Array { ") + fields + "\n" + emissive("1 1 0") +
               "  Cube { width 1 height 1 depth 1 } }\n";
    };
    // CENTER, 3 along x 1.5 apart: x = -1.5, 0, 1.5; cubes 1 wide: [-2, -1], [-0.5, 0.5],
    // [1, 2] -> columns [10, 30), [40, 60), [70, 90).
    const Image centered =
        renderText(gl, scene("origin CENTER numElements1 3 separation1 1.5 0 0"));
    CHECK(coveredRuns(centered, 0.0) == std::vector<glm::ivec2>{{10, 29}, {40, 59}, {70, 89}});
    CHECK(coveredRect(centered) == expectedRect(-2.0, -0.5, 2.0, 0.5));
    // FIRST (the default): x = 0, 1.5 (the third, at 3, is out of view); two rows 1.2 apart
    // along y.
    const Image first =
        renderText(gl, scene("numElements1 3 separation1 1.5 0 0 numElements2 2 separation2 0 "
                             "1.2 0"));
    CHECK(coveredRuns(first, 0.0) == std::vector<glm::ivec2>{{40, 59}, {70, 89}});
    CHECK(coveredRuns(first, 1.2) == std::vector<glm::ivec2>{{40, 59}, {70, 89}});
    CHECK(coveredRect(first) == expectedRect(-0.5, -0.5, 2.0, 1.7));
    // LAST: x = 0, -1.5, -3.
    const Image last = renderText(gl, scene("origin LAST numElements1 3 separation1 1.5 0 0"));
    CHECK(coveredRuns(last, 0.0) == std::vector<glm::ivec2>{{10, 29}, {40, 59}});
    CHECK(coveredRect(last) == expectedRect(-2.0, -0.5, 0.5, 0.5));
    // Each copy is separated: a Material in the children does not reach the cube after it.
    const Image separated =
        renderText(gl, kCamera + std::string("Array { numElements1 2 separation1 10 0 0\n") +
                           emissive("1 0 0") + "}\nCube { width 1 height 1 depth 1 }\n");
    CHECK(colorAt(separated, 0.0, 0.0) != kRed);
}

TEST_CASE("MultipleCopy draws its children once per matrix") {
    Offscreen gl;
    const Image image =
        renderText(gl, kCamera +
                           std::string("MultipleCopy { matrix [\n"
                                       "  1 0 0 0  0 1 0 0  0 0 1 0  -1.5 0 0 1,\n"
                                       "  2 0 0 0  0 1 0 0  0 0 1 0  1 1 0 1 ]\n") +
                           emissive("0 0 1") + "  Cube { width 1 height 1 depth 1 } }\n");
    // The first copy at x = -1.5; the second twice as wide at (1, 1).
    CHECK(coveredRuns(image, 0.0) == std::vector<glm::ivec2>{{10, 29}});
    CHECK(coveredRuns(image, 1.0) == std::vector<glm::ivec2>{{50, 89}});
    CHECK(coveredRect(image) == expectedRect(-2.0, -0.5, 2.0, 1.5));
}

TEST_CASE("Selection draws as a Separator") {
    Offscreen gl;
    const Image image = renderText(
        gl, kCamera + std::string("Selection { policy TOGGLE\n") + emissive("1 0 0") +
                "  Translation { translation -1 0 0 } Cube { width 1 height 1 depth 1 } }\n" +
                "Cube { width 1 height 1 depth 1 }\n");
    CHECK(colorAt(image, -1.0, 0.0) == kRed);
    CHECK(colorAt(image, 0.0, 0.0) != kRed); // neither the material nor the translation leaked
    CHECK(coveredRuns(image, 0.0) == std::vector<glm::ivec2>{{20, 59}});
}

TEST_CASE("Annotation draws its children after the rest of the scene, without depth test") {
    Offscreen gl;
    const auto scene = [](const char* group) {
        return kCamera + std::string(group) + " {\n" + "  Translation { translation 0 0 -3 }\n" +
               emissive("0 1 0") + "  Cube { width 1 height 1 depth 1 } }\n" + emissive("1 0 0") +
               "Cube { width 2 height 2 depth 2 }\n" +
               // A transparent square in front of everything: annotations still come after it.
               "Separator { Translation { translation 0 0 2 }\n" +
               "  Material { diffuseColor 0 0 0 ambientColor 0 0 0 emissiveColor 0 0 1 "
               "transparency 0.5 }\n" +
               "  Cube { width 4 height 0.5 depth 0.1 } }\n";
    };
    // As a Separator the green cube is behind the red one.
    const Image separator = renderText(gl, scene("Separator"));
    CHECK(colorAt(separator, 0.0, 0.5) == kRed);
    // As an Annotation it is drawn last, over the red cube and over the transparent strip.
    const Image annotation = renderText(gl, scene("Annotation"));
    CHECK(colorAt(annotation, 0.0, 0.4) == kGreen);
    CHECK(colorAt(annotation, 0.0, 0.0) == kGreen);
    CHECK(colorAt(annotation, 0.8, 0.8) == kRed);
    // The strip is a thin box: its front and back faces each blend half blue over what is
    // there (no culling, no depth writes in the transparent pass): 1/4 of it remains.
    CHECK(colorAt(annotation, -0.8, 0.0) == glm::vec3(0.25f, 0.0f, 0.75f)); // strip over red
    CHECK(colorAt(annotation, -1.5, 0.0) == glm::vec3(0.0f, 0.0f, 0.75f));  // strip over black
    // Its own state stays in it (a Separator): the red cube is red, not green.
    CHECK(coveredRect(annotation) == coveredRect(separator));
}

TEST_CASE("a File draws what it includes: the image equals the inlined scene") {
    Offscreen gl;
    const auto dir = freshFolder("file");
    const std::string part = "Separator {\n" + emissive("1 0.5 0") +
                             "  Cube { width 1 height 2 depth 1 }\n"
                             "  File { name \"deeper/more.iv\" }\n}\n";
    const std::string more =
        "Translation { translation 1 0 0 }\n" + emissive("0 0.5 1") + "Sphere { radius 0.5 }\n";
    writeText(dir / "parts" / "part.iv", "#Inventor V2.1 ascii\n" + part);
    writeText(dir / "parts" / "deeper" / "more.iv",
              "#Inventor V2.1 ascii\nSeparator {\n" + more + "}\n");
    writeText(dir / "scene.iv", std::string("#Inventor V2.1 ascii\nSeparator {\n") + kCamera +
                                    "Translation { translation -0.5 0 0 }\n"
                                    "File { name \"parts/part.iv\" }\n}\n");
    const Image included = render(gl, *readScene((dir / "scene.iv").string()));
    const Image inlined = renderText(gl, kCamera +
                                             std::string("Translation { translation -0.5 0 "
                                                         "0 }\nSeparator {\n") +
                                             emissive("1 0.5 0") +
                                             "  Cube { width 1 height 2 depth 1 }\n"
                                             "  Separator {\n" +
                                             more + "}\n}\n");
    CHECK(coveredRect(included) == expectedRect(-1.0, -1.0, 1.0, 1.0));
    CHECK(sameImage(included, inlined));
    std::filesystem::remove_all(dir);
}

TEST_CASE("a File whose file is missing makes the render an error naming the scene and line") {
    Offscreen gl;
    const auto dir = freshFolder("missing");
    writeText(dir / "scene.iv", std::string("#Inventor V2.1 ascii\nSeparator {\n") + kCamera +
                                    "File {\n  name \"nowhere.iv\" }\n}\n");
    ref_ptr<Node> root = readScene((dir / "scene.iv").string()); // reading is fine
    try {
        render(gl, *root);
        FAIL("no error");
    } catch (const Error& e) {
        const std::string what = e.what();
        // At the File's name (line 5), the position the reader gives nodes (File.h).
        CHECK(what.find((dir / "scene.iv").string() + ":5:") == 0);
        CHECK(what.find("nowhere.iv") != std::string::npos);
        CHECK(what.find('\n') == std::string::npos);
    }
    std::filesystem::remove_all(dir);
}

TEST_CASE("ShapeKit draws its shape under its transform, appearance and localTransform") {
    Offscreen gl;
    const Image image = renderText(
        gl, kCamera + std::string("ShapeKit {\n"
                                  "  appearance AppearanceKit { material Material {\n"
                                  "    diffuseColor 0 0 0 ambientColor 0 0 0 emissiveColor 1 0 0 "
                                  "} }\n"
                                  "  transform Transform { translation 1 0.5 0 }\n"
                                  "  localTransform Transform { scaleFactor 1 2 1 }\n"
                                  "  shape Cube { width 1 height 1 depth 1 }\n"
                                  "}\n"
                                  "Cube { width 0.5 height 0.5 depth 0.5 }\n"));
    // The kit's cube: 1 x 2 around (1, 0.5), red.
    CHECK(colorAt(image, 1.0, 1.2) == kRed);
    CHECK(coveredRuns(image, 1.2) == std::vector<glm::ivec2>{{60, 79}});
    // The cube after it is at the origin, not red: the kit is a separator.
    CHECK(coveredRuns(image, 0.0) == std::vector<glm::ivec2>{{45, 54}, {60, 79}});
    CHECK(colorAt(image, 0.0, 0.0) != kRed);

    // Without a shape part a ShapeKit draws a default Cube (2 x 2 x 2), as Inventor's.
    CHECK(coveredRect(renderText(gl, kCamera + std::string("ShapeKit { }\n"))) ==
          expectedRect(-1.0, -1.0, 1.0, 1.0));
}

TEST_CASE("SeparatorKit's childList holds child kits under its transform, not localTransform") {
    Offscreen gl;
    const Image image = renderText(
        gl, kCamera + std::string("SeparatorKit {\n"
                                  "  transform Transform { translation 0 1 0 }\n"
                                  "  childList NodeKitListPart {\n"
                                  "    containerTypeName \"Separator\"\n"
                                  "    childTypeNames [ \"ShapeKit\", \"SeparatorKit\" ]\n"
                                  "    containerNode Separator {\n"
                                  "      ShapeKit { shape Cube { width 1 height 1 depth 1 } }\n"
                                  "      ShapeKit {\n"
                                  "        transform Transform { translation -1.5 0 0 }\n"
                                  "        localTransform Transform { scaleFactor 2 1 1 }\n"
                                  "        childList NodeKitListPart { containerNode Separator {\n"
                                  "          ShapeKit { transform Transform { translation 0 -2 "
                                  "0 }\n"
                                  "                     shape Cube { width 0.5 height 0.5 depth "
                                  "0.5 } } } }\n"
                                  "        shape Cube { width 0.5 height 0.5 depth 0.5 } }\n"
                                  "    }\n"
                                  "  }\n"
                                  "}\n"));
    // Row y = 1: the first child at x = 0 (1 wide), the second at x = -1.5 scaled to 1 wide.
    CHECK(coveredRuns(image, 1.0) == std::vector<glm::ivec2>{{10, 29}, {40, 59}});
    // Its child kit: at (-1.5, -1), 0.5 wide (localTransform applies only to the shape).
    CHECK(coveredRuns(image, -1.0) == std::vector<glm::ivec2>{{15, 24}});
}

TEST_CASE("WrapperKit draws its contents under localTransform") {
    Offscreen gl;
    const Image image = renderText(
        gl, kCamera + std::string("WrapperKit {\n"
                                  "  transform Transform { translation 0 -1 0 }\n"
                                  "  localTransform Transform { translation -1 0 0 }\n"
                                  "  contents Separator { Cube { width 1 height 1 depth 1 } }\n"
                                  "}\n"));
    CHECK(coveredRect(image) == expectedRect(-1.5, -1.5, -0.5, -0.5));
}

TEST_CASE("LightKit places its light by its transform, the light stays in scope after it") {
    Offscreen gl;
    // The light shines along +x in its coordinates; about Y by +90 degrees that is -z, onto
    // the cube's front face (diffuse 0.8 + 0.2 x 0.2 ambient = 0.84); by -90 degrees it is +z,
    // from behind (ambient only, 0.04). The cube after the kit is not moved by its transform.
    const auto scene = [](const char* angle) {
        return kCamera +
               std::string("LightKit {\n"
                           "  transform Transform { rotation 0 1 0 ") +
               angle +
               " }\n"
               "  light DirectionalLight { direction 1 0 0 }\n"
               "}\n"
               "Cube { width 1 height 1 depth 1 }\n";
    };
    const Image lit = renderText(gl, scene("1.5707963"));
    const Image dark = renderText(gl, scene("-1.5707963"));
    CHECK(coveredRect(lit) == expectedRect(-0.5, -0.5, 0.5, 0.5));
    CHECK(colorAt(lit, 0.0, 0.0).r == doctest::Approx(0.84f).epsilon(1e-3));
    CHECK(colorAt(dark, 0.0, 0.0).r == doctest::Approx(0.04f).epsilon(1e-3));
}

TEST_CASE("CameraKit's camera sets the view, placed by its transform") {
    Offscreen gl;
    const Image image = renderText(
        gl, "CameraKit {\n"
            "  transform Transform { translation 1 0 0 }\n"
            "  camera OrthographicCamera { position 0 0 5 height 5 nearDistance 1 farDistance 20 "
            "}\n"
            "}\n" +
                emissive("1 1 1") + "Cube { width 1 height 1 depth 1 }\n");
    // The camera moved 1 to the right: the cube appears 1 unit (20 pixels) left of centre.
    CHECK(coveredRect(image) == expectedRect(-1.5, -0.5, -0.5, 0.5));
}

TEST_CASE("SceneKit draws its childList under the camera its cameraList switches on") {
    Offscreen gl;
    const Image image =
        renderText(gl, "SceneKit {\n"
                       "  cameraList NodeKitListPart { containerNode Switch { whichChild 1\n"
                       "    CameraKit { camera OrthographicCamera { position 0 0 5 height 10 } }\n"
                       "    CameraKit { camera OrthographicCamera { position 0 0 5 height 5 "
                       "nearDistance 1 farDistance 20 } } } }\n"
                       "  childList NodeKitListPart { containerNode Group {\n"
                       "    ShapeKit { shape Cube { width 1 height 1 depth 1 } } } }\n"
                       "}\n");
    CHECK(coveredRect(image) == expectedRect(-0.5, -0.5, 0.5, 0.5));
}

TEST_CASE("BaseKit and NodeKitListPart draw their parts and items") {
    Offscreen gl;
    const Image image = renderText(
        gl, kCamera + std::string("BaseKit { callbackList NodeKitListPart { containerNode "
                                  "Separator {\n"
                                  "  Translation { translation 1 0 0 } Cube { width 1 height 1 "
                                  "depth 1 } } } }\n"
                                  "NodeKitListPart { containerNode Group { Cube { width 0.5 "
                                  "height 0.5 depth 0.5 } } }\n"));
    CHECK(coveredRuns(image, 0.0) == std::vector<glm::ivec2>{{45, 54}, {60, 79}});
}

TEST_CASE("Info, Label and PickStyle change nothing in the image") {
    Offscreen gl;
    const std::string body = kCamera + emissive("1 0 0") + "Cube { width 1 height 1 depth 1 }\n";
    const Image plain = renderText(gl, body);
    const Image noted = renderText(gl, "Info { string \"a note\" }\nLabel { label \"part\" }\n"
                                       "PickStyle { style UNPICKABLE }\n" +
                                           body);
    CHECK(sameImage(plain, noted));
}

TEST_CASE("every new node type renders: at its defaults, around a cube, it changes nothing") {
    Offscreen gl;
    auto cube = Cube::create();
    cube->width = 1.0f; // 1 x 2 x 2
    const auto scene = [&cube](ref_ptr<Node> node) {
        ref_ptr<Node> root = readSceneFromString("#Inventor V2.1 ascii\nSeparator {\n" +
                                                 std::string(kCamera) + emissive("1 0 0") + "}\n");
        auto* group = static_cast<Separator*>(root.get());
        if (node) group->addChild(node);
        group->addChild(cube);
        return root;
    };
    const Image plain = render(gl, *scene(nullptr));
    CHECK(coveredRect(plain) == expectedRect(-0.5, -1.0, 0.5, 1.0));
    for (const char* name : {"Translation",
                             "Rotation",
                             "RotationXYZ",
                             "Scale",
                             "TransformSeparator",
                             "Units",
                             "LOD",
                             "LevelOfDetail",
                             "Array",
                             "MultipleCopy",
                             "Selection",
                             "File",
                             "Annotation",
                             "Info",
                             "Label",
                             "PickStyle",
                             "NodeKitListPart",
                             "BaseKit",
                             "AppearanceKit",
                             "SeparatorKit",
                             "WrapperKit",
                             "LightKit",
                             "CameraKit",
                             "SceneKit"}) {
        CAPTURE(name);
        ref_ptr<Node> node = nodeTypes().find(name)->create();
        // A group holds the same cube (drawn twice, or once more after the rest: Annotation).
        if (auto* children = node->children()) children->push_back(cube);
        CHECK(sameImage(render(gl, *scene(node)), plain));
    }
    // ShapeKit: its default 2 x 2 x 2 Cube, in the red material in scope, around the other.
    const Image kit = render(gl, *scene(nodeTypes().find("ShapeKit")->create()));
    CHECK(coveredRect(kit) == expectedRect(-1.0, -1.0, 1.0, 1.0));
    CHECK(colorAt(kit, 0.75, 0.0) == kRed);
}
