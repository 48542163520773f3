// The malformed-input catalogue: every bad file gives one clear volsg::Error with file, line,
// column and what was expected; nothing crashes, hangs or allocates without bound.
#include <doctest/doctest.h>

#include <random>
#include <string>

#include <volsg/core/Error.h>
#include <volsg/io/GraphCompare.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>

#include "io/TestNodes.h"

using namespace volsg;

namespace {

const std::string header = "#Inventor V2.1 ascii\n";

/// The message of the error reading `text` gives (the test fails if there is none).
std::string errorOf(const std::string& text) {
    try {
        readSceneFromString(text, "bad.iv");
    } catch (const Error& e) {
        CHECK(e.file() == "bad.iv");
        CHECK(e.line() >= 1);
        CHECK(e.column() >= 1);
        return e.what();
    }
    FAIL("no error for: " << text.substr(0, 200));
    return {};
}

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

#define CHECK_ERROR(text, where, words)                                                            \
    do {                                                                                           \
        const std::string message = errorOf(text);                                                 \
        CHECK_MESSAGE(message.rfind(where, 0) == 0, message);                                      \
        CHECK_MESSAGE(contains(message, words), message);                                          \
    } while (false)

/// Reads `text`; a success must write and read back to an equal graph, a failure must be a
/// volsg::Error with a position. Anything else (another exception, a crash) fails the test.
void readsOrFailsCleanly(const std::string& text) {
    ref_ptr<Node> root;
    try {
        root = readSceneFromString(text, "fuzz.iv");
    } catch (const Error& e) {
        if (e.line() < 1) FAIL("error without a line: " << e.what());
        return;
    }
    const std::string written = writeSceneToString(*root);
    ref_ptr<Node> again = readSceneFromString(written, "written.iv");
    std::string why;
    if (!graphsEqual(*root, *again, &why))
        FAIL("round trip of a fuzzed file differs: " << why << "\n" << text);
}

/// A valid scene with every kind of token, for truncation and mutation.
const std::string richScene = R"(DEF top Separator {
  DEF cam PerspectiveCamera { position 0 0 5 orientation 0 1 0 0.5 }
  Material { diffuseColor [ 1 0 0, 0 1 0 ] transparency 0.5 }
  Cone { parts (SIDES | BOTTOM) }
  AllFieldsNode { sfString "a\"quoted\"string" sfNode USE cam mfNode [ Cube { } NULL ]
                  sfMatrix 1 0 0 0 0 1 0 0 0 0 1 0 1 2 3 1 sfInt32 0x1F sfBool TRUE }
  Foo { fields [ SFFloat a, MFNode kids ] a 1 kids [ Sphere { } ] Cube { } }
  Switch { whichChild -3 USE cam }
}
)";

} // namespace

TEST_CASE("a truncated file names the node left open") {
    CHECK_ERROR(header + "Separator {\n  Cube { width 2",
                "bad.iv:3:17:", "unexpected end of file: Cube opened at 3:8 has no closing '}'");
    CHECK_ERROR(header + "Cube { width", "bad.iv:2:13:",
                "field 'width' of Cube expects SFFloat: expected a number, found end of file");
    CHECK_ERROR(header + "DEF a", "bad.iv:2:6:", "expected a node type after 'DEF a'");
}

TEST_CASE("unbalanced braces are an error at the stray or missing brace") {
    CHECK_ERROR(header + "Cube { }\n}\n", "bad.iv:3:1:", "unexpected '}': no node is open");
    CHECK_ERROR(header + "Separator {\n  Cube { }\n",
                "bad.iv:4:1:", "Separator opened at 2:11 has no closing '}'");
    CHECK_ERROR(header + "Cube width 2 }",
                "bad.iv:2:6:", "expected '{' after node type 'Cube', found 'width'");
}

TEST_CASE("an unknown node type without a fields description is an error at its name") {
    CHECK_ERROR(header + "Separator {\n  Foo { a 1 }\n}\n",
                "bad.iv:3:3:", "unknown node type 'Foo'");
    CHECK_ERROR(header + "Separator { widht 2 }", "bad.iv:2:13:", "unknown node type 'widht'");
}

