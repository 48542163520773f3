// Every field type reads its Inventor ASCII text and prints it back; the tokenizer's numbers,
// strings, positions and limits.
#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <random>
#include <sstream>

#include <volsg/core/Error.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/Tokenizer.h>

#include "io/TestNodes.h"

using namespace volsg;
using test::AllFieldsNode;

namespace {

/// Field values read straight from text; node values are not expected here.
class TextInput final : public FieldInput {
public:
    explicit TextInput(std::string text) : text_(std::move(text)), tokens_(text_, "field.txt") {}
    Tokenizer& tokens() override { return tokens_; }
    ref_ptr<Node> readNode() override { throw Error("no nodes in this test"); }

private:
    std::string text_;
    Tokenizer tokens_;
};

class TextOutput final : public FieldOutput {
public:
    std::ostream& stream() override { return out_; }
    void writeNode(const Node*) override { out_ << "<node>"; }
    void newline() override { out_ << '\n'; }
    std::string text() const { return out_.str(); }

private:
    std::ostringstream out_;
};

/// Reads `text` into the field and checks that all of it was used.
void parse(Field& field, const std::string& text) {
    TextInput in(text);
    field.read(in);
    CHECK_MESSAGE(in.tokens().atEnd(), "text left after the value of ", text);
}

std::string printed(const Field& field) {
    TextOutput out;
    field.write(out);
    return out.text();
}

/// The error message of parsing `text` into the field.
std::string parseError(Field& field, const std::string& text) {
    try {
        parse(field, text);
    } catch (const Error& e) {
        return e.what();
    }
    FAIL("no error for: " << text);
    return {};
}

ref_ptr<AllFieldsNode> fresh() {
    return AllFieldsNode::create();
}

} // namespace

TEST_CASE("SFFloat reads integers, signs, exponents and a leading point") {
    auto n = fresh();
    const std::pair<const char*, float> cases[] = {
        {"1", 1.0f},     {"-1.5e3", -1500.0f},      {".5", 0.5f},   {"+2.", 2.0f}, {"-.25", -0.25f},
        {"1E2", 100.0f}, {"3.4028235e38", FLT_MAX}, {"1e-50", 0.0f}};
    for (const auto& c : cases) { // not a structured binding: CHECK_MESSAGE captures it
        parse(n->sfFloat, c.first);
        CHECK_MESSAGE(n->sfFloat() == c.second, c.first);
    }
    CHECK_FALSE(n->sfFloat.isDefault());
}

TEST_CASE("SFFloat prints the shortest text that reads back to the same float") {
    auto n = fresh();
    n->sfFloat = 0.1f;
    CHECK(printed(n->sfFloat) == "0.1");
    n->sfFloat = 2.0f;
    CHECK(printed(n->sfFloat) == "2");
    n->sfFloat = -1500.0f;
    CHECK(printed(n->sfFloat) == "-1500");

    // Random bit patterns: every finite float survives print-then-read bit for bit.
    std::mt19937 rng(1234);
    int checked = 0;
    for (int i = 0; i < 20000; ++i) {
        const float v = std::bit_cast<float>(std::uint32_t(rng()));
        if (!std::isfinite(v)) continue;
        n->sfFloat = v;
        const std::string text = printed(n->sfFloat);
        auto back = fresh();
        parse(back->sfFloat, text);
        if (std::bit_cast<std::uint32_t>(back->sfFloat()) != std::bit_cast<std::uint32_t>(v))
            FAIL("float " << text << " did not read back to the same bits");
        ++checked;
    }
    CHECK(checked > 19000);
}

