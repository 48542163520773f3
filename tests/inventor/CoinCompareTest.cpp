// volsg-coin-compare's comparison and report (viewer/inventor): silhouette IoU and colour
// difference on small images with known answers, the agreement thresholds, one-line messages,
// header kinds, rows handed between processes, the summary and the Markdown table. No Coin:
// the library under test (volsg_coin_compare) knows none.
#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>

#include <unistd.h>

#include <volsg/core/Error.h>

#include "../../viewer/inventor/ChildProcess.h"
#include "../../viewer/inventor/ImageCompare.h"
#include "../../viewer/inventor/ModelReport.h"

using namespace volsg::coincompare;

namespace {

constexpr Rgb8 black{0, 0, 0};
constexpr Rgb8 white{255, 255, 255};

std::string outputPath(const std::string& name) {
    const std::filesystem::path dir =
        std::filesystem::path(VOLSG_BINARY_DIR) / "test-output" / "inventor";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

} // namespace

TEST_CASE("IoU and colour difference of two overlapping silhouettes") {
    // A covers x = 0..2 of the top row, B covers x = 1..3: |A∩B| = 2, |A∪B| = 4.
    Image8 a(4, 4), b(4, 4);
    for (int x = 0; x < 3; ++x)
        a.at(x, 0) = white;
    for (int x = 1; x < 4; ++x)
        b.at(x, 0) = white;
    const Comparison c = compare(a, black, b, black);
    CHECK(c.pixelsA == 3);
    CHECK(c.pixelsB == 3);
    CHECK(c.intersection == 2);
    CHECK(c.unionCount == 4);
    CHECK(c.iou == doctest::Approx(0.5));
    // Union: two pixels white in both (difference 0), two white against black (difference 1).
    CHECK(c.colourDifference == doctest::Approx(0.5));
    CHECK_FALSE(agrees(c));
}

TEST_CASE("the colour difference is per channel in [0,1], averaged over RGB and the union") {
    Image8 a(2, 1), b(2, 1);
    a.at(0, 0) = {100, 50, 0};
    b.at(0, 0) = {90, 60, 0}; // 10 + 10 + 0 over 3 channels of 255
    a.at(1, 0) = {255, 0, 0}; // only in A: B shows its background there
    const Comparison c = compare(a, black, b, black);
    CHECK(c.unionCount == 2);
    CHECK(c.intersection == 1);
    CHECK(c.iou == doctest::Approx(0.5));
    const double expected = ((10.0 + 10.0) / (3.0 * 255.0) + 255.0 / (3.0 * 255.0)) / 2.0;
    CHECK(c.colourDifference == doctest::Approx(expected).epsilon(1e-12));
}

TEST_CASE("identical images agree, two empty images agree that nothing is seen") {
    Image8 a(3, 3);
    a.at(1, 1) = {10, 20, 30};
    const Comparison same = compare(a, black, a, black);
    CHECK(same.iou == 1.0);
    CHECK(same.colourDifference == 0.0);
    CHECK(agrees(same));

    const Image8 empty(3, 3);
    const Comparison none = compare(empty, black, empty, black);
    CHECK(none.unionCount == 0);
    CHECK(none.iou == 1.0);
    CHECK(none.colourDifference == 0.0);
}

TEST_CASE("each image is measured against its own background") {
    const Rgb8 grey{51, 51, 51}, greyish{51, 51, 52}; // one renderer rounds 0.2 up in blue
    Image8 a(2, 2, grey), b(2, 2, greyish);
    a.at(0, 0) = white;
    b.at(0, 0) = white;
    const Comparison c = compare(a, grey, b, greyish);
    CHECK(c.unionCount == 1);
    CHECK(c.iou == 1.0);
    CHECK(c.colourDifference == 0.0);
    // Against one background, the other image's whole background would be "seen".
    CHECK(compare(a, grey, b, grey).unionCount == 4);
}

TEST_CASE("a silhouette is every pixel that differs from the background in any channel") {
    Image8 a(3, 1);
    a.at(1, 0) = {0, 0, 1};
    const std::vector<bool> s = silhouette(a, black);
    CHECK(s == std::vector<bool>{false, true, false});
}

TEST_CASE("agreement thresholds: IoU >= 0.9 and colour difference <= 0.08, both inclusive") {
    Comparison c;
    c.iou = 0.9;
    c.colourDifference = 0.08;
    CHECK(agrees(c));
    c.iou = 0.8999;
    CHECK_FALSE(agrees(c));
    c.iou = 1.0;
    c.colourDifference = 0.0801;
    CHECK_FALSE(agrees(c));
    // 9 of 10 pixels shared exactly: IoU 0.9 from counts.
    Image8 a(10, 1), b(10, 1);
    for (int x = 0; x < 10; ++x)
        a.at(x, 0) = white;
    for (int x = 0; x < 9; ++x)
        b.at(x, 0) = white;
    const Comparison counted = compare(a, black, b, black);
    CHECK(counted.iou == doctest::Approx(0.9));
    CHECK(counted.colourDifference == doctest::Approx(0.1)); // one of ten differs fully
    CHECK_FALSE(agrees(counted));
}

TEST_CASE("images of different sizes are an error") {
    CHECK_THROWS_AS(compare(Image8(2, 2), black, Image8(2, 3), black), volsg::Error);
}

TEST_CASE("8-bit conversion rounds as volsg's PNG writer does, and GL rows are flipped") {
    CHECK(toByte(0.0f) == 0);
    CHECK(toByte(1.0f) == 255);
    CHECK(toByte(0.5f) == 128);
    CHECK(toByte(1.5f) == 255);
    CHECK(toByte(-0.2f) == 0);
    CHECK(toByte(std::numeric_limits<float>::quiet_NaN()) == 0);
    CHECK(toRgb8(glm::vec3(0.2f, 0.4f, 0.6f)) == Rgb8{51, 102, 153});

    volsg::Image v(1, 1);
    v.at(0, 0) = glm::vec4(1.0f, 0.5f, 0.0f, 0.3f);
    CHECK(fromVolsg(v).at(0, 0) == Rgb8{255, 128, 0});

    // Bottom-up RGBA: the first row in memory is the bottom of the image.
    const std::uint8_t rgba[] = {1, 2, 3, 255, 4, 5, 6, 255};
    const Image8 flipped = fromBottomUpRgba(rgba, 1, 2);
    CHECK(flipped.at(0, 0) == Rgb8{4, 5, 6});
    CHECK(flipped.at(0, 1) == Rgb8{1, 2, 3});
}

TEST_CASE("PNGs hold the 8-bit images exactly") {
    Image8 a(16, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            a.at(x, y) = {std::uint8_t(16 * y + x), std::uint8_t(255 - 16 * y - x),
                          std::uint8_t((7 * x + 3 * y) & 255)};
    const std::string path = outputPath("roundtrip.png");
    writePng8(path, a);
    CHECK(readPng8(path) == a);
}

TEST_CASE("the side-by-side picture: Coin, volsg, and the silhouettes coloured by owner") {
    Image8 coin(2, 1), volsg(2, 1);
    coin.at(0, 0) = white;
    volsg.at(0, 0) = white;
    volsg.at(1, 0) = {10, 0, 0};
    const Image8 picture = sideBySide(&coin, black, &volsg, black, 2, 1);
    CHECK(picture.width == 3 * 2 + 2 * 4);
    CHECK(picture.height == 1);
    CHECK(picture.at(0, 0) == white);                  // Coin
    CHECK(picture.at(2 + 4 + 1, 0) == Rgb8{10, 0, 0}); // volsg
    const int x0 = 2 * (2 + 4);
    CHECK(picture.at(x0, 0) == Rgb8{160, 160, 160});   // both
    CHECK(picture.at(x0 + 1, 0) == Rgb8{220, 0, 220}); // volsg only
    const Image8 missing = sideBySide(&coin, black, nullptr, black, 2, 1);
    CHECK(missing.at(2 + 4, 0) == Rgb8{80, 0, 0});
}

TEST_CASE("messages are one line and bounded") {
    CHECK(oneLine("a\nb\tc   d\r\n") == "a b c d");
    CHECK(oneLine("  lead and trail  ") == "lead and trail");
    const std::string longText(1000, 'x');
    const std::string cut = oneLine(longText, 50);
    CHECK(cut.size() == 50);
    CHECK(cut.substr(47) == "...");
    CHECK(oneLine(longText).size() == maxMessageLength);
    // A cut never splits a UTF-8 character ("é" is two bytes).
    std::string accents;
    for (int i = 0; i < 40; ++i)
        accents += "\xc3\xa9";
    const std::string cutAccents = oneLine(accents, 10);
    CHECK(cutAccents.size() <= 10);
    CHECK(cutAccents.substr(0, 6) == "\xc3\xa9\xc3\xa9\xc3\xa9");
    CHECK(cutAccents.substr(cutAccents.size() - 3) == "...");
    CHECK(oneLine("short", 50) == "short");
}

TEST_CASE("header kinds from the first line") {
    CHECK(headerKindOf(std::string_view("#Inventor V2.1 binary  \n\0\0\0", 27)) == "V2.1 binary");
    CHECK(headerKindOf("#Inventor V2.0 binary\n") == "V2.0 binary");
    CHECK(headerKindOf("#Inventor V2.1 ascii\n\nSeparator {}") == "V2.1 ascii");
    CHECK(headerKindOf("#Inventor V1.0 ascii\r\n") == "V1.0 ascii");
    CHECK(headerKindOf("#VRML V1.0 ascii\n") == "VRML V1.0 ascii");
    CHECK(headerKindOf("Separator {}") == "no Inventor header");
    CHECK(headerKindOf("") == "no Inventor header");
    CHECK(headerKind(outputPath("does-not-exist.iv")) == "unreadable");
}

TEST_CASE("rows survive the trip between processes, messages made one line") {
    ModelRow row;
    row.model = "chess/king.iv";
    row.header = "V2.1 binary";
    row.readOk = false;
    row.readError = "king.iv:1:1: binary\tfiles\nare not read";
    row.coinRendered = row.volsgRendered = row.compared = true;
    row.renderError = "x.framed.iv:20:5: unknown node type 'Info'";
    row.missingTypes = "Info ShapeHints";
    row.comparison.pixelsA = 1000;
    row.comparison.pixelsB = 900;
    row.comparison.intersection = 850;
    row.comparison.unionCount = 1050;
    row.comparison.iou = 850.0 / 1050.0;
    row.comparison.colourDifference = 0.123456789012345;
    row.coinBackground = {1, 2, 3};
    row.writeBackOk = false;
    row.writeBackError = "volsg did not read the model";
    row.notes = "volsg render: x; Coin rendering: y";
    const std::string line = serialize(row);
    CHECK(line.find('\n') == std::string::npos);
    const ModelRow back = deserialize(line);
    CHECK(back.model == row.model);
    CHECK(back.header == row.header);
    CHECK(back.readOk == row.readOk);
    CHECK(back.readError == "king.iv:1:1: binary files are not read");
    CHECK(back.renderError == row.renderError);
    CHECK(back.missingTypes == row.missingTypes);
    CHECK(back.compared);
    CHECK(back.comparison.intersection == 850);
    CHECK(back.comparison.unionCount == 1050);
    CHECK(back.comparison.iou == row.comparison.iou); // exact: %.17g
    CHECK(back.comparison.colourDifference == row.comparison.colourDifference);
    CHECK(back.coinBackground == Rgb8{1, 2, 3});
    CHECK(back.writeBackError == row.writeBackError);
    CHECK(back.notes == row.notes);
    CHECK_THROWS_AS(deserialize("not a row"), volsg::Error);

    const Fields fields = decodeFields(encodeFields({{"a", "1"}, {"b", "two\nlines"}}));
    CHECK(fields.at("a") == "1");
    CHECK(fields.at("b") == "two lines");
}

TEST_CASE("summary, required agreement and the Markdown table") {
    std::vector<ModelRow> rows(4);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        rows[i].model = "m" + std::to_string(i) + ".iv";
        rows[i].coinRendered = true;
    }
    rows[0].readOk = rows[1].readOk = true;
    rows[0].volsgRendered = rows[0].compared = true; // agrees: IoU 1, no colour difference
    rows[0].comparison.pixelsA = rows[0].comparison.pixelsB = 10;
    rows[1].volsgRendered = rows[1].compared = true;
    rows[1].comparison.iou = 0.5;
    rows[0].writeBackOk = true;
    rows[2].notes = "a | pipe";
    const Summary s = summarize(rows);
    CHECK(s.models == 4);
    CHECK(s.read == 2);
    CHECK(s.agree == 1);
    CHECK(s.writtenBack == 1);
    // Two empty images compare as IoU 1, but a row agrees only when Coin's image shows something.
    ModelRow empty;
    empty.compared = true;
    CHECK(agrees(empty.comparison));
    CHECK_FALSE(empty.agree());
    CHECK(summaryLine(s) ==
          "read 2/4, agree 1/4, written back ok 1/4 (rendered: Coin 4/4, volsg 2/4)");
    CHECK(meetsAgreement(s, 0.0));
    CHECK(meetsAgreement(s, 0.25));
    CHECK_FALSE(meetsAgreement(s, 0.26));
    Summary ninety;
    ninety.models = 97;
    ninety.agree = 88; // 88/97 = 0.907
    CHECK(meetsAgreement(ninety, 0.9));
    ninety.agree = 87; // 0.897
    CHECK_FALSE(meetsAgreement(ninety, 0.9));

    CHECK(formatIoU(rows[1]) == "0.500");
    CHECK(formatIoU(rows[2]) == "-");
    const std::string md = markdownTable(rows, "intro");
    std::size_t tableLines = 0, start = 0;
    while (start < md.size()) {
        const std::size_t end = md.find('\n', start);
        if (md.compare(start, 2, "| ") == 0) ++tableLines;
        start = end == std::string::npos ? md.size() : end + 1;
    }
    CHECK(tableLines == rows.size() + 2); // header, separator ("| --- |"), one per row
    CHECK(md.find("a \\| pipe") != std::string::npos);
    CHECK(md.find("why it differs") != std::string::npos);
    CHECK(tableLine(rows[1]).find("\t0.500\t") != std::string::npos);
}

TEST_CASE("child processes: output, exceptions, crashes, exit status and hangs become results") {
    const ChildResult fine = runInChild([] { return std::string("fine\tdone"); }, 10.0);
    CHECK(fine.ok);
    CHECK(fine.output == "fine\tdone");

    const ChildResult thrown =
        runInChild([]() -> std::string { throw volsg::Error("bad thing", "f.iv", 3, 4); }, 10.0);
    CHECK_FALSE(thrown.ok);
    CHECK(thrown.problem == "f.iv:3:4: bad thing");
    const ChildResult lines =
        runInChild([]() -> std::string { throw std::runtime_error("two\nlines"); }, 10.0);
    CHECK(lines.problem == "two lines");

    const ChildResult crashed = runInChild(
        []() -> std::string {
            std::raise(SIGSEGV);
            return "not reached";
        },
        10.0);
    CHECK_FALSE(crashed.ok);
    CHECK(crashed.problem == "crashed (SIGSEGV)");

    const ChildResult exited = runInChild([]() -> std::string { ::_exit(7); }, 10.0);
    CHECK_FALSE(exited.ok);
    CHECK(exited.problem == "exited with status 7");

    const auto start = std::chrono::steady_clock::now();
    const ChildResult hung = runInChild(
        [] {
            std::this_thread::sleep_for(std::chrono::seconds(30));
            return std::string("late");
        },
        0.5);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK_FALSE(hung.ok);
    CHECK(hung.problem == "timed out after 0.5 s");
    CHECK(seconds < 10.0);

    // Several at once, polled together.
    RunningChild a = startChild([] { return std::string(100000, 'a'); }, 10.0);
    RunningChild b = startChild([] { return std::string("b"); }, 10.0);
    while (!childDone(a) || !childDone(b))
        pollChildren({&a, &b}, 100);
    CHECK(finishChild(a).output.size() == 100000);
    CHECK(finishChild(b).output == "b");
}

TEST_CASE("errors are counted by kind, without their place") {
    CHECK(errorKind("a/b c.iv:4:5: unknown node type 'Font' (a type this reader does not know "
                    "must describe its fields)") == "unknown node type 'Font'");
    CHECK(errorKind("x.iv:1:1: binary Inventor files are not supported (header '#Inventor V2.1 "
                    "binary')") == "binary Inventor files are not supported");
    CHECK(errorKind("unknown field 'vertexProperty' in IndexedFaceSet") ==
          "unknown field 'vertexProperty' in IndexedFaceSet");
    CHECK(errorKind("crashed (SIGSEGV)") == "crashed");
    CHECK(errorKind("note: not a place") == "note: not a place");
    const auto kinds = countKinds({"a.iv:1:2: unknown node type 'Info'",
                                   "b.iv:3:4: unknown node type 'Info' (more)",
                                   "c.iv:5:6: unknown node type 'Font'"});
    REQUIRE(kinds.size() == 2);
    CHECK(kinds[0] == std::pair<std::string, int>("unknown node type 'Info'", 2));
    CHECK(kinds[1] == std::pair<std::string, int>("unknown node type 'Font'", 1));
    CHECK(formatKinds(kinds, 1) == "2 x unknown node type 'Info'; 1 more kinds");
    CHECK(formatKinds({}, 5) == "none");
}

TEST_CASE("the node types a file uses, and those volsg's reader lacks") {
    const std::string text = "#Inventor V2.1 ascii\n"
                             "# Comment { not a node\n"
                             "Separator {\n"
                             "  DEF shape+0 Cube { width 2 }\n"
                             "  Info { string \"Fake { \\\" Quoted {\" }\n"
                             "  IndexedFaceSet {\n"
                             "    vertexProperty\n"
                             "    VertexProperty { vertex [ 0 0 0 ] }\n"
                             "  }\n"
                             "  USE shape+0\n"
                             "  Cube{}\n"
                             "  FooKit { fields [ SFNode part ] part Sphere { } }\n"
                             "}\n";
    const std::vector<std::string> names = nodeTypeNames(text);
    CHECK(names == std::vector<std::string>{"Cube", "FooKit", "IndexedFaceSet", "Info", "Separator",
                                            "Sphere", "VertexProperty"});
    const std::vector<std::string> lacking = typesVolsgLacks({"Cube", "NoSuchNodeTypeAtAll"});
    CHECK(lacking == std::vector<std::string>{"NoSuchNodeTypeAtAll"});
}
