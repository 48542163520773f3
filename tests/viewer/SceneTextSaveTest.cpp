// Saving by rewriting only what changed: comments, blank lines and the layout of untouched
// nodes stay byte for byte; a changed value replaces its own span; a field the file did not
// set is added to its node; a camera inserted at the root is written there; structural changes
// and files that cannot be patched are refused with a reason (the viewer then writes the whole
// scene). Every patched text reads back to the edited graph.
#include <doctest/doctest.h>

#include <volsg/actions/SearchAction.h>
#include <volsg/editors/FieldText.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/Group.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/Volume.h>

#include "view/SceneTextSave.h"

using namespace volsg;

namespace {

const std::string kText = "#Inventor V2.1 ascii\n"
                          "# A volume scene, commented.\n"
                          "Separator {\n"
                          "  # the data\n"
                          "  VolumeData { generator SOFT_SPHERE dimensions 16 16 16 }\n"
                          "\n"
                          "  DEF tf TransferFunction {\n"
                          "    red [ 0 0.2, 1 1 ]   # warm\n"
                          "    alpha [ 0 0,\n"
                          "            1 0.6 ]  # opacity ramp\n"
                          "  }\n"
                          "  DEF volume Volume { }  # no fields set\n"
                          "  Separator { USE tf }\n"
                          "}\n";

/// The patched text; fails the test when it is refused.
std::string patch(const SceneTextSnapshot& snapshot, Node& root) {
    std::string reason;
    const auto text = snapshot.patched(root, reason);
    INFO("refused: " << reason);
    REQUIRE(text);
    return *text;
}

/// Reading `text` back gives the same graph as `root` (as SceneWriter writes both).
void checkReadsBackAs(const std::string& text, const Node& root) {
    CHECK(writeSceneToString(*readSceneFromString(text)) == writeSceneToString(root));
}

} // namespace

TEST_CASE("an unchanged scene saves as its file, byte for byte") {
    auto root = readSceneFromString(kText);
    const SceneTextSnapshot snapshot = SceneTextSnapshot::take(kText, *root);
    CHECK(patch(snapshot, *root) == kText);
}

TEST_CASE("a changed value replaces its own span and nothing else") {
    auto root = readSceneFromString(kText);
    const SceneTextSnapshot snapshot = SceneTextSnapshot::take(kText, *root);
    auto* tf = static_cast<TransferFunction*>(findByName(*root, "tf"));
    tf->alpha.setValues({{0, 0}, {1, 0.1f}});
    std::string expected = kText;
    const std::string before = "[ 0 0,\n            1 0.6 ]";
    expected.replace(expected.find(before), before.size(), "[ 0 0, 1 0.1 ]");
    const std::string text = patch(snapshot, *root);
    CHECK(text == expected);
    checkReadsBackAs(text, *root);
}

TEST_CASE("a field the file did not set is added to its node, in the node's layout") {
    auto root = readSceneFromString(kText);
    const SceneTextSnapshot snapshot = SceneTextSnapshot::take(kText, *root);
    auto* volume = static_cast<Volume*>(findByName(*root, "volume"));
    volume->numPlanes = 64;
    auto* tf = static_cast<TransferFunction*>(findByName(*root, "tf"));
    tf->dataRange = glm::vec2(-100.0f, 300.0f);
    std::string expected = kText;
    expected.replace(expected.find("Volume { }"), 10, "Volume { numPlanes 64 }");
    const std::string opacity = "1 0.6 ]";
    expected.insert(expected.find(opacity) + opacity.size(), "\n            dataRange -100 300");
    const std::string text = patch(snapshot, *root);
    CHECK(text == expected);
    checkReadsBackAs(text, *root);
}