TEST_CASE("an unknown node type close to a known one suggests it") {
    CHECK_ERROR(header + "Separator {\n  Volum { }\n}\n",
                "bad.iv:3:3:", "unknown node type 'Volum' (did you mean Volume?");
    CHECK_ERROR(header + "PerspectivCamera { }", "bad.iv:2:1:", "(did you mean PerspectiveCamera?");
    CHECK_ERROR(header + "transferfunction { }", "bad.iv:2:1:", "(did you mean TransferFunction?");
    // Nothing near: no suggestion.
    CHECK(errorOf(header + "Gizmo { }").find("did you mean") == std::string::npos);
}

TEST_CASE("an unknown field is an error naming the field and the node type") {
    CHECK_ERROR(header + "Cube { widht 2 }", "bad.iv:2:8:", "unknown field 'widht' in Cube");
    CHECK_ERROR(header + "Cube { 2 }", "bad.iv:2:8:", "unknown field '2' in Cube");
    CHECK_ERROR(header + "Cube { [ }", "bad.iv:2:8:", "expected a field name of Cube or '}'");
}

TEST_CASE("a value of the wrong type says what the field expects") {
    CHECK_ERROR(header + "Cube { width TRUE }", "bad.iv:2:14:",
                "field 'width' of Cube expects SFFloat: expected a number, found 'TRUE'");
    CHECK_ERROR(header + "Switch { whichChild 1.5 }", "bad.iv:2:21:",
                "field 'whichChild' of Switch expects SFInt32: expected an integer");
    CHECK_ERROR(header + "ClipPlane { on maybe }",
                "bad.iv:2:16:", "field 'on' of ClipPlane expects SFBool");
    CHECK_ERROR(header + "Cone { parts (SIDES | TOP) }",
                "bad.iv:2:23:", "field 'parts' of Cone expects SFBitMask: unknown value 'TOP'");
    CHECK_ERROR(header + "Separator { renderCaching MAYBE }",
                "bad.iv:2:27:", "expected one of OFF, ON, AUTO");
}

TEST_CASE("USE of an undefined name is an error at the name") {
    CHECK_ERROR(header + "Separator { USE nothing }",
                "bad.iv:2:17:", "USE of undefined name 'nothing'");
    // A name is bound when its node is complete, so a node cannot contain itself.
    CHECK_ERROR(header + "DEF loop Separator { USE loop }",
                "bad.iv:2:26:", "USE of undefined name 'loop'");
    CHECK_ERROR(header + "USE", "bad.iv:2:4:", "expected a name after USE, found end of file");
}

TEST_CASE("NaN and 1e39 in a float field are errors at the value") {
    CHECK_ERROR(header + "Cube { width nan }", "bad.iv:2:14:",
                "field 'width' of Cube expects SFFloat: value 'nan' is not a finite number");
    CHECK_ERROR(header + "Cube {\n  height 1e39\n}",
                "bad.iv:3:10:", "value 1e39 is out of range for a 32-bit float");
    CHECK_ERROR(header + "Coordinate3 { point [ 0 0 0, 1 inf 1 ] }",
                "bad.iv:2:32:", "not a finite number");
}

TEST_CASE("a binary Inventor file cut short is an error at a byte offset") {
    // The header line is 22 bytes with its '\n'; the 3 bytes after it cannot hold a name.
    try {
        readSceneFromString(std::string("#Inventor V2.1 binary\n\x01\x02\x03", 25), "bad.iv");
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(std::string(e.what()) ==
              "bad.iv: byte 22: unexpected end of file: a node type name needs 4 bytes, 3 left");
    }
    CHECK_ERROR("#Inventor V1.0 binary\n",
                "bad.iv:1:1:", "Inventor V1.0 binary files are not supported");
}

TEST_CASE("an empty file is an error") {
    CHECK_ERROR("", "bad.iv:1:1:", "empty file: expected the header '#Inventor V2.1 ascii'");
}

TEST_CASE("a file without a header is an error") {
    CHECK_ERROR("Separator { Cube { } }\n",
                "bad.iv:1:1:", "missing header: the first line must be '#Inventor V2.1 ascii'");
    CHECK_ERROR("#Inventor V3.0 ascii\nCube { }", "bad.iv:1:1:", "unsupported header");
    CHECK_ERROR("#VRML V2.0 utf8\nShape { }", "bad.iv:1:1:", "unsupported header");
}

