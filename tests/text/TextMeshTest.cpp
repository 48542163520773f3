// Text3 and AsciiText meshes against FreeType's own outlines: the front faces have the area of
// the (flattened) outline, holes stay holes, the box is FreeType's box scaled to the Font
// size, justification and lines move the text as Coin does, sides face sideways, parts are
// respected; bad input gives one Error naming the node.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include <volsg/core/Error.h>
#include <volsg/geometry/PolygonTessellator.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/AsciiText.h>
#include <volsg/nodes/Font.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Shape.h>
#include <volsg/nodes/Text3.h>
#include <volsg/state/State.h>
#include <volsg/text/Font.h>
#include <volsg/text/TextLayout.h>

using namespace volsg;

namespace {

/// The mesh of the last shape of the scene's root Separator, with the state its other
/// children set.
const Mesh& meshOf(const ref_ptr<Node>& root) {
    State state;
    Shape* shape = nullptr;
    for (const auto& child : *root->children()) {
        if (child->isA<Shape>())
            shape = static_cast<Shape*>(child.get());
        else
            state.add(*child);
    }
    REQUIRE(shape);
    return shape->mesh(state);
}

ref_ptr<Node> read(const std::string& body) {
    return readSceneFromString("#Inventor V2.1 ascii\nSeparator {\n" + body + "\n}\n", "<test>");
}

std::shared_ptr<FontFace> dejaVuSans() {
    return FontFace::open(findFontFile("defaultFont"));
}

/// Area of the triangles whose normal points along `z` (+1 front, -1 back).
double facingArea(const Mesh& m, double z) {
    double area = 0.0;
    for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        const std::uint32_t a = m.indices[i], b = m.indices[i + 1], c = m.indices[i + 2];
        if (m.normals[a].z * z < 0.5) continue;
        const glm::dvec3 pa(m.positions[a]), pb(m.positions[b]), pc(m.positions[c]);
        const glm::dvec3 cross = glm::cross(pb - pa, pc - pa);
        CHECK(cross.z * z > 0.0); // counter-clockwise seen from the side it faces
        area += 0.5 * glm::length(cross);
    }
    return area;
}

/// The outline flattened here, independently of the library: each conic or cubic piece cut
/// into `steps` equal parameter steps (Coin's rule); the signed shoelace area of each contour.
std::vector<double> contourAreas(const GlyphOutline& outline, int steps, double scale) {
    std::vector<double> areas;
    for (const auto& c : outline.contours) {
        std::vector<glm::dvec2> poly{c.start};
        glm::dvec2 from = c.start;
        for (const auto& s : c.segments) {
            for (int i = 1; s.degree > 1 && i < steps; ++i) {
                const double t = double(i) / steps, r = 1.0 - t;
                poly.push_back(s.degree == 2 ? r * r * from + 2 * r * t * s.c1 + t * t * s.to
                                             : r * r * r * from + 3 * r * r * t * s.c1 +
                                                   3 * r * t * t * s.c2 + t * t * t * s.to);
            }
            poly.push_back(s.to);
            from = s.to;
        }
        double twice = 0.0;
        for (std::size_t i = 0; i + 1 < poly.size(); ++i)
            twice += poly[i].x * poly[i + 1].y - poly[i + 1].x * poly[i].y;
        areas.push_back(twice / 2.0 * scale * scale);
    }
    return areas;
}

Box3 bounds(const Mesh& m) {
    return m.bounds();
}

} // namespace

