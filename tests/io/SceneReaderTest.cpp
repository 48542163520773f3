// Reading well-formed scene files: structure, DEF/USE, self-described nodes, file folders.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/UnknownNode.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/Cone.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Sphere.h>
#include <volsg/nodes/Switch.h>
#include <volsg/nodes/Transform.h>

#include "io/TestNodes.h"

using namespace volsg;

namespace {

template <class T> T* childAs(const Node& group, std::size_t i) {
    const auto* kids = group.children();
    REQUIRE(kids);
    REQUIRE(i < kids->size());
    return dynamic_cast<T*>((*kids)[i].get());
}

/// A fresh, empty folder under the system temporary directory.
std::filesystem::path scratchFolder(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("volsg-io-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace

TEST_CASE("the docs/SCENE-FORMAT.md example reads into the expected nodes and fields") {
    auto root = readSceneFromString(R"(#Inventor V2.1 ascii
# comment to end of line
Separator {
  DEF cam PerspectiveCamera { position 0 0 5  heightAngle 0.785398 }
  Transform { translation 1 0 0  rotation 0 1 0 1.5708 }
  Material { diffuseColor 0.8 0.2 0.2  transparency 0.5 }
  Cube { width 2 }
  USE cam
}
)");
    REQUIRE(root->isA<Separator>());
    REQUIRE(root->children()->size() == 5);
    auto* cam = childAs<PerspectiveCamera>(*root, 0);
    REQUIRE(cam);
    CHECK(cam->getName() == "cam");
    CHECK(cam->position() == glm::vec3(0, 0, 5));
    CHECK(cam->heightAngle() == 0.785398f);
    CHECK(cam->nearDistance.isDefault());
    auto* xf = childAs<Transform>(*root, 1);
    REQUIRE(xf);
    CHECK(xf->translation() == glm::vec3(1, 0, 0));
    CHECK(xf->rotation().axis == glm::vec3(0, 1, 0));
    CHECK(xf->rotation().angle == 1.5708f);
    auto* mat = childAs<Material>(*root, 2);
    REQUIRE(mat);
    CHECK(mat->diffuseColor() == std::vector<glm::vec3>{glm::vec3(0.8f, 0.2f, 0.2f)});
    CHECK(mat->transparency() == std::vector<float>{0.5f});
    auto* cube = childAs<Cube>(*root, 3);
    REQUIRE(cube);
    CHECK(cube->width() == 2.0f);
    CHECK(cube->height() == 2.0f);
    CHECK(root->children()->at(4).get() == cam);
}

TEST_CASE("fields may come in any order and repeat, the last value wins") {
    auto root = readSceneFromString("#Inventor V2.1 ascii\n"
                                    "Cone { height 3 parts (SIDES | BOTTOM) bottomRadius 0.5 "
                                    "height 4 }");
    auto* cone = dynamic_cast<Cone*>(root.get());
    REQUIRE(cone);
    CHECK(cone->height() == 4.0f);
    CHECK(cone->bottomRadius() == 0.5f);
    CHECK(cone->parts() == Cone::ALL);
}

TEST_CASE("a single top-level node is returned as it is") {
    auto root = readSceneFromString("#Inventor V2.1 ascii\nCube { }\n");
    CHECK(root->isA<Cube>());
}

TEST_CASE("several top-level nodes are wrapped in a Separator") {
    auto root = readSceneFromString("#Inventor V2.1 ascii\nCube { } Sphere { } Cube { }\n");
    REQUIRE(root->isA<Separator>());
    REQUIRE(root->children()->size() == 3);
    CHECK(root->children()->at(1)->type().name() == std::string("Sphere"));
}

TEST_CASE("a file with only the header gives an empty Separator") {
    auto root = readSceneFromString("#Inventor V2.1 ascii\n# nothing else\n");
    REQUIRE(root->isA<Separator>());
    CHECK(root->children()->empty());
}

TEST_CASE("Inventor V2.0 and VRML V1.0 headers are accepted") {
    CHECK(readSceneFromString("#Inventor V2.0 ascii\nCube { }")->isA<Cube>());
    CHECK(readSceneFromString("#VRML V1.0 ascii\r\nCube { }")->isA<Cube>());
    CHECK(readSceneFromString("\xEF\xBB\xBF#Inventor V2.1 ascii   \nCube { }")->isA<Cube>());
}

TEST_CASE("USE shares the DEF node itself, not a copy") {
    auto root = readSceneFromString("#Inventor V2.1 ascii\n"
                                    "Separator {\n"
                                    "  DEF red Material { diffuseColor 1 0 0 }\n"
                                    "  Separator { USE red Cube { } }\n"
                                    "  USE red\n"
                                    "}\n");
    Node* red = root->children()->at(0).get();
    Node* inner = root->children()->at(1).get();
    CHECK(inner->children()->at(0).get() == red);
    CHECK(root->children()->at(2).get() == red);
    CHECK(red->refCount() == 3);
}

TEST_CASE("a later DEF of the same name rebinds it for the USEs after it") {
    auto root = readSceneFromString("#Inventor V2.1 ascii\n"
                                    "Separator { DEF a Cube { } USE a DEF a Sphere { } USE a }\n");
    const auto& k = *root->children();
    CHECK(k[1] == k[0]);
    CHECK(k[3] == k[2]);
    CHECK(k[2]->isA<Sphere>());
}

TEST_CASE("the +N suffix of a DEF name is not part of the node name") {
    auto root = readSceneFromString("#Inventor V2.1 ascii\n"
                                    "Separator { DEF cam+3 Cube { } DEF +0 Sphere { } USE cam+3 "
                                    "USE +0 }\n");
    const auto& k = *root->children();
    CHECK(k[0]->getName() == "cam");
    CHECK(k[1]->getName().empty());
    CHECK(k[2] == k[0]);
    CHECK(k[3] == k[1]);
}

TEST_CASE("Switch reads its whichChild field before its children") {
    auto root = readSceneFromString("#Inventor V2.1 ascii\n"
                                    "Switch { whichChild -3 Cube { } Cube { } }\n");
    auto* sw = dynamic_cast<Switch*>(root.get());
    REQUIRE(sw);
    CHECK(sw->whichChild() == Switch::SWITCH_ALL);
    CHECK(sw->getNumChildren() == 2);
}

TEST_CASE("an unknown self-described node keeps its type name, fields, values and children") {
    auto root = readSceneFromString("#Inventor V2.1 ascii\n"
                                    "Foo {\n"
                                    "  fields [ SFFloat a, MFVec3f b, SFEnum mode, SFNode n ]\n"
                                    "  b [ 0 0 0, 1 2 3 ]\n"
                                    "  a 1.5\n"
                                    "  mode FANCY\n"
                                    "  Cube { width 4 }\n"
                                    "}\n");
    auto* foo = dynamic_cast<UnknownNode*>(root.get());
    REQUIRE(foo);
    CHECK(foo->fileTypeName() == "Foo");
    REQUIRE(foo->fieldCount() == 4);
    CHECK(std::string(foo->fieldAt(0)->name()) == "a");
    CHECK(std::string(foo->fieldAt(1)->typeName()) == "MFVec3f");
    auto* a = dynamic_cast<SFFloat*>(foo->field("a"));
    REQUIRE(a);
    CHECK(a->getValue() == 1.5f);
    auto* b = dynamic_cast<MFVec3f*>(foo->field("b"));
    REQUIRE(b);
    CHECK(b->getValues() == std::vector<glm::vec3>{glm::vec3(0), glm::vec3(1, 2, 3)});
    CHECK(foo->field("n")->isDefault());
    REQUIRE(foo->children()->size() == 1);
    CHECK(foo->children()->at(0)->isA<Cube>());
}

TEST_CASE("our own node types read with or without a matching fields description") {
    test::registerTestNodeTypes();
    auto plain = readSceneFromString("#Inventor V2.1 ascii\nTestGroup { weight 2 Cube { } }");
    auto described = readSceneFromString(
        "#Inventor V2.1 ascii\nTestGroup { fields [ SFFloat weight ] weight 2 Cube { } }");
    for (const auto& root : {plain, described}) {
        auto* g = dynamic_cast<test::TestGroup*>(root.get());
        REQUIRE(g);
        CHECK(g->weight() == 2.0f);
        CHECK(g->getNumChildren() == 1);
    }
}

TEST_CASE("readScene reads a file and nodes resolve relative names against its folder") {
    test::registerTestNodeTypes();
    const auto dir = scratchFolder("reader-folder");
    const auto file = dir / "scene.iv";
    {
        std::ofstream out(file);
        out << "#Inventor V2.1 ascii\n"
               "Separator { FileUser { fileName \"data/ct.raw\" } "
               "FileUser { fileName \"/abs/ct.raw\" } }\n";
    }
    auto root = readScene(file.string());
    auto* rel = dynamic_cast<test::FileUser*>(root->children()->at(0).get());
    auto* abs = dynamic_cast<test::FileUser*>(root->children()->at(1).get());
    REQUIRE((rel && abs));
    CHECK(rel->resolved == (dir / "data/ct.raw").string());
    CHECK(rel->sceneFile == file.string());
    CHECK(rel->readDoneCalls == 1);
    CHECK(abs->resolved == "/abs/ct.raw");
    std::filesystem::remove_all(dir);

    // Text with a file name resolves against that name's folder; a placeholder against none.
    auto named = readSceneFromString("#Inventor V2.1 ascii\nFileUser { fileName \"a.raw\" }",
                                     "/some/where/s.iv");
    CHECK(dynamic_cast<test::FileUser*>(named.get())->resolved == "/some/where/a.raw");
    auto text = readSceneFromString("#Inventor V2.1 ascii\nFileUser { fileName \"a.raw\" }");
    CHECK(dynamic_cast<test::FileUser*>(text.get())->resolved == "a.raw");
}

TEST_CASE("readScene of a missing file is an error naming the file") {
    CHECK_THROWS_WITH_AS(readScene("/nonexistent/volsg/scene.iv"),
                         doctest::Contains("/nonexistent/volsg/scene.iv"), Error);
}

TEST_CASE("a list of a million points in one field reads completely") {
    std::string text = "#Inventor V2.1 ascii\nCoordinate3 { point [\n";
    const int count = 1000000;
    text.reserve(std::size_t(count) * 8);
    for (int i = 0; i < count; ++i)
        text += std::to_string(i % 10) + " 0 1,";
    text += " ] }\n";
    auto root = readSceneFromString(text);
    auto* points = dynamic_cast<MFVec3f*>(root->field("point"));
    REQUIRE(points);
    CHECK(points->size() == std::size_t(count));
    CHECK((*points)[count - 1] == glm::vec3(9, 0, 1));
}