TEST_CASE("megabytes of random bytes give an error, never a crash") {
    std::mt19937 rng(20261121);
    std::string bytes(4 << 20, '\0');
    for (char& c : bytes)
        c = char(rng() & 0xff);
    CHECK_THROWS_AS(readSceneFromString(bytes, "random.bin"), Error);
    CHECK_THROWS_AS(readSceneFromString(header + bytes, "random.bin"), Error);
    // Printable noise gets further into the parser before it fails.
    for (char& c : bytes)
        c = char(' ' + rng() % 95);
    CHECK_THROWS_AS(readSceneFromString(header + bytes, "random.txt"), Error);
}

TEST_CASE("nesting 100000 levels deep is an error at the level past the limit") {
    std::string deep = header;
    for (int i = 0; i < 100000; ++i)
        deep += "Separator { ";
    // The 1001st '{' is at column 1000 * 12 + 11.
    CHECK_ERROR(deep, "bad.iv:2:12011:", "nodes nested deeper than 1000 levels");

    test::registerTestNodeTypes();
    std::string viaFields = header;
    for (int i = 0; i < 100000; ++i)
        viaFields += "AllFieldsNode { sfNode ";
    CHECK_ERROR(viaFields, "bad.iv:2:", "nodes nested deeper than 1000 levels");
}

TEST_CASE("nesting exactly at the limit reads") {
    std::string deep = header;
    for (int i = 0; i < maxSceneNestingDepth; ++i)
        deep += "Group {\n";
    for (int i = 0; i < maxSceneNestingDepth; ++i)
        deep += "}\n";
    auto root = readSceneFromString(deep);
    int depth = 1;
    for (const Node* n = root.get(); !n->children()->empty(); n = n->children()->front().get())
        ++depth;
    CHECK(depth == maxSceneNestingDepth);
}

TEST_CASE("a huge list in a short file is an error, not an allocation") {
    // A list that is never closed, and counts that do not fit the field's integers.
    CHECK_ERROR(header + "Coordinate3 { point [ 0 0 0, 1 1 1",
                "bad.iv:2:35:", "the MFVec3f list started at 2:21 has no closing ']'");
    CHECK_ERROR(header + "IndexedFaceSet { coordIndex [ 0, 99999999999999999999999999 ] }",
                "bad.iv:2:34:", "out of range for a 32-bit integer");
    // A megabyte of one number is refused by the tokenizer's word limit.
    CHECK_ERROR(header + "Cube { width " + std::string(2 << 20, '7') + " }",
                "bad.iv:2:14:", "word longer than");
    // A million empty list slots: each comma needs a value first.
    CHECK_ERROR(header + "Coordinate3 { point [ " + std::string(1 << 20, ',') + " ] }",
                "bad.iv:2:23:", "expected a number, found ','");
}

TEST_CASE("an unterminated string is an error naming where it started") {
    test::registerTestNodeTypes();
    CHECK_ERROR(header + "AllFieldsNode {\n sfString \"abc\n\n", "bad.iv:", "started at 3:11");
}

TEST_CASE("a fields description must match a known type and name known field types") {
    test::registerTestNodeTypes();
    CHECK_ERROR(header + "TestGroup { fields [ SFInt32 weight ] }", "bad.iv:2:22:",
                "field 'weight' of TestGroup is SFFloat, but the file declares it SFInt32");
    CHECK_ERROR(header + "TestGroup { fields [ SFFloat height ] }",
                "bad.iv:2:30:", "TestGroup has no field 'height'");
    CHECK_ERROR(header + "Foo { fields [ SFBogus a ] }",
                "bad.iv:2:16:", "unknown field type 'SFBogus' in the fields description of Foo");
    CHECK_ERROR(header + "Foo { fields [ SFFloat a, SFInt32 a ] }",
                "bad.iv:2:35:", "field 'a' is declared twice in Foo");
    CHECK_ERROR(header + "Foo { fields [ SFFloat a ] b 1 }",
                "bad.iv:2:28:", "unknown node type 'b'");
    CHECK_ERROR(header + "Foo { fields SFFloat a }", "bad.iv:2:14:", "expected '[' after 'fields'");
}

