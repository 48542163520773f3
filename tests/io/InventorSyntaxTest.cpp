// The Inventor text syntax beyond nodes and values: ignore flags, field connections and
// engines, unknown types kept without a description, alternate representations, V1.0 files
// (docs/SCENE-FORMAT.md sections 1.4 and 1.10) — read, kept and written back.
#include <doctest/doctest.h>

#include <string>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/core/Error.h>
#include <volsg/engines/Engines.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/GraphCompare.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/io/UnknownNode.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/ShapeHints.h>
#include <volsg/nodes/Transform.h>

using namespace volsg;

namespace {

const std::string header = "#Inventor V2.1 ascii\n";

ReadOptions keeping() {
    ReadOptions o;
    o.keepUnknownTypes = true;
    return o;
}

/// Reads, writes, reads again: the same graph, and the same text written twice.
ref_ptr<Node> roundTrip(const std::string& text, const ReadOptions& options = {}) {
    ref_ptr<Node> first = readSceneFromString(text, "syntax.iv", options);
    const std::string written = writeSceneToString(*first);
    ref_ptr<Node> second = readSceneFromString(written, "written.iv", options);
    std::string why;
    CHECK_MESSAGE(graphsEqual(*first, *second, &why), why, "\n", written);
    CHECK(writeSceneToString(*second) == written);
    return first;
}

std::string errorOf(const std::string& text, const ReadOptions& options = {}) {
    try {
        readSceneFromString(text, "bad.iv", options);
    } catch (const Error& e) {
        return e.what();
    }
    FAIL("no error for " << text);
    return {};
}

} // namespace

TEST_CASE("the ignore flag is kept with or without a value and written back") {
    auto root = roundTrip(header + "Cube { width 3 ~ height ~ }");
    auto* cube = dynamic_cast<Cube*>(root.get());
    REQUIRE(cube);
    CHECK(cube->width.isIgnored());
    CHECK(cube->width() == 3.0f);
    CHECK(cube->height.isIgnored());
    CHECK(cube->height.isDefault());
    CHECK_FALSE(cube->depth.isIgnored());
    const std::string text = writeSceneToString(*root);
    CHECK(text.find("width 3 ~") != std::string::npos);
    CHECK(text.find("height ~") != std::string::npos);
}

TEST_CASE("field connections to node fields and engine outputs round-trip") {
    auto root = roundTrip(header + "Separator {\n"
                                   "  DEF a Transform { translation 1 2 3 }\n"
                                   "  Transform { translation = USE a.translation }\n"
                                   "  Transform { translation 0 0 0 = USE a . translation }\n"
                                   "  Cube { width 2 = DEF t ElapsedTime { speed 3 } . timeOut\n"
                                   "         height ~ = USE t . timeOut }\n"
                                   "  Cube { depth = Calculator { a 1 expression \"oa = a * 2\" }"
                                   ".oa }\n"
                                   "}");
    auto& children = *root->children();
    auto* second = dynamic_cast<Transform*>(children[1].get());
    REQUIRE(second);
    REQUIRE(second->translation.connection());
    CHECK(second->translation.connection()->source == children[0]);
    CHECK(second->translation.connection()->sourceField == "translation");
    CHECK(second->translation.isDefault()); // no value was given
    auto* third = dynamic_cast<Transform*>(children[2].get());
    CHECK_FALSE(third->translation.isDefault());
    auto* cube = dynamic_cast<Cube*>(children[3].get());
    REQUIRE(cube->width.connection());
    REQUIRE(cube->height.connection());
    // One engine, shared by two connections.
    CHECK(cube->width.connection()->source == cube->height.connection()->source);
    CHECK(dynamic_cast<ElapsedTime*>(cube->width.connection()->source.get()));
    CHECK(cube->height.isIgnored());
    const std::string text = writeSceneToString(*root);
    CHECK(text.find("= USE a . translation") != std::string::npos);
    CHECK(text.find("= DEF t ElapsedTime") != std::string::npos);
    CHECK(text.find("= USE t . timeOut") != std::string::npos);
}

TEST_CASE("bad connections are errors with their position") {
    CHECK(errorOf(header + "Cube { width = Calculator { } . nothing }")
              .find("bad.iv:2:16: field 'width' of Cube: no field or output 'nothing' in "
                    "Calculator") != std::string::npos);
    CHECK(errorOf(header + "Separator { DEF c Cube { } Switch { whichChild = USE c }}")
              .find("expected '.' and the name of a field or output") != std::string::npos);
    CHECK(errorOf(header + "Separator { ElapsedTime { } }").find("'ElapsedTime' is an engine") !=
          std::string::npos);
    CHECK(
        errorOf(header + "DEF c Cube { width = USE c.width }").find("USE of undefined name 'c'") !=
        std::string::npos);
    CHECK(errorOf(header + "Separator { DEF g Group { } Cube { width = USE g.nothing } }")
              .find("no field or output 'nothing' in Group") != std::string::npos);
    CHECK(errorOf(header + "Separator { DEF m Material { } Cube { width = USE m.diffuseColor } }")
              .find("cannot connect 'width' to 'diffuseColor' of Material") != std::string::npos);
}

