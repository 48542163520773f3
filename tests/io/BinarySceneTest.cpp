// Binary Inventor files (docs/SCENE-FORMAT.md section 1.9), built byte by byte here, read to
// the same graphs as their text.
#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <string>

#include <volsg/core/Error.h>
#include <volsg/engines/Engines.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/GraphCompare.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/io/UnknownNode.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/Texture2.h>

using namespace volsg;

namespace {

/// Bytes of a binary Inventor file.
struct Bytes {
    std::string data;
    Bytes& word(std::uint32_t v) {
        for (int s = 24; s >= 0; s -= 8)
            data += char((v >> s) & 0xFF);
        return *this;
    }
    Bytes& f(float v) {
        std::uint32_t u;
        std::memcpy(&u, &v, 4);
        return word(u);
    }
    Bytes& d(double v) {
        std::uint64_t u;
        std::memcpy(&u, &v, 8);
        return word(std::uint32_t(u >> 32)).word(std::uint32_t(u));
    }
    Bytes& str(const std::string& s) {
        word(std::uint32_t(s.size()));
        data += s;
        data.append((4 - s.size() % 4) % 4, '\0');
        return *this;
    }
    Bytes& raw(const std::string& s) {
        data += s;
        return *this;
    }
    /// A node header of V2.1: type name, flags, field word.
    Bytes& node(const std::string& type, std::uint32_t fields, bool group = false,
                bool engine = false) {
        return str(type).word((group ? 2u : 0u) | (engine ? 1u : 0u)).word(fields);
    }
};

const std::string v21 = "#Inventor V2.1 binary  \n";
const std::string v20 = "#Inventor V2.0 binary  \n";

ReadOptions keeping() {
    ReadOptions o;
    o.keepUnknownTypes = true;
    return o;
}

void checkSame(const std::string& binary, const std::string& text) {
    ref_ptr<Node> fromBinary = readSceneFromString(binary, "scene.iv");
    ref_ptr<Node> fromText =
        readSceneFromString("#Inventor V2.1 ascii\n" + text, "scene.iv", keeping());
    std::string why;
    CHECK_MESSAGE(graphsEqual(*fromBinary, *fromText, &why), why, "\n",
                  writeSceneToString(*fromBinary));
    // And what the binary gave writes as text that reads back the same.
    ref_ptr<Node> back = readSceneFromString(writeSceneToString(*fromBinary), "back.iv", keeping());
    CHECK_MESSAGE(graphsEqual(*fromBinary, *back, &why), why);
}

std::string errorOf(const std::string& binary) {
    try {
        readSceneFromString(binary, "bad.iv");
    } catch (const Error& e) {
        return e.what();
    }
    FAIL("no error");
    return {};
}

} // namespace

TEST_CASE("a V2.1 binary file reads to the graph of its text: nodes, DEF/USE, values") {
    Bytes b;
    b.raw(v21).node("Separator", 1, true).str("renderCaching").str("ON").word(0).word(4);
    b.str("DEF").str("box+0").node("Cube", 2).str("width").f(3).word(0).str("height").f(0.5f).word(
        0);
    b.str("USE").str("box+0");
    b.node("Coordinate3", 1).str("point").word(2).f(1).f(2).f(3).f(4).f(5).f(6).word(0);
    b.node("ResetTransform", 1).str("whatToReset").str("TRANSFORM").str("BBOX").str("").word(0);
    checkSame(b.data, "Separator { renderCaching ON DEF box Cube { width 3 height 0.5 } USE box"
                      " Coordinate3 { point [ 1 2 3, 4 5 6 ] }"
                      " ResetTransform { whatToReset (TRANSFORM | BBOX) } }");
}

TEST_CASE("binary field flags: ignored, default, and connections to engines") {
    Bytes b;
    b.raw(v21).node("Separator", 0, true).word(2);
    b.node("Cube", 2).str("width").f(2).word(1).str("depth").f(7).word(4); // ignored; default
    b.node("Cube", 1).str("height").f(1).word(2);                          // connected:
    b.node("ElapsedTime", 1, false, true).str("speed").f(2).word(0).str("timeOut");
    checkSame(b.data, "Separator { Cube { width 2 ~ }"
                      " Cube { height 1 = ElapsedTime { speed 2 } . timeOut } }");
}