TEST_CASE("SFFloat refuses NaN, infinity and values beyond float range") {
    auto n = fresh();
    CHECK(parseError(n->sfFloat, "nan").find("not a finite number") != std::string::npos);
    CHECK(parseError(n->sfFloat, "-Inf").find("not a finite number") != std::string::npos);
    const std::string big = parseError(n->sfFloat, "  1e39");
    CHECK(big.find("field.txt:1:3:") == 0);
    CHECK(big.find("1e39 is out of range for a 32-bit float") != std::string::npos);
    CHECK(parseError(n->sfFloat, "-3.5e38").find("out of range") != std::string::npos);
    CHECK(parseError(n->sfFloat, "1.2.3").find("expected a number, found '1.2.3'") !=
          std::string::npos);
    CHECK(parseError(n->sfFloat, "e5").find("expected a number") != std::string::npos);
    CHECK(parseError(n->sfFloat, "").find("expected a number, found end of file") !=
          std::string::npos);
}

TEST_CASE("SFInt32 reads decimal and hex and checks the 32-bit range") {
    auto n = fresh();
    parse(n->sfInt32, "-17");
    CHECK(n->sfInt32() == -17);
    parse(n->sfInt32, "0x1F");
    CHECK(n->sfInt32() == 31);
    parse(n->sfInt32, "0XfF");
    CHECK(n->sfInt32() == 255);
    parse(n->sfInt32, "0xFFFFFFFF"); // hex is a bit pattern
    CHECK(n->sfInt32() == -1);
    parse(n->sfInt32, "-2147483648");
    CHECK(n->sfInt32() == INT32_MIN);
    parse(n->sfInt32, "2147483647");
    CHECK(n->sfInt32() == INT32_MAX);
    CHECK(printed(n->sfInt32) == "2147483647");
    CHECK(parseError(n->sfInt32, "2147483648").find("out of range for a 32-bit integer") !=
          std::string::npos);
    CHECK(parseError(n->sfInt32, "0x100000000").find("out of range") != std::string::npos);
    CHECK(parseError(n->sfInt32, "99999999999999999999999").find("out of range") !=
          std::string::npos);
    CHECK(parseError(n->sfInt32, "1.5").find("expected an integer, found '1.5'") !=
          std::string::npos);
}

TEST_CASE("SFUInt32 reads the full unsigned range and refuses negatives") {
    auto n = fresh();
    parse(n->sfUInt32, "4294967295");
    CHECK(n->sfUInt32() == 4294967295u);
    parse(n->sfUInt32, "0xff0000ff");
    CHECK(n->sfUInt32() == 0xff0000ffu);
    CHECK(printed(n->sfUInt32) == "4278190335");
    CHECK(parseError(n->sfUInt32, "-1").find("out of range") != std::string::npos);
    CHECK(parseError(n->sfUInt32, "4294967296").find("out of range") != std::string::npos);
}

TEST_CASE("SFBool reads TRUE FALSE 0 1 and prints TRUE or FALSE") {
    auto n = fresh();
    parse(n->sfBool, "TRUE");
    CHECK(n->sfBool());
    CHECK(printed(n->sfBool) == "TRUE");
    parse(n->sfBool, "0");
    CHECK_FALSE(n->sfBool());
    CHECK(printed(n->sfBool) == "FALSE");
    parse(n->sfBool, "1");
    CHECK(n->sfBool());
    parse(n->sfBool, "FALSE");
    CHECK_FALSE(n->sfBool());
    CHECK(parseError(n->sfBool, "yes").find("expected TRUE, FALSE, 0 or 1, found 'yes'") !=
          std::string::npos);
}

TEST_CASE("SFString reads quoted text with escapes and prints it back escaped") {
    auto n = fresh();
    parse(n->sfString, R"("say \"hi\" \\ back\slash")");
    CHECK(n->sfString() == R"(say "hi" \ back\slash)");
    CHECK(printed(n->sfString) == R"("say \"hi\" \\ back\\slash")");
    parse(n->sfString, "bare");
    CHECK(n->sfString() == "bare");
    parse(n->sfString, "\"two\nlines # not a comment\"");
    CHECK(n->sfString() == "two\nlines # not a comment");
    for (const std::string s : {"", "\"", "\\", "a\\\"b", "{ } [ ] , |", "\t\n"}) {
        n->sfString = s;
        auto back = fresh();
        parse(back->sfString, printed(n->sfString));
        CHECK(back->sfString() == s);
    }
}

