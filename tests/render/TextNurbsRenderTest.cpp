// What Text2, Text3 and NURBS surfaces draw, against closed-form expectations: Text2's glyph
// pixels where the anchor projects (FreeType's bitmap metrics), in the material's colour, at
// the anchor's depth, moved by justification; its pick rectangle; Text3's and a trimmed
// surface's coverage.
#include <doctest/doctest.h>

#include "support/Offscreen.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <volsg/actions/PickAction.h>
#include <volsg/context/OSMesaContext.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Text2.h>
#include <volsg/render/Renderer.h>
#include <volsg/text/Font.h>
#include <volsg/text/TextLayout.h>

using namespace volsg;

namespace {

using volsg::test::Offscreen;

constexpr int kSize = 100;

/// A 100 x 100 image under an OrthographicCamera at z = 5 looking down -Z, 4 units high
/// (25 pixels per unit; the origin at window pixel (50, 50)), with `body` after it.
Image render(Offscreen& gl, const std::string& body, float height = 4.0f) {
    const auto root = readSceneFromString(
        "#Inventor V2.1 ascii\nSeparator {\n OrthographicCamera { position 0 0 5 height " +
            std::to_string(height) + " nearDistance 1 farDistance 10 }\n" + body + "\n}\n",
        "<test>");
    RenderOptions options;
    options.width = kSize;
    options.height = kSize;
    return gl.renderer.render(*root, options);
}

/// Smallest rectangle (min x, min y, max x, max y; image rows top-down) of pixels that are
/// not black, or all -1.
glm::ivec4 litRect(const Image& image) {
    glm::ivec4 r(-1);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (glm::vec3(image.at(x, y)) == glm::vec3(0.0f)) continue;
            if (r.x < 0) r = {x, y, x, y};
            r = {std::min(r.x, x), std::min(r.y, y), std::max(r.z, x), std::max(r.w, y)};
        }
    return r;
}

int litCount(const Image& image) {
    int n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (glm::vec3(image.at(x, y)) != glm::vec3(0.0f)) ++n;
    return n;
}

std::shared_ptr<FontFace> sans() {
    return FontFace::open(findFontFile("defaultFont"));
}

} // namespace

TEST_CASE("Text2 draws FreeType's glyph pixels at the projected origin in the diffuse colour") {
    Offscreen gl;
    // The origin at (-1, 0): window pixel x = 25, baseline y = 50 (rows up from the bottom).
    const Image image = render(gl, R"(
      Font { size 32 }
      Material { diffuseColor 1 0.5 0.25 emissiveColor 0 0 0 }
      Transform { translation -1 0 0 }
      Text2 { string "I" }
    )");
    const auto glyph = sans()->bitmap(U'I', 32);
    REQUIRE(glyph->width > 0);
    // GL rows [50 + top - rows, 50 + top) are image rows [50 - top, 50 - top + rows).
    const glm::ivec4 expected(25 + glyph->left, 50 - glyph->top,
                              25 + glyph->left + glyph->width - 1,
                              50 - glyph->top + glyph->rows - 1);
    const glm::ivec4 r = litRect(image);
    CAPTURE(r);
    CAPTURE(expected);
    CHECK(std::abs(r.x - expected.x) <= 1);
    CHECK(std::abs(r.z - expected.z) <= 1);
    CHECK(std::abs(r.y - expected.y) <= 1);
    CHECK(std::abs(r.w - expected.w) <= 1);
    // The lit pixels start within two pixels of the projected x and fill the capital's
    // height: DejaVu Sans' I is 0.73 em tall, 23 pixels at 32.
    CHECK(std::abs(r.x - 25) <= 3);
    CHECK(std::abs((r.w - r.y + 1) - 23) <= 1);
    CHECK(r.w == 49); // standing on the baseline
    // Fully covered texels are exactly the diffuse colour, unlit.
    int full = 0;
    for (int row = 0; row < glyph->rows; ++row)
        for (int col = 0; col < glyph->width; ++col) {
            if (glyph->coverage[std::size_t(row) * std::size_t(glyph->width) + std::size_t(col)] !=
                255)
                continue;
            const glm::vec4 c = image.at(25 + glyph->left + col, 50 - glyph->top + row);
            CHECK(glm::length(glm::vec3(c) - glm::vec3(1.0f, 0.5f, 0.25f)) < 1e-3f);
            ++full;
        }
    CHECK(full > 20);
}

TEST_CASE("Text2 justification moves the string by half or all of its advance") {
    Offscreen gl;
    const auto face = sans();
    const ScreenText layout =
        layoutScreenText(*face, std::vector<std::string>{"II"}, 20, 1.0, TextJustification::Left);
    const int width = layout.lineWidths[0];
    auto leftmost = [&](const char* justification) {
        return litRect(render(gl, std::string("Font { size 20 } Text2 { string \"II\" "
                                              "justification ") +
                                      justification + " }"))
            .x;
    };
    const int left = leftmost("LEFT"), centre = leftmost("CENTER"), right = leftmost("RIGHT");
    CAPTURE(width);
    CHECK(std::abs(left - (50 + face->bitmap(U'I', 20)->left)) <= 1);
    CHECK(std::abs(right - (left - width)) <= 1);
    CHECK(std::abs(centre - (left - width / 2)) <= 1);
}

TEST_CASE("Text2 lines go down by spacing x size pixels") {
    Offscreen gl;
    const glm::ivec4 one = litRect(render(gl, "Font { size 16 } Text2 { string \"I\" }"));
    const glm::ivec4 two =
        litRect(render(gl, "Font { size 16 } Text2 { string [ \"I\", \"I\" ] spacing 2 }"));
    CHECK(two.y == one.y);
    CHECK(two.w == one.w + 32);
}

