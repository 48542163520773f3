// The viewer's input scripts: what each command becomes, and errors with their line.
#include <doctest/doctest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <volsg/core/Error.h>

#include "view/ViewModes.h"
#include "view/ViewerScript.h"

using namespace volsg;

TEST_CASE("a drag becomes a move, a press, evenly spaced moves and a release") {
    const auto steps = parseViewerScript("drag right 10 20 50 100 4 shift\n", "s.txt");
    REQUIRE(steps.size() == 7);
    CHECK(steps[0].kind == ScriptStep::Kind::Move);
    CHECK(steps[1].kind == ScriptStep::Kind::Press);
    CHECK(steps[1].button == GLFW_MOUSE_BUTTON_RIGHT);
    CHECK(steps[1].mods == GLFW_MOD_SHIFT);
    for (int i = 1; i <= 4; ++i) {
        CHECK(steps[std::size_t(1 + i)].kind == ScriptStep::Kind::Move);
        CHECK(steps[std::size_t(1 + i)].point.value.x == doctest::Approx(10.0 + 10.0 * i));
        CHECK(steps[std::size_t(1 + i)].point.value.y == doctest::Approx(20.0 + 20.0 * i));
    }
    CHECK(steps[6].kind == ScriptStep::Kind::Release);
    CHECK(steps[6].point.value.x == 50.0);
}

TEST_CASE("script points name canvases and world points") {
    const auto steps = parseViewerScript("# comment line\n"
                                         "move tf:0.25,0.5\n"
                                         "move world:1,-2,3.5   # trailing comment\n"
                                         "screenshot out.png scene\n"
                                         "key s ctrl\n"
                                         "wait 3\n",
                                         "s.txt");
    REQUIRE(steps.size() == 5);
    CHECK(steps[0].point.kind == ScriptPoint::Kind::Canvas);
    CHECK(steps[0].point.canvas == "tf");
    CHECK(steps[0].point.value.y == 0.5);
    CHECK(steps[1].point.kind == ScriptPoint::Kind::World);
    CHECK(steps[1].point.value == glm::dvec3(1.0, -2.0, 3.5));
    CHECK(steps[2].sceneOnly);
    CHECK(steps[3].mods == GLFW_MOD_CONTROL);
    CHECK(keyCodeOf(steps[3].text) == GLFW_KEY_S);
    CHECK(steps[4].frames == 3);
    CHECK(steps[4].line == 6);
}

TEST_CASE("a bad script line is an error naming the file and line") {
    try {
        parseViewerScript("wait 1\nwait 2\njump 3 4\n", "bad.txt");
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.file() == "bad.txt");
        CHECK(e.line() == 3);
        CHECK(e.message().find("jump") != std::string::npos);
    }
    CHECK_THROWS_AS(parseViewerScript("drag left 1 2 3\n", "s"), Error);  // a point short
    CHECK_THROWS_AS(parseViewerScript("move nowhere:1,2\n", "s"), Error); // unknown place
    CHECK_THROWS_AS(parseViewerScript("key hyper\n", "s"), Error);        // unknown key
    CHECK_THROWS_AS(parseViewerScript("press left 1 2 sideways\n", "s"), Error);
}

TEST_CASE("view commands set layout, navigation, stereo, cursor and region") {
    const auto steps = parseViewerScript("layout four\n"
                                         "navigation walk\n"
                                         "stereo anaglyph 0.05\n"
                                         "stereo off\n"
                                         "cursor 3 4 5\n"
                                         "region 7\n"
                                         "click left view:axial:0.25,0.75\n",
                                         "s.txt");
    REQUIRE(steps.size() == 9);
    CHECK(steps[0].kind == ScriptStep::Kind::Layout);
    CHECK(steps[0].text == "four");
    CHECK(steps[1].kind == ScriptStep::Kind::Navigation);
    CHECK(steps[1].text == "walk");
    CHECK(steps[2].kind == ScriptStep::Kind::Stereo);
    CHECK(steps[2].separation == 0.05);
    CHECK(steps[3].separation == 0.0); // unchanged
    CHECK(steps[4].kind == ScriptStep::Kind::Cursor);
    CHECK(steps[4].voxel == glm::ivec3(3, 4, 5));
    CHECK(steps[5].kind == ScriptStep::Kind::Region);
    CHECK(steps[5].voxel.x == 7);
    CHECK(steps[6].point.kind == ScriptPoint::Kind::View);
    CHECK(steps[6].point.canvas == "axial");
    CHECK(steps[6].point.value.x == 0.25);
    CHECK(steps[6].point.value.y == 0.75);
}

TEST_CASE("unknown view modes and views are errors naming the line") {
    for (const char* bad :
         {"layout three\n", "navigation swim\n", "stereo interlaced\n", "stereo anaglyph 2\n",
          "region 0\n", "cursor 1 2\n", "click left view:top:0.5,0.5\n"}) {
        CAPTURE(bad);
        try {
            parseViewerScript(std::string("wait 1\n") + bad, "views.txt");
            FAIL("no error");
        } catch (const Error& e) {
            CHECK(e.file() == "views.txt");
            CHECK(e.line() == 2);
        }
    }
}