TEST_CASE("binary unknown types: standard ones from the table, others described") {
    Bytes b;
    b.raw(v21).node("Separator", 0, true).word(3);
    // Texture2 (no class here): an SFImage of 2 x 1 pixels, 3 components, padded to 8 bytes.
    b.node("Texture2", 2).str("image").word(2).word(1).word(3);
    b.raw(std::string("\xFF\x00\x00\x00\xFF\x00", 6));
    b.raw(std::string(2, '\0')).word(0).str("wrapS").str("CLAMP").word(0);
    // A described extension node with children.
    b.node("Gizmo", 0x4002, true).str("SFFloat").str("size").str("MFString").str("tags");
    b.str("size").f(1.5f).word(0).str("tags").word(2).str("a").str("bc").word(0);
    b.word(1).node("Cube", 0);
    // A standard type whose class lacks one of the file's fields (vertexProperty).
    b.node("IndexedFaceSet", 2).str("coordIndex").word(3).word(0).word(1).word(2).word(0);
    b.str("vertexProperty").node("VertexProperty", 1).str("vertex").word(1).f(0).f(0).f(0);
    b.word(0).word(0);
    checkSame(b.data,
              "Separator { Texture2 { image 2 1 3 0xFF0000 0x00FF00 wrapS CLAMP }"
              " Gizmo { fields [ SFFloat size, MFString tags ] size 1.5 tags [ \"a\", \"bc\" ]"
              " Cube { } }"
              " IndexedFaceSet { coordIndex [ 0, 1, 2 ] vertexProperty VertexProperty {"
              " vertex 0 0 0 } } }");
    auto root = readSceneFromString(b.data, "scene.iv");
    auto* texture = dynamic_cast<Texture2*>((*root->children())[0].get());
    REQUIRE(texture);
    const ImageValue& image = texture->image();
    CHECK(image.pixels == std::vector<std::uint8_t>{255, 0, 0, 0, 255, 0});
}

TEST_CASE("V2.0 binary: no node flags, a Group without a field word, images as words, "
          "PackedColor's rgba upgraded") {
    Bytes b;
    b.raw(v20).str("Group").word(3); // a V2.0 Group: no field word, then its child count
    b.str("Separator").word(0).word(1).str("Cube").word(0);
    b.str("Texture2").word(1).str("image").word(1).word(1).word(2).word(0x1234).word(0);
    b.str("PackedColor").word(1).str("rgba").word(1).word(0x11223344).word(0);
    checkSame(b.data, "Group { Separator { Cube { } } Texture2 { image 1 1 2 0x1234 }"
                      " PackedColor { orderedRGBA 0x44332211 } }");
}

TEST_CASE("binary GlobalField and typed engines") {
    Bytes b;
    b.raw(v21).node("Cube", 2).str("width").f(0).word(2);
    b.str("GlobalField").word(0).str("type").str("SFTime").word(1).str("realTime").d(0).word(0);
    b.str("realTime");
    b.str("height").f(1).word(2).str("SelectOne").word(1).str("type").str("MFFloat");
    b.word(2).str("index").word(1).word(0).str("input").word(2).f(4).f(5).word(0).str("output");
    checkSame(b.data, "Cube { width 0 = GlobalField { type SFTime realTime 0 } . realTime"
                      " height 1 = SelectOne { type MFFloat index 1 input [ 4, 5 ] } . output }");
}

TEST_CASE("binary errors name the byte") {
    // "#Inventor V2.1 binary  \n" is 24 bytes, so the first name is at byte 24.
    CHECK(errorOf(v21 + std::string("\0\0\0\x10", 4) + "Cube") ==
          "bad.iv: byte 24: unexpected end of file: a node type name is a string of 16 bytes, "
          "4 left");
    Bytes b;
    b.raw(v21).node("Cube", 1).str("width").raw("\x01\x02");
    CHECK(errorOf(b.data) == "bad.iv: byte 52: field 'width' of Cube expects SFFloat: "
                             "unexpected end of file: a float needs 4 bytes, 2 left");
    Bytes c;
    c.raw(v21).node("Cube", 1).str("wide").f(1).word(0);
    CHECK(errorOf(c.data) == "bad.iv: byte 40: unknown field 'wide' in Cube");
}