TEST_CASE("standard Inventor types without a class need keepUnknownTypes and keep their fields") {
    const std::string text = header + "Separator { BumpMap { filename \"wood.png\" wrapS CLAMP }"
                                      " CacheHint { memValue 0.25 } Cube { } }";
    CHECK(errorOf(text).find("'BumpMap' is a standard Inventor type") != std::string::npos);
    auto root = roundTrip(text, keeping());
    auto* texture = dynamic_cast<UnknownNode*>((*root->children())[0].get());
    REQUIRE(texture);
    CHECK(texture->fileTypeName() == "BumpMap");
    CHECK(texture->description() == UnknownNode::Description::Inventor);
    CHECK(std::string(texture->findField("image")->typeName()) == "SFImage");
    CHECK(texture->findField("image")->isDefault());
    const std::string written = writeSceneToString(*root);
    CHECK(written.find("fields [") == std::string::npos); // Inventor knows these
    CHECK(written.find("wrapS CLAMP") != std::string::npos);
    CHECK(errorOf(text.substr(0, text.size() - 2) + " BumpMap { nosuch 1 } }", keeping())
              .find("unknown field 'nosuch' in BumpMap") != std::string::npos);
}

TEST_CASE("a standard field our class lacks keeps the node as the standard type") {
    // DrawStyle has no linePatternScaleFactor (a Coin addition) here.
    const std::string text = header + "DrawStyle { style LINES lineWidth 3"
                                      " linePatternScaleFactor 2 }";
    CHECK(errorOf(text).find("unknown field 'linePatternScaleFactor' in DrawStyle") !=
          std::string::npos);
    auto root = roundTrip(text, keeping());
    auto* style = dynamic_cast<UnknownNode*>(root.get());
    REQUIRE(style);
    CHECK(style->fileTypeName() == "DrawStyle");
    auto* width = dynamic_cast<SFFloat*>(style->findField("lineWidth"));
    REQUIRE(width);
    CHECK(width->getValue() == 3.0f);
    auto* scale = dynamic_cast<SFInt32*>(style->findField("linePatternScaleFactor"));
    REQUIRE(scale);
    CHECK(scale->getValue() == 2);
}

TEST_CASE("unknown types without a description keep their values as text") {
    const std::string text =
        header + "Separator { Gizmo { a 1 2.5 -3 b \"two words\" c [ 1, 2 ] d ( A | B ) e WORD"
                 " f Cube { width 3 } g 7 ~ Sphere { } } }";
    CHECK(errorOf(text).find("unknown node type 'Gizmo'") != std::string::npos);
    auto root = roundTrip(text, keeping());
    auto* gizmo = dynamic_cast<UnknownNode*>((*root->children())[0].get());
    REQUIRE(gizmo);
    CHECK(gizmo->description() == UnknownNode::Description::Raw);
    CHECK(gizmo->fieldCount() == 7);
    CHECK(dynamic_cast<SFNode*>(gizmo->findField("f")));
    CHECK(gizmo->findField("g")->isIgnored());
    REQUIRE(gizmo->children()->size() == 1);
    const std::string written = writeSceneToString(*root);
    CHECK(written.find("a 1 2.5 -3") != std::string::npos);
    CHECK(written.find("b \"two words\"") != std::string::npos);
    CHECK(written.find("d ( A | B )") != std::string::npos);
    CHECK(written.find("fields [") == std::string::npos);
}

TEST_CASE("an unknown node draws its alternateRep, and an isA Group its children") {
    auto root =
        roundTrip(header + "Separator {"
                           "  Foo { fields [ SFNode alternateRep ] alternateRep Cube {"
                           "    width 4 } }"
                           "  Bar { fields [ MFString isA ] isA \"Group\" Cube { height 6 } }"
                           "  Baz { fields [ SFFloat x ] x 1 Cube { depth 100 } }"
                           "}");
    const Box3 box = computeBoundingBox(*root);
    CHECK(box.max.x == doctest::Approx(2.0)); // the alternate Cube, 4 wide
    CHECK(box.max.y == doctest::Approx(3.0)); // Bar's child, 6 high
    CHECK(box.max.z == doctest::Approx(1.0)); // Baz's children are not drawn
}

TEST_CASE("V1.0 files are read, with Coin's upgrade of ShapeHints") {
    const std::string v1 = "#Inventor V1.0 ascii\n"
                           "Separator { ShapeHints { hints (SOLID | ORDERED) creaseAngle 0.5 }"
                           " Cube { } }";
    auto root = readSceneFromString(v1, "old.iv", keeping());
    auto* hints = dynamic_cast<ShapeHints*>((*root->children())[0].get());
    REQUIRE(hints);
    CHECK(hints->shapeType() == ShapeHints::SOLID);
    CHECK(hints->vertexOrdering() == ShapeHints::COUNTERCLOCKWISE);
    CHECK(hints->faceType() == ShapeHints::UNKNOWN_FACE_TYPE);
    CHECK(hints->creaseAngle() == 0.5f);
    CHECK_FALSE(hints->field("hints"));
    // Written as V2.1, it reads back the same.
    const std::string written = writeSceneToString(*root);
    CHECK(written.rfind("#Inventor V2.1 ascii", 0) == 0);
    std::string why;
    CHECK_MESSAGE(graphsEqual(*root, *readSceneFromString(written, "new.iv", keeping()), &why),
                  why);
}