TEST_CASE("fields after children and NULL children are errors") {
    CHECK_ERROR(header + "Switch { Cube { } whichChild 0 }",
                "bad.iv:2:19:", "field 'whichChild' of Switch must come before its children");
    CHECK_ERROR(header + "Separator { NULL }",
                "bad.iv:2:13:", "NULL is only allowed as the value of a node field");
    CHECK_ERROR(header + "DEF USE Cube { }", "bad.iv:2:5:", "expected a name after DEF");
}

TEST_CASE("every truncation of a valid file reads or fails cleanly") {
    test::registerTestNodeTypes();
    const std::string full = header + "# a comment\n" + richScene;
    for (std::size_t n = 0; n <= full.size(); ++n)
        readsOrFailsCleanly(full.substr(0, n));
}

TEST_CASE("random token soup reads or fails cleanly, and what reads round-trips") {
    test::registerTestNodeTypes();
    const char* vocabulary[] = {"Separator",
                                "Cube",
                                "Group",
                                "Switch",
                                "Material",
                                "Coordinate3",
                                "AllFieldsNode",
                                "TestGroup",
                                "Foo",
                                "{",
                                "}",
                                "[",
                                "]",
                                "(",
                                ")",
                                ",",
                                "|",
                                "DEF",
                                "USE",
                                "NULL",
                                "a",
                                "b",
                                "fields",
                                "SFFloat",
                                "MFVec3f",
                                "SFNode",
                                "width",
                                "point",
                                "sfNode",
                                "mfNode",
                                "diffuseColor",
                                "whichChild",
                                "1",
                                "-2.5",
                                "0x1F",
                                "1e39",
                                "nan",
                                "TRUE",
                                "\"str\"",
                                "\"open",
                                "sfBitMask",
                                "A",
                                "sfEnum",
                                "FIRST",
                                "weight",
                                "# comment\n",
                                "\n",
                                "mfFloat",
                                "0"};
    constexpr std::size_t words = sizeof(vocabulary) / sizeof(vocabulary[0]);
    std::mt19937 rng(42);
    int parsed = 0;
    for (int doc = 0; doc < 3000; ++doc) {
        std::string text = header;
        // Start most documents with a node so the parser gets past the first token.
        if (rng() % 4 != 0) text += "Separator { ";
        const int length = int(rng() % 60);
        for (int i = 0; i < length; ++i) {
            text += vocabulary[rng() % words];
            text += ' ';
        }
        if (rng() % 2) text += "}";
        try {
            readSceneFromString(text, "fuzz.iv");
            ++parsed;
        } catch (const Error&) {
        }
        readsOrFailsCleanly(text);
    }
    MESSAGE(parsed << " of 3000 random documents were valid scenes");
}

TEST_CASE("random edits of a valid file read or fail cleanly, and what reads round-trips") {
    test::registerTestNodeTypes();
    // Split the valid scene into tokens (roughly: at white space and around punctuation).
    std::vector<std::string> pieces;
    std::string current;
    for (char c : richScene) {
        const bool punct = std::string("{}[](),|").find(c) != std::string::npos;
        if (c == ' ' || c == '\n' || punct) {
            if (!current.empty()) pieces.push_back(current);
            current.clear();
            if (punct) pieces.emplace_back(1, c);
        } else {
            current += c;
        }
    }
    std::mt19937 rng(99);
    int parsed = 0;
    for (int doc = 0; doc < 2000; ++doc) {
        std::vector<std::string> edited = pieces;
        for (int edits = 1 + int(rng() % 3); edits > 0; --edits) {
            const std::size_t at = rng() % edited.size();
            const std::string& other = pieces[rng() % pieces.size()];
            switch (rng() % 3) {
            case 0:
                edited.erase(edited.begin() + std::ptrdiff_t(at));
                break;
            case 1:
                edited.insert(edited.begin() + std::ptrdiff_t(at), other);
                break;
            default:
                edited[at] = other;
            }
        }
        std::string text = header;
        for (const auto& piece : edited)
            text += piece + '\n';
        try {
            readSceneFromString(text, "edit.iv");
            ++parsed;
        } catch (const Error&) {
        }
        readsOrFailsCleanly(text);
    }
    MESSAGE(parsed << " of 2000 edited documents were valid scenes");
    CHECK(parsed > 0);
}