TEST_CASE("the front of Text3 'I' has the outline's area and FreeType's box, scaled to the size") {
    const auto face = dejaVuSans();
    const auto outline = face->outline(U'I');
    REQUIRE(outline->contours.size() == 1);
    const double size = 10.0;
    const std::vector<double> areas = contourAreas(*outline, 8, size);
    const auto root = read("Font { size 10 } Text3 { string \"I\" }");
    const Mesh& m = meshOf(root);
    REQUIRE(!m.indices.empty());
    CHECK(facingArea(m, 1.0) == doctest::Approx(std::abs(areas[0])).epsilon(1e-6));
    const Box3 box = bounds(m);
    CHECK(box.min.x == doctest::Approx(outline->bboxMin.x * size).epsilon(1e-6));
    CHECK(box.max.x == doctest::Approx(outline->bboxMax.x * size).epsilon(1e-6));
    CHECK(box.min.y == doctest::Approx(outline->bboxMin.y * size).epsilon(1e-6));
    CHECK(box.max.y == doctest::Approx(outline->bboxMax.y * size).epsilon(1e-6));
    CHECK(box.min.z == 0.0);
    CHECK(box.max.z == 0.0);
    // DejaVu Sans' capital I is 0.729 em tall on the baseline.
    CHECK(box.max.y == doctest::Approx(7.29).epsilon(1e-3));
    for (const auto& n : m.normals)
        CHECK(glm::dvec3(n) == glm::dvec3(0, 0, 1));
}

TEST_CASE("holes stay holes: the area of Text3 'O' is its outer contour's minus its inner") {
    const auto face = dejaVuSans();
    const auto outline = face->outline(U'O');
    REQUIRE(outline->contours.size() == 2);
    for (const char* complexity : {"0", "0.5", "1"}) {
        CAPTURE(complexity);
        const int steps = std::max(1, int(16.0f * std::stof(complexity)));
        const std::vector<double> areas = contourAreas(*outline, steps, 4.0);
        const double outer = std::max(std::abs(areas[0]), std::abs(areas[1]));
        const double inner = std::min(std::abs(areas[0]), std::abs(areas[1]));
        CHECK(areas[0] * areas[1] < 0.0); // opposite orientations
        const auto root = read("Complexity { value " + std::string(complexity) +
                               " } Font { size 4 } Text3 { string \"O\" }");
        const double front = facingArea(meshOf(root), 1.0);
        CHECK(front == doctest::Approx(outer - inner).epsilon(1e-6));
        CHECK(front < 0.9 * outer);
    }
    SUBCASE("and so do 'B', 'e', '8' and '@'") {
        for (const char32_t c : {U'B', U'e', U'8', U'@'}) {
            const auto glyph = face->outline(c);
            double expected = 0.0;
            for (const double a : contourAreas(*glyph, 8, 1.0))
                expected += a;
            std::string s;
            s += char(c);
            CAPTURE(s);
            const auto root = read("Font { size 1 } Text3 { string \"" + s + "\" }");
            CHECK(facingArea(meshOf(root), 1.0) ==
                  doctest::Approx(std::abs(expected)).epsilon(1e-6));
        }
    }
}