TEST_CASE("SFVec2f SFVec3f SFVec4f and SFColor read their components in order") {
    auto n = fresh();
    parse(n->sfVec2f, "1 -2");
    CHECK(n->sfVec2f() == glm::vec2(1, -2));
    parse(n->sfVec3f, "1 2.5 -3");
    CHECK(n->sfVec3f() == glm::vec3(1, 2.5f, -3));
    CHECK(printed(n->sfVec3f) == "1 2.5 -3");
    parse(n->sfVec4f, "1 2 3 4");
    CHECK(n->sfVec4f() == glm::vec4(1, 2, 3, 4));
    parse(n->sfColor, "0.8 0.2 0.25");
    CHECK(n->sfColor() == glm::vec3(0.8f, 0.2f, 0.25f));
    CHECK(printed(n->sfColor) == "0.8 0.2 0.25");
    CHECK(parseError(n->sfVec3f, "1 2").find("expected a number, found end of file") !=
          std::string::npos);
}

TEST_CASE("SFRotation is axis then angle in radians") {
    auto n = fresh();
    parse(n->sfRotation, "0 1 0 1.5708");
    CHECK(n->sfRotation().axis == glm::vec3(0, 1, 0));
    CHECK(n->sfRotation().angle == 1.5708f);
    CHECK(printed(n->sfRotation) == "0 1 0 1.5708");
    // It turns +X to -Z, as a quarter turn about +Y does (tolerance 1e-4).
    const glm::dvec4 x = n->sfRotation().matrix() * glm::dvec4(1, 0, 0, 0);
    CHECK(x.z == doctest::Approx(-1.0).epsilon(1e-4));
}

TEST_CASE("SFPlane is the normal then the distance") {
    auto n = fresh();
    parse(n->sfPlane, "0 0 1 -0.75");
    CHECK(n->sfPlane().normal == glm::vec3(0, 0, 1));
    CHECK(n->sfPlane().distance == -0.75f);
    CHECK(printed(n->sfPlane) == "0 0 1 -0.75");
}

TEST_CASE("SFMatrix reads Inventor row order so the translation lands in GLM column 3") {
    auto n = fresh();
    parse(n->sfMatrix, "1 0 0 0  0 2 0 0  0 0 3 0  4 5 6 1");
    const glm::mat4& m = n->sfMatrix();
    CHECK(m[3] == glm::vec4(4, 5, 6, 1));
    // Acting on a column vector: scale, then translate.
    const glm::vec4 p = m * glm::vec4(1, 1, 1, 1);
    CHECK(p == glm::vec4(5, 7, 9, 1));
    CHECK(printed(n->sfMatrix) == "1 0 0 0 0 2 0 0 0 0 3 0 4 5 6 1");
}

TEST_CASE("SFEnum reads names and prints them and refuses unknown names") {
    auto n = fresh();
    parse(n->sfEnum, "THIRD");
    CHECK(n->sfEnum() == AllFieldsNode::THIRD);
    CHECK(printed(n->sfEnum) == "THIRD");
    const std::string e = parseError(n->sfEnum, "FOURTH");
    CHECK(e.find("unknown value 'FOURTH'") != std::string::npos);
    CHECK(e.find("FIRST, SECOND, THIRD") != std::string::npos);
    // A value without a name is written as a number, which reads back.
    n->sfEnum = 5;
    CHECK(printed(n->sfEnum) == "5");
    parse(n->sfEnum, "5");
    CHECK(n->sfEnum() == 5);
}