TEST_CASE("a camera inserted at the root is written there and the rest stays as it was") {
    auto root = readSceneFromString(kText);
    const SceneTextSnapshot snapshot = SceneTextSnapshot::take(kText, *root);
    auto camera = PerspectiveCamera::create();
    camera->position = glm::vec3(0.0f, 0.0f, 4.5f);
    camera->focalDistance = 4.5f;
    auto* children = root->children();
    children->insert(children->begin(), camera);
    const std::string text = patch(snapshot, *root);
    const std::string head = "Separator {\n";
    std::string expected = kText;
    expected.insert(expected.find(head) + head.size(),
                    "  PerspectiveCamera {\n    position 0 0 4.5\n    focalDistance 4.5\n  }\n");
    CHECK(text == expected);
    checkReadsBackAs(text, *root);
}

TEST_CASE("several top-level nodes: the inserted camera goes after the header") {
    const std::string text = "#Inventor V2.1 ascii\n"
                             "Cube { }  # one\n"
                             "Sphere { radius 2 }\n";
    auto root = readSceneFromString(text);
    const SceneTextSnapshot snapshot = SceneTextSnapshot::take(text, *root);
    auto camera = OrthographicCamera::create();
    camera->height = 3.0f;
    root->children()->insert(root->children()->begin(), camera);
    const std::string out = patch(snapshot, *root);
    CHECK(out == "#Inventor V2.1 ascii\nOrthographicCamera {\n  height 3\n}\n"
                 "Cube { }  # one\nSphere { radius 2 }\n");
    checkReadsBackAs(out, *root);
}

TEST_CASE("shared nodes and connections are kept, and an edit of a shared node is made once") {
    const std::string text = "#Inventor V2.1 ascii\n"
                             "Separator {\n"
                             "  DEF m Material { diffuseColor 1 0 0 }  # red\n"
                             "  DEF c Cube { width 2 }\n"
                             "  Cube { width = USE c.width  height 3 }\n"
                             "  Separator { USE m  USE c }\n"
                             "}\n";
    auto root = readSceneFromString(text);
    const SceneTextSnapshot snapshot = SceneTextSnapshot::take(text, *root);
    CHECK(patch(snapshot, *root) == text);
    Field& colour = *findByName(*root, "m")->field("diffuseColor");
    setFieldFromText(colour, "0 0 1");
    std::string expected = text;
    expected.replace(expected.find("1 0 0"), 5, fieldValueText(colour));
    const std::string out = patch(snapshot, *root);
    CHECK(out == expected);
    checkReadsBackAs(out, *root);
}

TEST_CASE("structural changes and unpatchable files are refused with a reason") {
    auto root = readSceneFromString(kText);
    const SceneTextSnapshot snapshot = SceneTextSnapshot::take(kText, *root);
    root->children()->pop_back();
    std::string reason;
    CHECK_FALSE(snapshot.patched(*root, reason));
    CHECK(reason.find("removed") != std::string::npos);

    const std::string v1 = "#Inventor V1.0 ascii\nSeparator { Cube { } }\n";
    auto old = readSceneFromString(v1);
    const SceneTextSnapshot oldSnapshot = SceneTextSnapshot::take(v1, *old);
    CHECK_FALSE(oldSnapshot.patched(*old, reason));
    CHECK(reason.find("V2.1") != std::string::npos);
}

TEST_CASE("a snapshot of text that does not match its graph refuses, never crashes") {
    // Every truncation of the file and every byte replaced by a brace, quote, bracket or '#'
    // against the graph read from the whole file: take() and patched() return (a refusal or a
    // text), and a text they return reads back.
    auto root = readSceneFromString(kText);
    int refused = 0, patchedOk = 0;
    auto attempt = [&](const std::string& text) {
        const SceneTextSnapshot snapshot = SceneTextSnapshot::take(text, *root);
        std::string reason;
        const auto out = snapshot.patched(*root, reason);
        if (!out) {
            CHECK(!reason.empty());
            ++refused;
        } else {
            ++patchedOk;
        }
    };
    for (std::size_t n = 0; n < kText.size(); ++n)
        attempt(kText.substr(0, n));
    for (std::size_t i = 0; i < kText.size(); ++i)
        for (const char c : {'{', '}', '"', '[', '#', '\\'}) {
            std::string text = kText;
            text[i] = c;
            attempt(text);
        }
    CHECK(refused > 0);
    CHECK(patchedOk > 0); // bytes inside comments change nothing that matters
}