TEST_CASE("Text3 parts: FRONT at z = 0, BACK at z = -1 facing -z, SIDES facing sideways") {
    SUBCASE("each part alone") {
        const Mesh front = meshOf(read("Text3 { string \"H\" parts FRONT }"));
        for (const auto& p : front.positions)
            CHECK(p.z == 0.0f);
        const Mesh back = meshOf(read("Text3 { string \"H\" parts BACK }"));
        REQUIRE(!back.indices.empty());
        for (const auto& p : back.positions)
            CHECK(p.z == -1.0f);
        CHECK(facingArea(back, -1.0) == doctest::Approx(facingArea(front, 1.0)));
        CHECK(facingArea(back, 1.0) == 0.0);
        const Mesh sides = meshOf(read("Text3 { string \"O\" parts SIDES }"));
        REQUIRE(!sides.indices.empty());
        for (const auto& n : sides.normals) {
            CHECK(std::abs(n.z) < 1e-6);
            CHECK(std::abs(glm::length(glm::dvec3(n)) - 1.0) < 1e-5);
        }
        for (const auto& p : sides.positions)
            CHECK((p.z == 0.0f || p.z == -1.0f));
    }
    SUBCASE("sides face away from the glyph: outward normals on the outer contour of 'O'") {
        const Mesh sides = meshOf(read("Font { size 10 } Text3 { string \"O\" parts SIDES }"));
        const Box3 box = bounds(sides);
        const glm::dvec2 centre(box.center());
        int outward = 0, inward = 0;
        for (std::size_t i = 0; i < sides.positions.size(); ++i) {
            const glm::dvec2 p(sides.positions[i]), n(sides.normals[i]);
            const double r = glm::length(p - centre);
            if (r > 0.9 * (box.max.x - centre.x)) // the outer contour
                (glm::dot(n, p - centre) > 0.0 ? outward : inward)++;
        }
        CHECK(outward > 0);
        CHECK(inward == 0);
    }
    SUBCASE("ALL: the three parts, in one mesh") {
        const Mesh all = meshOf(read("Text3 { string \"A\" parts ALL }"));
        const Mesh front = meshOf(read("Text3 { string \"A\" parts FRONT }"));
        const Mesh sides = meshOf(read("Text3 { string \"A\" parts SIDES }"));
        CHECK(all.positions.size() == 2 * front.positions.size() + sides.positions.size());
        CHECK(bounds(all).min.z == -1.0);
        CHECK(bounds(all).max.z == 0.0);
    }
    SUBCASE("no parts, no text, an empty string: nothing") {
        CHECK(meshOf(read("Text3 { string \"A\" parts () }")).indices.empty());
        CHECK(meshOf(read("Text3 { }")).indices.empty());
        CHECK(meshOf(read("Text3 { string [ \"\", \" \" ] parts ALL }")).indices.empty());
    }
}

TEST_CASE("Text3 justification and lines place the text as Coin does") {
    const auto face = dejaVuSans();
    const auto outline = face->outline(U'I');
    const double size = 10.0, width = outline->advance * size;
    const Box3 left = bounds(meshOf(read("Font { size 10 } Text3 { string \"I\" }")));
    const Box3 right =
        bounds(meshOf(read("Font { size 10 } Text3 { string \"I\" justification RIGHT }")));
    const Box3 centre =
        bounds(meshOf(read("Font { size 10 } Text3 { string \"I\" justification CENTER }")));
    CHECK(right.min.x == doctest::Approx(left.min.x - width).epsilon(1e-6));
    CHECK(centre.min.x == doctest::Approx(left.min.x - width / 2).epsilon(1e-6));
    CHECK(right.min.y == left.min.y);
    // A second line: spacing x size further down.
    const Box3 two =
        bounds(meshOf(read("Font { size 10 } Text3 { string [ \"I\", \"I\" ] spacing 1.5 }")));
    CHECK(two.min.y == doctest::Approx(left.min.y - 15.0).epsilon(1e-6));
    CHECK(two.max.y == doctest::Approx(left.max.y).epsilon(1e-6));
    // Advances and kerning: "II" is one advance wider than "I".
    const Box3 pair = bounds(meshOf(read("Font { size 10 } Text3 { string \"II\" }")));
    CHECK(pair.max.x ==
          doctest::Approx(left.max.x + width + face->kerning(U'I', U'I') * size).epsilon(1e-6));
}