TEST_CASE("wait takes a frame count or waits for the seek animation") {
    const auto steps = parseViewerScript("wait 3\nwait seek\n", "s.txt");
    REQUIRE(steps.size() == 2);
    CHECK(steps[0].kind == ScriptStep::Kind::Wait);
    CHECK(steps[0].frames == 3);
    CHECK(steps[0].text.empty());
    CHECK(steps[1].kind == ScriptStep::Kind::Wait);
    CHECK(steps[1].text == "seek");
    CHECK(steps[1].frames == 0);
    try {
        parseViewerScript("wait\nwait forever\n", "w.txt");
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.line() == 1); // a bare wait has no count
    }
    CHECK_THROWS_AS(parseViewerScript("wait forever\n", "w.txt"), Error);
    CHECK_THROWS_AS(parseViewerScript("wait seek 2\n", "w.txt"), Error);
}

TEST_CASE("antialiasing modes have names both ways and unknown names are errors") {
    for (Antialias mode : {Antialias::Off, Antialias::Multisample, Antialias::Supersample})
        CHECK(parseAntialias(antialiasName(mode)) == mode);
    CHECK(parseAntialias("msaa") == Antialias::Multisample);
    CHECK(parseAntialias("2x2") == Antialias::Supersample);
    CHECK_THROWS_AS(parseAntialias("8x"), Error);
}

TEST_CASE("orientation and preset commands, and their errors") {
    const auto steps = parseViewerScript("view left\n"
                                         "sections neurological\n"
                                         "axes + - +\n"
                                         "preset both CT angiography (MIP)\n",
                                         "s.txt");
    REQUIRE(steps.size() == 4);
    CHECK(steps[0].kind == ScriptStep::Kind::View);
    CHECK(steps[0].text == "left");
    CHECK(steps[1].kind == ScriptStep::Kind::Sections);
    CHECK(steps[1].text == "neurological");
    CHECK(steps[2].kind == ScriptStep::Kind::Axes);
    CHECK(steps[2].voxel == glm::ivec3(1, -1, 1));
    CHECK(steps[3].kind == ScriptStep::Kind::Preset);
    CHECK(steps[3].frames == 2); // PresetApply::Both
    CHECK(steps[3].text == "CT angiography (MIP)");
    CHECK_THROWS_AS(parseViewerScript("view sideways\n", "s"), Error);
    CHECK_THROWS_AS(parseViewerScript("sections upside-down\n", "s"), Error);
    CHECK_THROWS_AS(parseViewerScript("axes + +\n", "s"), Error);
    CHECK_THROWS_AS(parseViewerScript("axes + * +\n", "s"), Error);
    CHECK_THROWS_AS(parseViewerScript("preset all CT bone\n", "s"), Error);
    CHECK_THROWS_AS(parseViewerScript("preset colour\n", "s"), Error);
}

TEST_CASE("file commands: open, drop, recent, type, the dialog's raw form and confirm") {
    const auto steps = parseViewerScript("open /d/a.nrrd\ndrop /d/b.iv /d/c.iv\nrecent 3\n"
                                         "type /d/some folder\ndialog raw 4 5 6 short 1 2 0.5\n"
                                         "confirm discard\nclick left dialog:b.iv\n",
                                         "f.txt");
    using K = ScriptStep::Kind;
    REQUIRE(steps.size() == 9); // the click is three steps
    CHECK(steps[0].kind == K::Open);
    CHECK(steps[0].text == "/d/a.nrrd");
    CHECK(steps[1].kind == K::Drop);
    CHECK(steps[1].files == std::vector<std::string>{"/d/b.iv", "/d/c.iv"});
    CHECK(steps[2].kind == K::Recent);
    CHECK(steps[2].frames == 3);
    CHECK(steps[3].kind == K::Type);
    CHECK(steps[3].text == "/d/some folder");
    CHECK(steps[4].kind == K::DialogRaw);
    CHECK(steps[4].voxel == glm::ivec3(4, 5, 6));
    CHECK(steps[4].text == "short");
    CHECK(steps[4].spacing == glm::dvec3(1, 2, 0.5));
    CHECK(steps[5].kind == K::Confirm);
    CHECK(steps[5].text == "discard");
    CHECK(steps[6].point.kind == ScriptPoint::Kind::Dialog);
    CHECK(steps[6].point.canvas == "b.iv");
    for (const char* bad :
         {"open\n", "open a b\n", "drop\n", "recent 0\n", "recent x\n", "dialog raw 1 2 3 int\n",
          "dialog raw 1 2 3 uchar 1 0 1\n", "dialog raw 1 2\n", "dialog cooked 1 2 3 uchar\n",
          "confirm maybe\n", "move dialog:\n"}) {
        CAPTURE(bad);
        CHECK_THROWS_AS(parseViewerScript(bad, "f.txt"), Error);
    }
}