TEST_CASE("SFBitMask reads a parenthesised union or a single name") {
    auto n = fresh();
    parse(n->sfBitMask, "(A | C)");
    CHECK(n->sfBitMask() == (AllFieldsNode::A | AllFieldsNode::C));
    CHECK(printed(n->sfBitMask) == "(A | C)");
    parse(n->sfBitMask, "B");
    CHECK(n->sfBitMask() == AllFieldsNode::B);
    CHECK(printed(n->sfBitMask) == "B");
    parse(n->sfBitMask, "(A|B|C)");
    CHECK(n->sfBitMask() == 7);
    CHECK(printed(n->sfBitMask) == "(AB | C)"); // widest names first
    parse(n->sfBitMask, "( )");
    CHECK(n->sfBitMask() == 0);
    CHECK(parseError(n->sfBitMask, "(A C)").find("expected '|' or ')'") != std::string::npos);
    CHECK(parseError(n->sfBitMask, "(A | D)").find("unknown value 'D'") != std::string::npos);
}

TEST_CASE("SFNode reads a node, a USE and NULL") {
    test::registerTestNodeTypes();
    auto root = readSceneFromString("#Inventor V2.1 ascii\n"
                                    "Separator {\n"
                                    "  DEF c Cube { width 3 }\n"
                                    "  AllFieldsNode { sfNode USE c }\n"
                                    "  AllFieldsNode { sfNode Sphere { radius 2 } }\n"
                                    "  AllFieldsNode { sfNode NULL }\n"
                                    "}\n");
    const auto& kids = *root->children();
    REQUIRE(kids.size() == 4);
    auto* a = dynamic_cast<AllFieldsNode*>(kids[1].get());
    auto* b = dynamic_cast<AllFieldsNode*>(kids[2].get());
    auto* c = dynamic_cast<AllFieldsNode*>(kids[3].get());
    REQUIRE((a && b && c));
    CHECK(a->sfNode.getValue() == kids[0].get());
    REQUIRE(b->sfNode.getValue() != nullptr);
    CHECK(std::string(b->sfNode.getValue()->type().name()) == "Sphere");
    CHECK(c->sfNode.getValue() == nullptr);
    CHECK_FALSE(c->sfNode.isDefault());
}

TEST_CASE("MF fields read bracketed lists with optional commas and a single bare value") {
    auto n = fresh();
    parse(n->mfFloat, "[ 1, 2 3, ]");
    CHECK(n->mfFloat() == std::vector<float>{1, 2, 3});
    parse(n->mfFloat, "4.5");
    CHECK(n->mfFloat() == std::vector<float>{4.5f});
    parse(n->mfFloat, "[]");
    CHECK(n->mfFloat().empty());
    parse(n->mfInt32, "[ 0, 1, 0x10, -1 ]");
    CHECK(n->mfInt32() == std::vector<std::int32_t>{0, 1, 16, -1});
    parse(n->mfVec3f, "[ 0 0 0, 1 1 1 2 2 2 ]");
    CHECK(n->mfVec3f() == std::vector<glm::vec3>{glm::vec3(0), glm::vec3(1), glm::vec3(2)});
    parse(n->mfVec3f, "1 2 3");
    CHECK(n->mfVec3f() == std::vector<glm::vec3>{glm::vec3(1, 2, 3)});
    parse(n->mfString, R"([ "a b", c, "d\"" ])");
    CHECK(n->mfString() == std::vector<std::string>{"a b", "c", "d\""});
    parse(n->mfBool, "[ TRUE 0 1 FALSE ]");
    CHECK(n->mfBool() == std::vector<bool>{true, false, true, false});
    CHECK(n->mfBool[2]);
    parse(n->mfColor, "[ 1 0 0, 0 1 0 ]");
    CHECK(n->mfColor.size() == 2);
    parse(n->mfRotation, "[ 0 0 1 0, 1 0 0 3.14 ]");
    CHECK(n->mfRotation[1].angle == 3.14f);
    parse(n->mfPlane, "[ 1 0 0 0 ]");
    CHECK(n->mfPlane[0].normal == glm::vec3(1, 0, 0));
    parse(n->mfMatrix, "[ 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 ]");
    CHECK(n->mfMatrix[0] == glm::mat4(1.0f));
    parse(n->mfVec2f, "[ 1 2, 3 4 ]");
    CHECK(n->mfVec2f[1] == glm::vec2(3, 4));
    parse(n->mfVec4f, "[ 1 2 3 4 ]");
    CHECK(n->mfVec4f[0] == glm::vec4(1, 2, 3, 4));
    parse(n->mfUInt32, "[ 1 0xFFFFFFFF ]");
    CHECK(n->mfUInt32[1] == 0xFFFFFFFFu);
    CHECK(parseError(n->mfFloat, "[ 1, , 2 ]").find("expected a number, found ','") !=
          std::string::npos);
    CHECK(parseError(n->mfVec3f, "[ 0 0 0, 1 1 ]").find("expected a number, found ']'") !=
          std::string::npos);
    const std::string open = parseError(n->mfFloat, "[ 1 2\n 3");
    CHECK(open.find("field.txt:2:3:") == 0);
    CHECK(open.find("MFFloat list started at 1:1 has no closing ']'") != std::string::npos);
}