TEST_CASE("Text3 with a profile: the back at the profile's depth, the sides bevelled out") {
    // The SGI sample's bevel (simple/text3.iv): out by 0.05 at depth 0.05, back at 0.3.
    const auto root = read(R"(
      Font { size 1 }
      ProfileCoordinate2 { point [ 0 0, 0.05 0.05, 0.25 0.05, 0.3 0 ] }
      LinearProfile { index [ 0, 1, 2, 3 ] }
      Text3 { string "I" parts ALL }
    )");
    const Mesh& m = meshOf(root);
    const auto outline = dejaVuSans()->outline(U'I');
    const Box3 box = bounds(m);
    CHECK(box.min.z == doctest::Approx(-0.3));
    CHECK(box.max.z == doctest::Approx(0.0));
    // 'I' is a rectangle: its corners move out diagonally, its sides by exactly 0.05.
    CHECK(box.max.x == doctest::Approx(outline->bboxMax.x + 0.05).epsilon(1e-5));
    CHECK(box.min.y == doctest::Approx(outline->bboxMin.y - 0.05).epsilon(1e-5));
    // The bevel faces out and forward; the middle band straight out.
    int forward = 0, out = 0;
    for (std::size_t i = 0; i < m.normals.size(); ++i) {
        const glm::vec3 n = m.normals[i];
        const float side = std::hypot(n.x, n.y);
        if (std::abs(n.z - std::sqrt(0.5f)) < 1e-4f && std::abs(side - std::sqrt(0.5f)) < 1e-4f)
            ++forward; // the 45 degree bevel between z = 0 and -0.05
        if (std::abs(n.z) < 1e-6f && m.positions[i].z <= -0.05f && m.positions[i].z >= -0.25f)
            ++out;
    }
    CHECK(forward > 0);
    CHECK(out > 0);
}

TEST_CASE("per-part materials colour the front, sides and back of Text3") {
    const auto root = read(R"(
      MaterialBinding { value PER_PART }
      Material { diffuseColor [ 1 0 0, 0 1 0, 0 0 1 ] }
      Text3 { string "L" parts ALL }
    )");
    const Mesh& m = meshOf(root);
    REQUIRE(m.colors.size() == m.positions.size());
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const glm::vec4 expected = m.normals[i].z > 0.5f    ? glm::vec4(1, 0, 0, 1)
                                   : m.normals[i].z < -0.5f ? glm::vec4(0, 0, 1, 1)
                                                            : glm::vec4(0, 1, 0, 1);
        CHECK(m.colors[i] == expected);
    }
}

TEST_CASE("AsciiText is the flat front of Text3, width stretches the pen positions") {
    const Mesh text3 = meshOf(read("Font { size 3 } Text3 { string \"Ab\" parts ALL }"));
    const Mesh ascii = meshOf(read("Font { size 3 } AsciiText { string \"Ab\" }"));
    CHECK(facingArea(ascii, 1.0) == doctest::Approx(facingArea(text3, 1.0)));
    CHECK(facingArea(ascii, -1.0) == 0.0);
    for (const auto& p : ascii.positions)
        CHECK(p.z == 0.0f);
    // "II" stretched to 20 units: the second I starts where the stretched pen puts it.
    const auto face = dejaVuSans();
    const auto I = face->outline(U'I');
    const double natural = 2 * I->advance + face->kerning(U'I', U'I');
    const Box3 stretched = bounds(meshOf(read("AsciiText { string \"II\" width 20 }")));
    const double stretch = 20.0 / (natural * 10.0);
    CHECK(stretched.max.x ==
          doctest::Approx((I->advance + face->kerning(U'I', U'I')) * 10.0 * stretch +
                          I->bboxMax.x * 10.0)
              .epsilon(1e-6));
    // RIGHT aligns the stretched width on the origin.
    const Box3 right =
        bounds(meshOf(read("AsciiText { string \"II\" width 20 justification RIGHT }")));
    CHECK(right.min.x == doctest::Approx(stretched.min.x - 20.0).epsilon(1e-6));
}