TEST_CASE("Text2 draws nothing for an empty string, behind the camera or past the far plane") {
    Offscreen gl;
    CHECK(litCount(render(gl, "Text2 { }")) == 0);
    CHECK(litCount(render(gl, "Text2 { string [ \"\", \"\" ] }")) == 0);
    CHECK(litCount(render(gl, "Transform { translation 0 0 6 } Text2 { string \"I\" }")) == 0);
    CHECK(litCount(render(gl, "Transform { translation 0 0 -20 } Text2 { string \"I\" }")) == 0);
    CHECK(litCount(render(gl, "Font { size 0.2 } Text2 { string \"I\" }")) == 0);
    CHECK(litCount(render(gl, "Text2 { string \"I\" }")) > 0);
}

TEST_CASE("Text2 is depth tested at its origin's depth") {
    Offscreen gl;
    const std::string text = "Material { diffuseColor 1 1 1 } Font { size 40 } "
                             "Text2 { string \"I\" }";
    const std::string cube =
        "Material { diffuseColor 0 0 0 emissiveColor 0 0 1 } Cube { width 4 height 4 }";
    // A blue square in front of the text hides it; behind it, the text draws over it.
    const Image hidden =
        render(gl, "Separator { Transform { translation 0 0 2 } " + cube + " } " + text);
    const Image shown =
        render(gl, "Separator { Transform { translation 0 0 -2 } " + cube + " } " + text);
    int white = 0, whiteHidden = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (glm::vec3(shown.at(x, y)) == glm::vec3(1.0f)) ++white;
            if (glm::vec3(hidden.at(x, y)) == glm::vec3(1.0f)) ++whiteHidden;
        }
    CHECK(white > 30);
    CHECK(whiteHidden == 0);
}

TEST_CASE("a pick hits Text2 inside its glyphs' screen rectangle") {
    Offscreen gl;
    const auto root = readSceneFromString(R"(#Inventor V2.1 ascii
      Separator {
        OrthographicCamera { position 0 0 5 height 4 nearDistance 1 farDistance 10 }
        Font { size 32 }
        Transform { translation -1 0 0 }
        DEF label Text2 { string "II" }
      })",
                                          "<test>");
    const auto glyph = sans()->bitmap(U'I', 32);
    auto pick = [&](int x, int y) {
        PickAction action;
        action.setPixel(x, y, kSize, kSize);
        action.apply(*root);
        return action.picked();
    };
    // Inside the first I's bitmap, at half its height.
    const auto hit = pick(25 + glyph->left + glyph->width / 2, 50 - glyph->top / 2);
    REQUIRE(hit);
    CHECK(hit->path.back()->getName() == "label");
    CHECK(hit->normal.z == doctest::Approx(1.0));
    CHECK(
        hit->point.x ==
        doctest::Approx(-1.0 + (glyph->left + glyph->width / 2 + 0.5 - 0.0) / 25.0).epsilon(0.02));
    CHECK(!pick(25 + glyph->left + glyph->width / 2, 50 + 10)); // below the baseline
    CHECK(!pick(5, 50 - glyph->top / 2));                       // left of the text
}

TEST_CASE("Text3 covers its mesh's projected box") {
    Offscreen gl;
    const Image image = render(gl, R"(
      Material { diffuseColor 0 0 0 emissiveColor 1 1 1 }
      Font { size 2 }
      Transform { translation -1 -1 0 }
      Text3 { string "H" parts ALL }
    )");
    const auto H = sans()->outline(U'H');
    // x from -1 + 2 xMin to -1 + 2 xMax: columns (x + 2) x 25.
    const glm::ivec4 r = litRect(image);
    CHECK(std::abs(r.x - int(std::lround((1.0 + 2.0 * H->bboxMin.x) * 25.0))) <= 1);
    CHECK(std::abs(r.z + 1 - int(std::lround((1.0 + 2.0 * H->bboxMax.x) * 25.0))) <= 1);
    CHECK(std::abs(r.w + 1 - int(std::lround((2.0 - (-1.0 + 2.0 * H->bboxMin.y)) * 25.0))) <= 1);
    CHECK(std::abs(r.y - int(std::lround((2.0 - (-1.0 + 2.0 * H->bboxMax.y)) * 25.0))) <= 1);
}

TEST_CASE("a trimmed NurbsSurface covers the square minus its hole") {
    Offscreen gl;
    // The square (-2, -2) to (2, 2) under 5 units across 100 pixels: 80 x 80 pixels, the hole
    // 40 x 40.
    const Image image = render(gl, R"(
      Material { diffuseColor 0 0 0 ambientColor 0 0 0 emissiveColor 1 1 1 }
      Coordinate3 { point [ -2 -2 0, 2 -2 0, -2 2 0, 2 2 0 ] }
      ProfileCoordinate2 { point [ 0 0, 1 0, 1 1, 0 1, 0.25 0.25, 0.25 0.75, 0.75 0.75, 0.75 0.25 ] }
      LinearProfile { index [ 0, 1, 2, 3, 0 ] }
      LinearProfile { index [ 4, 5, 6, 7, 4 ] linkage START_NEW }
      NurbsSurface { numUControlPoints 2 numVControlPoints 2
                     uKnotVector [ 0, 0, 1, 1 ] vKnotVector [ 0, 0, 1, 1 ] }
    )",
                               5.0f);
    CHECK(std::abs(litCount(image) - (6400 - 1600)) <= 48);
    CHECK(glm::vec3(image.at(50, 50)) == glm::vec3(0.0f)); // the hole
    CHECK(glm::vec3(image.at(15, 50)) == glm::vec3(1.0f));
}