TEST_CASE("MF fields print bracketed lists that read back equal") {
    auto n = fresh();
    n->mfFloat = {1.5f, -2.0f};
    CHECK(printed(n->mfFloat) == "[ 1.5, -2 ]");
    n->mfFloat = {};
    CHECK(printed(n->mfFloat) == "[ ]");
    n->mfVec3f = {glm::vec3(1, 2, 3)};
    CHECK(printed(n->mfVec3f) == "[ 1 2 3 ]");
    n->mfString = {"x y", "\"q\""};
    CHECK(printed(n->mfString) == R"([ "x y", "\"q\"" ])");
    n->mfBool = {true, false};
    CHECK(printed(n->mfBool) == "[ TRUE, FALSE ]");

    // A long list breaks into lines; every value comes back.
    std::vector<float> many(100);
    for (std::size_t i = 0; i < many.size(); ++i)
        many[i] = float(i) * 0.25f;
    n->mfFloat = many;
    const std::string text = printed(n->mfFloat);
    CHECK(std::count(text.begin(), text.end(), '\n') >= 10);
    auto back = fresh();
    parse(back->mfFloat, text);
    CHECK(back->mfFloat.equals(n->mfFloat));
    CHECK_FALSE(back->mfFloat.equals(n->mfInt32)); // another type is never equal
}

TEST_CASE("MFNode reads a list of nodes including USE and NULL") {
    test::registerTestNodeTypes();
    auto root =
        readSceneFromString("#Inventor V2.1 ascii\n"
                            "AllFieldsNode { mfNode [ DEF s Sphere { }, USE s NULL Cube { } ] }\n");
    auto* n = dynamic_cast<AllFieldsNode*>(root.get());
    REQUIRE(n);
    const auto& v = n->mfNode.getValues();
    REQUIRE(v.size() == 4);
    CHECK(v[0] == v[1]);
    CHECK(v[0]->getName() == "s");
    CHECK(v[2] == nullptr);
    CHECK(std::string(v[3]->type().name()) == "Cube");
}

TEST_CASE("createFieldOfType makes a field of every type name") {
    auto owner = fresh();
    const char* names[] = {
        "SFFloat", "MFFloat",    "SFInt32",  "MFInt32", "SFUInt32",   "MFUInt32",   "SFBool",
        "MFBool",  "SFString",   "MFString", "SFVec2f", "MFVec2f",    "SFVec3f",    "MFVec3f",
        "SFVec4f", "MFVec4f",    "SFColor",  "MFColor", "SFRotation", "MFRotation", "SFPlane",
        "MFPlane", "SFMatrix",   "MFMatrix", "SFEnum",  "MFEnum",     "SFBitMask",  "SFNode",
        "MFNode",  "SFName",     "MFName",   "SFShort", "SFUShort",   "SFDouble",   "SFTime",
        "SFVec3d", "SFColorRGBA"};
    for (const char* name : names) {
        auto f = createFieldOfType(name, owner.get(), "f");
        REQUIRE_MESSAGE(f, name);
        CHECK(std::string(f->typeName()) == name);
        CHECK(f->isDefault());
    }
    CHECK_FALSE(createFieldOfType("SFNoSuchType", owner.get(), "f"));
}