TEST_CASE("font names map to DejaVu faces") {
    CHECK(findFontFile("defaultFont").path.find("DejaVuSans.ttf") != std::string::npos);
    CHECK(findFontFile("Helvetica").path.find("DejaVuSans.ttf") != std::string::npos);
    CHECK(findFontFile("Times-Roman").path.find("DejaVuSerif.ttf") != std::string::npos);
    CHECK(findFontFile("Courier").path.find("DejaVuSansMono.ttf") != std::string::npos);
    CHECK(findFontFile("Courier-Bold").path.find("DejaVuSansMono-Bold.ttf") != std::string::npos);
    CHECK(findFontFile("Helvetica-Bold").path.find("DejaVuSans-Bold.ttf") != std::string::npos);
    CHECK(findFontFile("Times-Bold").path.find("DejaVuSerif-Bold.ttf") != std::string::npos);
    const FontFile italic = findFontFile("Times-Italic");
    CHECK((italic.path.find("DejaVuSerif-Italic.ttf") != std::string::npos ||
           (italic.path.find("DejaVuSerif.ttf") != std::string::npos && italic.synthesizeOblique)));
    CHECK(findFontFile("Some Font Nobody Has").path.find("DejaVuSans.ttf") != std::string::npos);
    // Only the core package's faces in a folder: italics are slanted from the upright face.
    const std::string folder = std::filesystem::path(findFontFile("Sans").path).parent_path();
    const std::vector<std::string> folders{folder};
    const FontFile oblique = findFontFile("Helvetica-Oblique", folders);
    CHECK(!oblique.path.empty());
    // Slanted outlines lean right: the top of 'I' is further right than its bottom.
    const auto upright = FontFace::open(FontFile{findFontFile("Helvetica").path, false});
    const auto slanted = FontFace::open(FontFile{findFontFile("Helvetica").path, true});
    CHECK(slanted->outline(U'I')->bboxMax.x > upright->outline(U'I')->bboxMax.x + 0.1);
    CHECK(slanted->outline(U'I')->advance == upright->outline(U'I')->advance);
}

TEST_CASE("a missing font file is one Error naming the font and the folders") {
    const std::vector<std::string> nowhere{"/nonexistent-fonts"};
    try {
        findFontFile("Times-Bold", nowhere);
        FAIL("no error");
    } catch (const Error& e) {
        const std::string what = e.what();
        CHECK(what.find("font 'Times-Bold'") != std::string::npos);
        CHECK(what.find("DejaVuSerif-Bold.ttf") != std::string::npos);
        CHECK(what.find("/nonexistent-fonts") != std::string::npos);
        CHECK(what.find("fonts-dejavu-core") != std::string::npos);
        CHECK(what.find('\n') == std::string::npos);
    }
}

TEST_CASE("bad text input: one Error naming the node") {
    auto root = Separator::create();
    auto font = Font::create();
    auto text = Text3::create();
    text->setName("title");
    text->string.setValues({"Hello"});
    root->addChild(font);
    root->addChild(text);
    font->size = std::numeric_limits<float>::quiet_NaN();
    CHECK_THROWS_WITH_AS(meshOf(root),
                         doctest::Contains("Text3 'title': the Font size is not a finite number"),
                         Error);
    font->size = 1e30f;
    CHECK_THROWS_WITH_AS(meshOf(root), doctest::Contains("Text3 'title': font size"), Error);
    font->size = 10.0f;
    text->string.setValues({std::string(std::size_t(2) << 20, 'x')});
    CHECK_THROWS_WITH_AS(meshOf(root), doctest::Contains("exceeds the limit"), Error);
    // Many lines of a glyph that is cheap alone: the vertex total is checked before building.
    text->string.setValues(std::vector<std::string>(4000, std::string(250, '@')));
    text->parts.setValue(Text3::ALL);
    CHECK_THROWS_WITH_AS(meshOf(root), doctest::Contains("vertices"), Error);
    // A zero or negative size draws nothing.
    text->string.setValues({"Hello"});
    font->size = 0.0f;
    CHECK(meshOf(root).indices.empty());
    font->size = -3.0f;
    CHECK(meshOf(root).indices.empty());
    // Malformed UTF-8 becomes U+FFFD (DejaVu has it), not a crash.
    font->size = 10.0f;
    text->string.setValues({"a\xff\xfe\xc3"});
    CHECK(!meshOf(root).indices.empty());
    CHECK(decodeUtf8("a\xff\xc3\xa9\xe2\x82") ==
          std::u32string{U'a', 0xFFFD, U'é', 0xFFFD, 0xFFFD});
}