TEST_CASE("enum fields of unknown nodes keep their words as written") {
    auto owner = fresh();
    auto e = createFieldOfType("SFEnum", owner.get(), "mode");
    parse(*e, "ANY_WORD");
    CHECK(printed(*e) == "ANY_WORD");
    auto b = createFieldOfType("SFBitMask", owner.get(), "parts");
    parse(*b, "( SIDES | TOP )");
    CHECK(printed(*b) == "(SIDES | TOP)");
    parse(*b, "ALL");
    CHECK(printed(*b) == "ALL");
}

TEST_CASE("EnumValues finds names by value and values by name") {
    const EnumValues& names = AllFieldsNode::modeNames;
    CHECK(std::string(names.nameOf(7)) == "THIRD");
    CHECK(names.nameOf(3) == nullptr);
    int v = -1;
    CHECK(names.valueOf("SECOND", v));
    CHECK(v == 1);
    CHECK_FALSE(names.valueOf("second", v));
}

TEST_CASE("fields copy values of their own type and refuse others") {
    auto a = fresh(), b = fresh();
    a->mfVec3f = {glm::vec3(1, 2, 3)};
    b->mfVec3f.copyFrom(a->mfVec3f);
    CHECK(b->mfVec3f.equals(a->mfVec3f));
    CHECK_THROWS_AS(b->sfFloat.copyFrom(a->sfInt32), Error);
}

TEST_CASE("tokenizer reports line and column of tokens past comments") {
    const std::string text = "# comment\n  Cube { # another\n\twidth 2 }\n";
    Tokenizer t(text, "t.iv");
    Token a = t.next();
    CHECK(a.text == "Cube");
    CHECK(a.line == 2);
    CHECK(a.column == 3);
    CHECK(t.next().isPunct('{'));
    Token w = t.next();
    CHECK(w.text == "width");
    CHECK(w.line == 3);
    CHECK(w.column == 2);
    CHECK(t.readFloat() == 2.0f);
    CHECK(t.acceptPunct('}'));
    CHECK(t.atEnd());
}

TEST_CASE("an unterminated string names the line and column where it started") {
    const std::string text = "a\n  \"never closed\nmore text";
    Tokenizer t(text, "s.iv");
    t.next();
    try {
        t.next();
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(std::string(e.what()).find("started at 2:3") != std::string::npos);
        CHECK(e.message().find("unterminated string") != std::string::npos);
    }
}

TEST_CASE("a word longer than the tokenizer limit is an error, not an allocation") {
    const std::string text(Tokenizer::maxWordLength + 10, 'x');
    Tokenizer t(text, "w.iv");
    CHECK_THROWS_WITH_AS(t.next(), doctest::Contains("w.iv:1:1: word longer than"), Error);
}

TEST_CASE("a string longer than 64 MiB is an error") {
    std::string text(Tokenizer::maxStringLength + 16, 'y');
    text[0] = '"';
    Tokenizer t(text, "big.iv");
    CHECK_THROWS_WITH_AS(t.next(), doctest::Contains("big.iv:1:1: string longer than"), Error);
}

TEST_CASE("control characters outside strings are refused with their position") {
    const std::string text = std::string("Cube {\n  w") + '\x01' + "idth }";
    Tokenizer t(text, "c.iv");
    t.next();
    t.next();
    t.next();
    CHECK_THROWS_WITH_AS(t.next(), doctest::Contains("c.iv:2:4: unexpected control character 0x01"),
                         Error);
}
