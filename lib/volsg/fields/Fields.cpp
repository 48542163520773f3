// Reading and writing of every field type in Inventor ASCII, and the field factory used for
// self-described (unknown) nodes.
#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/BinaryInput.h>
#include <volsg/io/Tokenizer.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <limits>
#include <ostream>
#include <sstream>
#include <type_traits>

namespace volsg {

namespace {

template <class T> void writeNumber(std::ostream& out, T v) {
    if constexpr (std::is_floating_point_v<T>) {
        if (!std::isfinite(v))
            throw Error("cannot write the non-finite value " + std::to_string(v));
    }
    // std::to_chars gives the shortest text that reads back to exactly the same value.
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    out.write(buffer, result.ptr - buffer);
}

void writeFloats(std::ostream& out, const float* v, int n) {
    for (int i = 0; i < n; ++i) {
        if (i) out << ' ';
        writeNumber(out, v[i]);
    }
}

void writeQuoted(std::ostream& out, const std::string& s) {
    out << '"';
    for (char c : s) {
        if (c == '"' || c == '\\') out << '\\';
        out << c;
    }
    out << '"';
}

bool isPlainWord(const std::string& s) {
    if (s.empty()) return false;
    for (unsigned char c : s)
        if (c <= ' ' || c == 0x7f || c == '"' || c == '#' || c == '{' || c == '}' || c == '[' ||
            c == ']' || c == '(' || c == ')' || c == ',' || c == '|' || c == '\\')
            return false;
    return true;
}

std::string enumChoices(const EnumValues& names) {
    std::string s;
    for (const auto& [name, value] : names.entries)
        s += (s.empty() ? "" : ", ") + std::string(name);
    return s;
}

// A name of `names`, or an integer for a value that has none (files we wrote ourselves).
int readEnumWord(Tokenizer& in, const EnumValues& names, const char* what) {
    const Token& t = in.peek();
    if (t.kind != Token::Kind::Word)
        in.failAt(t, std::string("expected ") + what + " (one of " + enumChoices(names) +
                         "), found " + Tokenizer::describe(t));
    int value = 0;
    if (names.valueOf(t.text, value)) {
        in.next();
        return value;
    }
    const char c = t.text[0];
    if ((c >= '0' && c <= '9') || c == '-' || c == '+') return in.readInt32();
    in.failAt(t, "unknown value " + Tokenizer::describe(t) + " (expected one of " +
                     enumChoices(names) + ")");
}

// How many values of an MF field go on one written line.
template <class Traits> constexpr std::size_t valuesPerLine() {
    using V = typename Traits::Value;
    if constexpr (std::is_arithmetic_v<V>)
        return 8;
    else if constexpr (std::is_same_v<V, glm::vec2> || std::is_same_v<V, std::string>)
        return 4;
    else if constexpr (std::is_same_v<V, glm::vec3>)
        return 3;
    else if constexpr (std::is_same_v<V, glm::vec4> || std::is_same_v<V, Rotation> ||
                       std::is_same_v<V, Plane>)
        return 2;
    else
        return 1;
}

[[noreturn]] void failUnclosedList(Tokenizer& tokens, const Token& open, const char* type) {
    tokens.failAt(tokens.peek(), std::string("unexpected end of file: the ") + type +
                                     " list started at " + std::to_string(open.line) + ":" +
                                     std::to_string(open.column) + " has no closing ']'");
}

[[noreturn]] void failTooManyValues(Tokenizer& tokens, const char* type) {
    tokens.failAt(tokens.peek(), std::string("more than ") +
                                     std::to_string(limits::maxFieldValues) + " values in one " +
                                     type + " field");
}

[[noreturn]] void typeMismatch(const Field& to, const Field& from) {
    throw Error(std::string("cannot copy a ") + from.typeName() + " into the " + to.typeName() +
                " field '" + to.name() + "'");
}

} // namespace

// ---- value traits ----------------------------------------------------------------------------

float FloatTraits::read(Tokenizer& in) {
    return in.readFloat();
}
void FloatTraits::write(std::ostream& out, const float& v) {
    writeNumber(out, v);
}

std::int32_t Int32Traits::read(Tokenizer& in) {
    return in.readInt32();
}
void Int32Traits::write(std::ostream& out, const std::int32_t& v) {
    writeNumber(out, v);
}

std::uint32_t UInt32Traits::read(Tokenizer& in) {
    return in.readUInt32();
}
void UInt32Traits::write(std::ostream& out, const std::uint32_t& v) {
    writeNumber(out, v);
}

bool BoolTraits::read(Tokenizer& in) {
    return in.readBool();
}
void BoolTraits::write(std::ostream& out, const bool& v) {
    out << (v ? "TRUE" : "FALSE");
}

std::string StringTraits::read(Tokenizer& in) {
    return in.expectString();
}
void StringTraits::write(std::ostream& out, const std::string& v) {
    writeQuoted(out, v);
}

glm::vec2 Vec2fTraits::read(Tokenizer& in) {
    const float x = in.readFloat();
    return {x, in.readFloat()};
}
void Vec2fTraits::write(std::ostream& out, const glm::vec2& v) {
    writeFloats(out, &v.x, 2);
}

glm::vec3 Vec3fTraits::read(Tokenizer& in) {
    glm::vec3 v;
    for (int i = 0; i < 3; ++i)
        v[i] = in.readFloat();
    return v;
}
void Vec3fTraits::write(std::ostream& out, const glm::vec3& v) {
    writeFloats(out, &v.x, 3);
}

glm::vec4 Vec4fTraits::read(Tokenizer& in) {
    glm::vec4 v;
    for (int i = 0; i < 4; ++i)
        v[i] = in.readFloat();
    return v;
}
void Vec4fTraits::write(std::ostream& out, const glm::vec4& v) {
    writeFloats(out, &v.x, 4);
}

glm::vec3 ColorTraits::read(Tokenizer& in) {
    return Vec3fTraits::read(in);
}
void ColorTraits::write(std::ostream& out, const glm::vec3& v) {
    writeFloats(out, &v.x, 3);
}

Rotation RotationTraits::read(Tokenizer& in) {
    Rotation r;
    r.axis = Vec3fTraits::read(in);
    r.angle = in.readFloat();
    return r;
}
void RotationTraits::write(std::ostream& out, const Rotation& r) {
    writeFloats(out, &r.axis.x, 3);
    out << ' ';
    writeNumber(out, r.angle);
}

Plane PlaneTraits::read(Tokenizer& in) {
    Plane p;
    p.normal = Vec3fTraits::read(in);
    p.distance = in.readFloat();
    return p;
}
void PlaneTraits::write(std::ostream& out, const Plane& p) {
    writeFloats(out, &p.normal.x, 3);
    out << ' ';
    writeNumber(out, p.distance);
}

// The file lists Inventor's row-vector SbMatrix row by row (translation in elements 12-14).
// That matrix is the transpose of ours, and GLM stores column by column, so the file's 16
// numbers are exactly GLM's memory order.
glm::mat4 MatrixTraits::read(Tokenizer& in) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i)
        m[i / 4][i % 4] = in.readFloat();
    return m;
}
void MatrixTraits::write(std::ostream& out, const glm::mat4& m) {
    for (int i = 0; i < 16; ++i) {
        if (i) out << ' ';
        writeNumber(out, m[i / 4][i % 4]);
    }
}

// ---- binary layouts of the value types (docs/SCENE-FORMAT.md section 1.9) -------------------

float FloatTraits::readBinary(BinaryInput& in) {
    return in.readFloat("a float");
}
std::int32_t Int32Traits::readBinary(BinaryInput& in) {
    return in.readInt32("an integer");
}
std::uint32_t UInt32Traits::readBinary(BinaryInput& in) {
    return in.readUInt32("an unsigned integer");
}
bool BoolTraits::readBinary(BinaryInput& in) {
    const std::size_t at = in.offset();
    const std::uint32_t v = in.readUInt32("a bool");
    if (v > 1) in.failAt(at, "a bool must be 0 or 1, found " + std::to_string(v));
    return v == 1;
}
std::string StringTraits::readBinary(BinaryInput& in) {
    return in.readString("a string");
}
glm::vec2 Vec2fTraits::readBinary(BinaryInput& in) {
    const float x = in.readFloat("a float");
    return {x, in.readFloat("a float")};
}
glm::vec3 Vec3fTraits::readBinary(BinaryInput& in) {
    glm::vec3 v;
    for (int i = 0; i < 3; ++i)
        v[i] = in.readFloat("a float");
    return v;
}
glm::vec4 Vec4fTraits::readBinary(BinaryInput& in) {
    glm::vec4 v;
    for (int i = 0; i < 4; ++i)
        v[i] = in.readFloat("a float");
    return v;
}
glm::vec3 ColorTraits::readBinary(BinaryInput& in) {
    return Vec3fTraits::readBinary(in);
}
Rotation RotationTraits::readBinary(BinaryInput& in) {
    Rotation r;
    r.axis = Vec3fTraits::readBinary(in);
    r.angle = in.readFloat("a float");
    return r;
}
Plane PlaneTraits::readBinary(BinaryInput& in) {
    Plane p;
    p.normal = Vec3fTraits::readBinary(in);
    p.distance = in.readFloat("a float");
    return p;
}
glm::mat4 MatrixTraits::readBinary(BinaryInput& in) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i)
        m[i / 4][i % 4] = in.readFloat("a float");
    return m;
}

// ---- the value types of engines and unknown Inventor nodes ----------------------------------

std::string NameTraits::read(Tokenizer& in) {
    return in.expectString();
}
std::string NameTraits::readBinary(BinaryInput& in) {
    return in.readString("a name");
}
void NameTraits::write(std::ostream& out, const std::string& v) {
    if (isPlainWord(v))
        out << v;
    else
        writeQuoted(out, v);
}

namespace {
template <class Int>
Int checkedShort(std::int64_t v, const char* type, Tokenizer* tokens, BinaryInput* binary,
                 std::size_t at) {
    if (v < std::numeric_limits<Int>::min() || v > std::numeric_limits<Int>::max()) {
        const std::string message = "value " + std::to_string(v) + " is out of range for " + type;
        if (tokens) tokens->fail(message);
        binary->failAt(at, message);
    }
    return static_cast<Int>(v);
}
} // namespace

std::int16_t ShortTraits::read(Tokenizer& in) {
    return checkedShort<std::int16_t>(in.readInt32(), sfName, &in, nullptr, 0);
}
std::int16_t ShortTraits::readBinary(BinaryInput& in) {
    const std::size_t at = in.offset();
    return checkedShort<std::int16_t>(in.readInt32("a short"), sfName, nullptr, &in, at);
}
void ShortTraits::write(std::ostream& out, const std::int16_t& v) {
    writeNumber(out, std::int32_t(v));
}
std::uint16_t UShortTraits::read(Tokenizer& in) {
    return checkedShort<std::uint16_t>(in.readInt32(), sfName, &in, nullptr, 0);
}
std::uint16_t UShortTraits::readBinary(BinaryInput& in) {
    const std::size_t at = in.offset();
    return checkedShort<std::uint16_t>(in.readUInt32("an unsigned short"), sfName, nullptr, &in,
                                       at);
}
void UShortTraits::write(std::ostream& out, const std::uint16_t& v) {
    writeNumber(out, std::int32_t(v));
}

double DoubleTraits::read(Tokenizer& in) {
    return in.readDouble();
}
double DoubleTraits::readBinary(BinaryInput& in) {
    return in.readDouble("a double");
}
void DoubleTraits::write(std::ostream& out, const double& v) {
    writeNumber(out, v);
}
double TimeTraits::read(Tokenizer& in) {
    return in.readDouble();
}
double TimeTraits::readBinary(BinaryInput& in) {
    return in.readDouble("a time");
}
void TimeTraits::write(std::ostream& out, const double& v) {
    writeNumber(out, v);
}

namespace {
template <class V> V readDoubles(Tokenizer& in) {
    V v;
    for (int i = 0; i < V::length(); ++i)
        v[i] = in.readDouble();
    return v;
}
template <class V> V readDoublesBinary(BinaryInput& in) {
    V v;
    for (int i = 0; i < V::length(); ++i)
        v[i] = in.readDouble("a double");
    return v;
}
template <class V> void writeComponents(std::ostream& out, const V& v) {
    for (int i = 0; i < V::length(); ++i) {
        if (i) out << ' ';
        writeNumber(out, v[i]);
    }
}
template <class V> V readInts(Tokenizer& in, bool shorts, const char* type) {
    V v;
    for (int i = 0; i < V::length(); ++i)
        v[i] = shorts ? checkedShort<std::int16_t>(in.readInt32(), type, &in, nullptr, 0)
                      : in.readInt32();
    return v;
}
template <class V> V readIntsBinary(BinaryInput& in, bool shorts, const char* type) {
    V v;
    for (int i = 0; i < V::length(); ++i) {
        const std::size_t at = in.offset();
        const std::int32_t x = in.readInt32("an integer");
        v[i] = shorts ? checkedShort<std::int16_t>(x, type, nullptr, &in, at) : x;
    }
    return v;
}
} // namespace

#define VOLSG_VECTOR_TRAITS(Traits, ReadText, ReadBinary)                                          \
    Traits::Value Traits::read(Tokenizer& in) {                                                    \
        return ReadText;                                                                           \
    }                                                                                              \
    Traits::Value Traits::readBinary(BinaryInput& in) {                                            \
        return ReadBinary;                                                                         \
    }                                                                                              \
    void Traits::write(std::ostream& out, const Value& v) {                                        \
        writeComponents(out, v);                                                                   \
    }
VOLSG_VECTOR_TRAITS(Vec2dTraits, readDoubles<Value>(in), readDoublesBinary<Value>(in))
VOLSG_VECTOR_TRAITS(Vec3dTraits, readDoubles<Value>(in), readDoublesBinary<Value>(in))
VOLSG_VECTOR_TRAITS(Vec4dTraits, readDoubles<Value>(in), readDoublesBinary<Value>(in))
VOLSG_VECTOR_TRAITS(ColorRGBATraits, Vec4fTraits::read(in), Vec4fTraits::readBinary(in))
VOLSG_VECTOR_TRAITS(Vec2sTraits, readInts<Value>(in, true, sfName),
                    readIntsBinary<Value>(in, true, sfName))
VOLSG_VECTOR_TRAITS(Vec3sTraits, readInts<Value>(in, true, sfName),
                    readIntsBinary<Value>(in, true, sfName))
VOLSG_VECTOR_TRAITS(Vec2i32Traits, readInts<Value>(in, false, sfName),
                    readIntsBinary<Value>(in, false, sfName))
VOLSG_VECTOR_TRAITS(Vec3i32Traits, readInts<Value>(in, false, sfName),
                    readIntsBinary<Value>(in, false, sfName))
VOLSG_VECTOR_TRAITS(Vec4i32Traits, readInts<Value>(in, false, sfName),
                    readIntsBinary<Value>(in, false, sfName))
#undef VOLSG_VECTOR_TRAITS

std::string EnumWordTraits::read(Tokenizer& in) {
    return in.expectWord("an enum name");
}
std::string EnumWordTraits::readBinary(BinaryInput& in) {
    return in.readString("an enum name");
}
void EnumWordTraits::write(std::ostream& out, const std::string& v) {
    out << v;
}

std::vector<std::string> BitWordsTraits::read(Tokenizer& in) {
    Value words;
    if (!in.acceptPunct('(')) {
        words.push_back(in.expectWord("a bit name"));
        return words;
    }
    if (in.acceptPunct(')')) return words;
    while (true) {
        if (words.size() >= limits::maxFieldValues)
            in.failAt(in.peek(), "more than " + std::to_string(limits::maxFieldValues) +
                                     " names in one bit mask");
        words.push_back(in.expectWord("a bit name"));
        if (in.acceptPunct(')')) return words;
        if (!in.acceptPunct('|'))
            in.failAt(in.peek(),
                      "expected '|' or ')' in a bit mask, found " + Tokenizer::describe(in.peek()));
    }
}
// Binary: the names one after the other, ended by an empty string.
std::vector<std::string> BitWordsTraits::readBinary(BinaryInput& in) {
    Value words;
    while (true) {
        std::string word = in.readString("a bit name");
        if (word.empty()) return words;
        if (words.size() >= limits::maxFieldValues)
            in.fail("more than " + std::to_string(limits::maxFieldValues) +
                    " names in one bit mask");
        words.push_back(std::move(word));
    }
}
void BitWordsTraits::write(std::ostream& out, const Value& v) {
    if (v.size() == 1) {
        out << v[0];
        return;
    }
    out << '(';
    for (std::size_t i = 0; i < v.size(); ++i)
        out << (i ? " | " : "") << v[i];
    out << ')';
}

namespace {
void checkImageSize(std::int64_t w, std::int64_t h, std::int64_t c, Tokenizer* tokens,
                    BinaryInput* binary, std::size_t at) {
    std::string message;
    if (w < 0 || h < 0 || c < 0 || c > 4)
        message = "invalid image size " + std::to_string(w) + " x " + std::to_string(h) + " x " +
                  std::to_string(c) + " (width, height >= 0, 0 to 4 components)";
    else if ((w == 0 || h == 0 || c == 0) && !(w == 0 && h == 0 && c == 0))
        message = "invalid image size " + std::to_string(w) + " x " + std::to_string(h) + " x " +
                  std::to_string(c) + " (an empty image is 0 0 0)";
    else if (w > std::int64_t(limits::maxImageSide) || h > std::int64_t(limits::maxImageSide) ||
             std::uint64_t(w) * std::uint64_t(h) > limits::maxImagePixels)
        message = "image of " + std::to_string(w) + " x " + std::to_string(h) +
                  " pixels exceeds the image limit (" + std::to_string(limits::maxImageSide) +
                  " per side, " + std::to_string(limits::maxImagePixels) + " in all)";
    if (message.empty()) return;
    if (tokens) tokens->fail(message);
    binary->failAt(at, message);
}
} // namespace

// `width height components` then one number per pixel, its components packed high byte first
// (0xFF0000 is red for three components).
ImageValue ImageTraits::read(Tokenizer& in) {
    ImageValue v;
    v.width = in.readInt32();
    v.height = in.readInt32();
    v.components = in.readInt32();
    checkImageSize(v.width, v.height, v.components, &in, nullptr, 0);
    const std::size_t pixels = std::size_t(v.width) * std::size_t(v.height);
    v.pixels.reserve(std::min<std::size_t>(pixels * std::size_t(v.components), 1 << 20));
    for (std::size_t i = 0; i < pixels; ++i) {
        if (in.atEnd()) in.failAt(in.peek(), "expected a pixel value, found end of file");
        const std::uint32_t p = in.readUInt32();
        for (int c = v.components - 1; c >= 0; --c)
            v.pixels.push_back(std::uint8_t((p >> (8 * c)) & 0xFF));
    }
    return v;
}
// 2.1: the bytes, padded to four; 2.0: one 32-bit word per pixel, as in text.
ImageValue ImageTraits::readBinary(BinaryInput& in) {
    ImageValue v;
    const std::size_t at = in.offset();
    v.width = in.readInt32("the image width");
    v.height = in.readInt32("the image height");
    v.components = in.readInt32("the image components");
    checkImageSize(v.width, v.height, v.components, nullptr, &in, at);
    const std::size_t pixels = std::size_t(v.width) * std::size_t(v.height);
    const std::size_t bytes = pixels * std::size_t(v.components);
    if (in.version() >= 2.1f) {
        in.requireItems((bytes + 3) / 4, 4, "the image", at);
        const std::string data = in.readBytes(bytes, "the image");
        v.pixels.assign(data.begin(), data.end());
        in.skip((bytes + 3) / 4 * 4 - bytes, "the image padding");
    } else {
        in.requireItems(pixels, 4, "the image", at);
        v.pixels.reserve(bytes);
        for (std::size_t i = 0; i < pixels; ++i) {
            const std::uint32_t p = in.readUInt32("a pixel");
            for (int c = v.components - 1; c >= 0; --c)
                v.pixels.push_back(std::uint8_t((p >> (8 * c)) & 0xFF));
        }
    }
    return v;
}
void ImageTraits::write(std::ostream& out, const ImageValue& v) {
    out << v.width << ' ' << v.height << ' ' << v.components;
    char buffer[16];
    const std::size_t pixels = std::size_t(v.width) * std::size_t(v.height);
    for (std::size_t i = 0; i < pixels; ++i) {
        std::uint32_t p = 0;
        for (int c = 0; c < v.components; ++c)
            p = (p << 8) | v.pixels[i * std::size_t(v.components) + std::size_t(c)];
        std::snprintf(buffer, sizeof buffer, " 0x%0*X", 2 * v.components, unsigned(p));
        out << buffer;
    }
}

// ---- SField / MField -------------------------------------------------------------------------

template <class Traits> void SField<Traits>::read(FieldInput& in) {
    if (BinaryInput* binary = in.binary())
        setValue(Traits::readBinary(*binary));
    else
        setValue(Traits::read(in.tokens()));
}

template <class Traits> void SField<Traits>::write(FieldOutput& out) const {
    Traits::write(out.stream(), value_);
}

template <class Traits> bool SField<Traits>::equals(const Field& other) const {
    const auto* o = dynamic_cast<const SField*>(&other);
    return o && o->value_ == value_;
}

template <class Traits> void SField<Traits>::copyFrom(const Field& other) {
    const auto* o = dynamic_cast<const SField*>(&other);
    if (!o) typeMismatch(*this, other);
    setValue(o->value_);
}

template <class Traits> void MField<Traits>::read(FieldInput& in) {
    std::vector<Value> values;
    if (BinaryInput* binary = in.binary()) {
        // A count, then the values; the count is checked against the bytes left first.
        const std::size_t at = binary->offset();
        const std::int32_t count = binary->readInt32("a value count");
        if (count < 0) binary->failAt(at, "negative value count " + std::to_string(count));
        if (std::size_t(count) > limits::maxFieldValues)
            binary->failAt(at, "more than " + std::to_string(limits::maxFieldValues) +
                                   " values in one " + Traits::mfName + " field");
        binary->requireItems(std::uint64_t(count), Traits::binarySize, "the list", at);
        values.reserve(std::size_t(count));
        for (std::int32_t i = 0; i < count; ++i)
            values.push_back(Traits::readBinary(*binary));
        setValues(std::move(values));
        return;
    }
    Tokenizer& tokens = in.tokens();
    if (!tokens.peek().isPunct('[')) {
        values.push_back(Traits::read(tokens));
        setValues(std::move(values));
        return;
    }
    const Token open = tokens.next();
    while (!tokens.acceptPunct(']')) {
        if (tokens.atEnd()) failUnclosedList(tokens, open, Traits::mfName);
        if (values.size() >= limits::maxFieldValues) failTooManyValues(tokens, Traits::mfName);
        values.push_back(Traits::read(tokens));
        tokens.acceptPunct(',');
    }
    setValues(std::move(values));
}

template <class Traits> void MField<Traits>::write(FieldOutput& out) const {
    std::ostream& os = out.stream();
    constexpr std::size_t perLine = valuesPerLine<Traits>();
    os << '[';
    if (values_.size() <= perLine) {
        for (std::size_t i = 0; i < values_.size(); ++i) {
            os << (i ? ", " : " ");
            Traits::write(os, values_[i]);
        }
    } else {
        for (std::size_t i = 0; i < values_.size(); ++i) {
            if (i % perLine == 0)
                out.newline();
            else
                os << ' ';
            Traits::write(os, values_[i]);
            if (i + 1 < values_.size()) os << ',';
        }
    }
    os << " ]";
}

template <class Traits> bool MField<Traits>::equals(const Field& other) const {
    const auto* o = dynamic_cast<const MField*>(&other);
    return o && o->values_ == values_;
}

template <class Traits> void MField<Traits>::copyFrom(const Field& other) {
    const auto* o = dynamic_cast<const MField*>(&other);
    if (!o) typeMismatch(*this, other);
    setValues(o->values_);
}

template class SField<FloatTraits>;
template class SField<Int32Traits>;
template class SField<UInt32Traits>;
template class SField<BoolTraits>;
template class SField<StringTraits>;
template class SField<Vec2fTraits>;
template class SField<Vec3fTraits>;
template class SField<Vec4fTraits>;
template class SField<ColorTraits>;
template class SField<RotationTraits>;
template class SField<PlaneTraits>;
template class SField<MatrixTraits>;
template class MField<FloatTraits>;
template class MField<Int32Traits>;
template class MField<UInt32Traits>;
template class MField<BoolTraits>;
template class MField<StringTraits>;
template class MField<Vec2fTraits>;
template class MField<Vec3fTraits>;
template class MField<Vec4fTraits>;
template class MField<ColorTraits>;
template class MField<RotationTraits>;
template class MField<PlaneTraits>;
template class MField<MatrixTraits>;
#define VOLSG_INSTANTIATE(Traits)                                                                  \
    template class SField<Traits>;                                                                 \
    template class MField<Traits>;
VOLSG_INSTANTIATE(NameTraits)
VOLSG_INSTANTIATE(ShortTraits)
VOLSG_INSTANTIATE(UShortTraits)
VOLSG_INSTANTIATE(DoubleTraits)
VOLSG_INSTANTIATE(TimeTraits)
VOLSG_INSTANTIATE(Vec2dTraits)
VOLSG_INSTANTIATE(Vec3dTraits)
VOLSG_INSTANTIATE(Vec4dTraits)
VOLSG_INSTANTIATE(ColorRGBATraits)
VOLSG_INSTANTIATE(Vec2sTraits)
VOLSG_INSTANTIATE(Vec3sTraits)
VOLSG_INSTANTIATE(Vec2i32Traits)
VOLSG_INSTANTIATE(Vec3i32Traits)
VOLSG_INSTANTIATE(Vec4i32Traits)
VOLSG_INSTANTIATE(EnumWordTraits)
VOLSG_INSTANTIATE(BitWordsTraits)
VOLSG_INSTANTIATE(ImageTraits)
#undef VOLSG_INSTANTIATE

// ---- enums and bit masks ---------------------------------------------------------------------

const char* EnumValues::nameOf(int value) const {
    for (const auto& [name, v] : entries)
        if (v == value) return name;
    return nullptr;
}

bool EnumValues::valueOf(std::string_view name, int& value) const {
    for (const auto& [n, v] : entries)
        if (name == n) {
            value = v;
            return true;
        }
    return false;
}

namespace {
// Binary enums and bit-mask bits are their names as strings.
int enumValueOfName(BinaryInput& in, const EnumValues& names, const std::string& name,
                    std::size_t at) {
    int value = 0;
    if (!names.valueOf(name, value))
        in.failAt(at, "unknown value '" + name + "' (expected one of " + enumChoices(names) + ")");
    return value;
}
} // namespace

void SFEnum::read(FieldInput& in) {
    if (BinaryInput* binary = in.binary()) {
        const std::size_t at = binary->offset();
        setValue(enumValueOfName(*binary, *names_, binary->readString("an enum name"), at));
        return;
    }
    setValue(readEnumWord(in.tokens(), *names_, "an enum name"));
}

void SFEnum::write(FieldOutput& out) const {
    if (const char* name = names_->nameOf(value_))
        out.stream() << name;
    else
        writeNumber(out.stream(), value_);
}

bool SFEnum::equals(const Field& other) const {
    const auto* o = dynamic_cast<const SFEnum*>(&other);
    return o && o->value_ == value_;
}

void SFEnum::copyFrom(const Field& other) {
    const auto* o = dynamic_cast<const SFEnum*>(&other);
    if (!o) typeMismatch(*this, other);
    setValue(o->value_);
}

void SFBitMask::read(FieldInput& in) {
    if (BinaryInput* binary = in.binary()) {
        int value = 0;
        for (const std::string& name : BitWordsTraits::readBinary(*binary))
            value |= enumValueOfName(*binary, *bits_, name, binary->offset());
        setValue(value);
        return;
    }
    Tokenizer& tokens = in.tokens();
    if (!tokens.acceptPunct('(')) {
        setValue(readEnumWord(tokens, *bits_, "a bit name"));
        return;
    }
    int value = 0;
    if (!tokens.acceptPunct(')')) {
        while (true) {
            value |= readEnumWord(tokens, *bits_, "a bit name");
            if (tokens.acceptPunct(')')) break;
            if (!tokens.acceptPunct('|'))
                tokens.failAt(tokens.peek(), "expected '|' or ')' in a bit mask, found " +
                                                 Tokenizer::describe(tokens.peek()));
        }
    }
    setValue(value);
}

void SFBitMask::write(FieldOutput& out) const {
    std::ostream& os = out.stream();
    if (const char* name = bits_->nameOf(value_)) {
        os << name;
        return;
    }
    // Cover the mask with names, widest first (so ALL beats SIDES | BOTTOM), each adding bits.
    std::vector<std::pair<const char*, int>> byWidth(bits_->entries);
    std::stable_sort(byWidth.begin(), byWidth.end(), [](const auto& a, const auto& b) {
        return std::popcount(unsigned(a.second)) > std::popcount(unsigned(b.second));
    });
    std::vector<const char*> names;
    unsigned remaining = unsigned(value_);
    for (const auto& [name, bits] : byWidth) {
        const unsigned b = unsigned(bits);
        if (b != 0 && (b & ~unsigned(value_)) == 0 && (b & remaining) != 0) {
            names.push_back(name);
            remaining &= ~b;
        }
    }
    os << '(';
    for (std::size_t i = 0; i < names.size(); ++i)
        os << (i ? " | " : "") << names[i];
    if (remaining != 0 || names.empty()) {
        // Bits without a name are written as a number, which read() accepts back.
        os << (names.empty() ? "" : " | ");
        writeNumber(os, std::int32_t(remaining));
    }
    os << ')';
}

bool SFBitMask::equals(const Field& other) const {
    const auto* o = dynamic_cast<const SFBitMask*>(&other);
    return o && o->value_ == value_;
}

void SFBitMask::copyFrom(const Field& other) {
    const auto* o = dynamic_cast<const SFBitMask*>(&other);
    if (!o) typeMismatch(*this, other);
    setValue(o->value_);
}

// ---- node fields -----------------------------------------------------------------------------

SFNode::SFNode(Node* owner, const char* name) : Field(owner, name) {}
SFNode::~SFNode() = default;

Node* SFNode::getValue() const {
    return value_.get();
}

void SFNode::setValue(ref_ptr<Node> n) {
    value_ = std::move(n);
    changed();
}

void SFNode::read(FieldInput& in) {
    setValue(in.readNode());
}

void SFNode::write(FieldOutput& out) const {
    out.writeNode(value_.get());
}

// The value of a node field is the node itself: equal means the same node. Comparing the
// graphs below it is graphsEqual()'s job (io/GraphCompare.h).
bool SFNode::equals(const Field& other) const {
    const auto* o = dynamic_cast<const SFNode*>(&other);
    return o && o->value_ == value_;
}

void SFNode::copyFrom(const Field& other) {
    const auto* o = dynamic_cast<const SFNode*>(&other);
    if (!o) typeMismatch(*this, other);
    setValue(o->value_);
}

MFNode::MFNode(Node* owner, const char* name) : Field(owner, name) {}
MFNode::~MFNode() = default;

void MFNode::setValues(std::vector<ref_ptr<Node>> v) {
    values_ = std::move(v);
    changed();
}

void MFNode::read(FieldInput& in) {
    std::vector<ref_ptr<Node>> values;
    if (BinaryInput* binary = in.binary()) {
        const std::size_t at = binary->offset();
        const std::int32_t count = binary->readInt32("a node count");
        if (count < 0) binary->failAt(at, "negative node count " + std::to_string(count));
        if (std::size_t(count) > limits::maxFieldValues)
            binary->failAt(at, "more than " + std::to_string(limits::maxFieldValues) +
                                   " values in one MFNode field");
        // A node takes at least its type name: 4 bytes of length and 4 of text.
        binary->requireItems(std::uint64_t(count), 8, "the list", at);
        for (std::int32_t i = 0; i < count; ++i)
            values.push_back(in.readNode());
        setValues(std::move(values));
        return;
    }
    Tokenizer& tokens = in.tokens();
    if (!tokens.peek().isPunct('[')) {
        values.push_back(in.readNode());
    } else {
        const Token open = tokens.next();
        while (!tokens.acceptPunct(']')) {
            if (tokens.atEnd()) failUnclosedList(tokens, open, "MFNode");
            if (values.size() >= limits::maxFieldValues) failTooManyValues(tokens, "MFNode");
            values.push_back(in.readNode());
            tokens.acceptPunct(',');
        }
    }
    setValues(std::move(values));
}

void MFNode::write(FieldOutput& out) const {
    out.stream() << '[';
    for (const auto& node : values_) {
        out.newline();
        out.writeNode(node.get());
    }
    out.stream() << " ]";
}

bool MFNode::equals(const Field& other) const {
    const auto* o = dynamic_cast<const MFNode*>(&other);
    return o && o->values_ == values_;
}

void MFNode::copyFrom(const Field& other) {
    const auto* o = dynamic_cast<const MFNode*>(&other);
    if (!o) typeMismatch(*this, other);
    setValues(o->values_);
}

// ---- SFTrigger, raw values -------------------------------------------------------------------

void SFTrigger::read(FieldInput&) {
    // A trigger has no value in a file, text or binary: the field name alone.
    setDefault(false);
}
void SFTrigger::write(FieldOutput&) const {}
bool SFTrigger::equals(const Field& other) const {
    const auto* o = dynamic_cast<const SFTrigger*>(&other);
    return o && o->count_ == count_;
}
void SFTrigger::copyFrom(const Field& other) {
    const auto* o = dynamic_cast<const SFTrigger*>(&other);
    if (!o) typeMismatch(*this, other);
    count_ = o->count_;
    changed();
}

void RawValueField::read(FieldInput& in) {
    // Read by the scene reader itself (it knows where a value ends); a raw value cannot be
    // read on its own.
    in.tokens().fail(std::string("the value of '") + name() + "' has no type to read it as");
}
void RawValueField::write(FieldOutput& out) const {
    std::ostream& os = out.stream();
    bool first = true;
    for (const Piece& p : pieces_) {
        if (!first) os << ' ';
        first = false;
        if (p.kind == Piece::Kind::String)
            writeQuoted(os, p.text);
        else
            os << p.text;
    }
}
bool RawValueField::equals(const Field& other) const {
    const auto* o = dynamic_cast<const RawValueField*>(&other);
    return o && o->pieces_ == pieces_;
}
void RawValueField::copyFrom(const Field& other) {
    const auto* o = dynamic_cast<const RawValueField*>(&other);
    if (!o) typeMismatch(*this, other);
    setPieces(o->pieces_);
}

// ---- flags and connections (Field.h) -----------------------------------------------------------

void Field::setIgnored(bool ignored) {
    if (isIgnored_ == ignored) return;
    isIgnored_ = ignored;
    if (owner_) owner_->touch();
}

void Field::connectFrom(ref_ptr<Node> source, std::string sourceField) {
    auto c = std::make_unique<FieldConnection>();
    c->source = std::move(source);
    c->sourceField = std::move(sourceField);
    connection_ = std::move(c);
    if (owner_) owner_->touch();
}

void Field::disconnect() {
    if (!connection_) return;
    connection_.reset();
    if (owner_) owner_->touch();
}

// ---- conversion between field types (engines and connections) ----------------------------------

namespace {

/// One value of a field as numbers (a float, a vector's components, a rotation's axis and
/// angle, a matrix in file order) or as text.
struct Element {
    std::vector<double> numbers;
    std::string text;
    bool isText = false;
};

template <class V> void toNumbers(const V& v, std::vector<double>& out) {
    if constexpr (std::is_arithmetic_v<V>) {
        out.push_back(double(v));
    } else if constexpr (std::is_same_v<V, Rotation>) {
        out.insert(out.end(),
                   {double(v.axis.x), double(v.axis.y), double(v.axis.z), double(v.angle)});
    } else if constexpr (std::is_same_v<V, Plane>) {
        out.insert(out.end(), {double(v.normal.x), double(v.normal.y), double(v.normal.z),
                               double(v.distance)});
    } else if constexpr (std::is_same_v<V, glm::mat4>) {
        for (int i = 0; i < 16; ++i)
            out.push_back(double(v[i / 4][i % 4]));
    } else {
        for (int i = 0; i < V::length(); ++i)
            out.push_back(double(v[i]));
    }
}

template <class V> bool fromNumbers(const std::vector<double>& in, V& v) {
    auto count = [] {
        if constexpr (std::is_arithmetic_v<V>)
            return 1;
        else if constexpr (std::is_same_v<V, Rotation> || std::is_same_v<V, Plane>)
            return 4;
        else if constexpr (std::is_same_v<V, glm::mat4>)
            return 16;
        else
            return int(V::length());
    }();
    if (int(in.size()) != count) return false;
    auto cast = [](double d, auto& target) {
        using T = std::remove_reference_t<decltype(target)>;
        if constexpr (std::is_same_v<T, bool>)
            target = d != 0.0;
        else if constexpr (std::is_integral_v<T>)
            target = d <= double(std::numeric_limits<T>::min())   ? std::numeric_limits<T>::min()
                     : d >= double(std::numeric_limits<T>::max()) ? std::numeric_limits<T>::max()
                                                                  : T(d);
        else
            target = T(d);
    };
    if constexpr (std::is_arithmetic_v<V>) {
        cast(in[0], v);
    } else if constexpr (std::is_same_v<V, Rotation>) {
        v.axis = glm::vec3(in[0], in[1], in[2]);
        v.angle = float(in[3]);
    } else if constexpr (std::is_same_v<V, Plane>) {
        v.normal = glm::vec3(in[0], in[1], in[2]);
        v.distance = float(in[3]);
    } else if constexpr (std::is_same_v<V, glm::mat4>) {
        for (int i = 0; i < 16; ++i)
            v[i / 4][i % 4] = float(in[std::size_t(i)]);
    } else {
        for (int i = 0; i < V::length(); ++i)
            cast(in[std::size_t(i)], v[i]);
    }
    return true;
}

template <class Traits> constexpr bool isNumeric() {
    using V = typename Traits::Value;
    return !std::is_same_v<V, std::string> && !std::is_same_v<V, std::vector<std::string>> &&
           !std::is_same_v<V, ImageValue>;
}

template <class Traits> Element elementOf(const typename Traits::Value& v) {
    Element e;
    if constexpr (isNumeric<Traits>()) {
        toNumbers(v, e.numbers);
    } else if constexpr (std::is_same_v<typename Traits::Value, std::string>) {
        e.text = v;
        e.isText = true;
    } else {
        std::ostringstream os;
        Traits::write(os, v);
        e.text = os.str();
        e.isText = true;
    }
    return e;
}

template <class Traits> std::string textOf(const Element& e) {
    if (e.isText) return e.text;
    std::ostringstream os;
    for (std::size_t i = 0; i < e.numbers.size(); ++i) {
        if (i) os << ' ';
        const double d = e.numbers[i];
        if (d == std::floor(d) && std::abs(d) < 1e15)
            writeNumber(os, std::int64_t(d));
        else
            writeNumber(os, d);
    }
    return os.str();
}

template <class Traits> bool valueOf(const Element& e, typename Traits::Value& v) {
    using V = typename Traits::Value;
    if constexpr (std::is_same_v<V, std::string>) {
        v = textOf<Traits>(e);
        return true;
    } else if constexpr (isNumeric<Traits>()) {
        return !e.isText && fromNumbers(e.numbers, v);
    } else {
        return false;
    }
}

/// The values of `f` as elements; false if `f` is not one of the value fields.
template <class Traits> bool elementsOf(const Field& f, std::vector<Element>& out) {
    if (const auto* sf = dynamic_cast<const SField<Traits>*>(&f)) {
        out.push_back(elementOf<Traits>(sf->getValue()));
        return true;
    }
    if (const auto* mf = dynamic_cast<const MField<Traits>*>(&f)) {
        for (std::size_t i = 0; i < mf->size(); ++i)
            out.push_back(elementOf<Traits>((*mf)[i]));
        return true;
    }
    return false;
}

/// Sets `f` from elements; 0 if `f` is not of this traits, 1 done, -1 cannot convert.
template <class Traits>
int assignElements(Field& f, const std::vector<Element>& in, bool& changed) {
    using V = typename Traits::Value;
    if (auto* sf = dynamic_cast<SField<Traits>*>(&f)) {
        if (in.empty()) return 1; // an empty list leaves a single value as it is
        V v{};
        if (!valueOf<Traits>(in.front(), v)) return -1;
        if (sf->isDefault() || !(sf->getValue() == v)) {
            sf->setValue(std::move(v));
            changed = true;
        }
        return 1;
    }
    if (auto* mf = dynamic_cast<MField<Traits>*>(&f)) {
        std::vector<V> values(in.size());
        for (std::size_t i = 0; i < in.size(); ++i) {
            V v{};
            if (!valueOf<Traits>(in[i], v)) return -1;
            values[i] = std::move(v);
        }
        if (mf->isDefault() || mf->getValues() != values) {
            mf->setValues(std::move(values));
            changed = true;
        }
        return 1;
    }
    return 0;
}

template <class... Traits> struct TraitsList {
    static bool elements(const Field& f, std::vector<Element>& out) {
        return (elementsOf<Traits>(f, out) || ...);
    }
    static int assign(Field& f, const std::vector<Element>& in, bool& changed) {
        int result = 0;
        ((result = result ? result : assignElements<Traits>(f, in, changed)), ...);
        return result;
    }
};
using AllValueTraits =
    TraitsList<FloatTraits, Int32Traits, UInt32Traits, BoolTraits, StringTraits, Vec2fTraits,
               Vec3fTraits, Vec4fTraits, ColorTraits, RotationTraits, PlaneTraits, MatrixTraits,
               NameTraits, ShortTraits, UShortTraits, DoubleTraits, TimeTraits, Vec2dTraits,
               Vec3dTraits, Vec4dTraits, ColorRGBATraits, Vec2sTraits, Vec3sTraits, Vec2i32Traits,
               Vec3i32Traits, Vec4i32Traits, EnumWordTraits, BitWordsTraits, ImageTraits>;

[[noreturn]] void cannotConvert(const Field& to, const Field& from) {
    throw Error(std::string("cannot convert a ") + from.typeName() + " into the " + to.typeName() +
                " field '" + to.name() + "'");
}

} // namespace

bool valuesClose(const Field& a, const Field& b, double relativeTolerance) {
    if (std::string_view(a.typeName()) != b.typeName()) return false;
    if (a.equals(b)) return true;
    std::vector<Element> ea, eb;
    if (!AllValueTraits::elements(a, ea) || !AllValueTraits::elements(b, eb)) return false;
    if (ea.size() != eb.size()) return false;
    for (std::size_t i = 0; i < ea.size(); ++i) {
        if (ea[i].isText != eb[i].isText || ea[i].text != eb[i].text) return false;
        if (ea[i].numbers.size() != eb[i].numbers.size()) return false;
        for (std::size_t k = 0; k < ea[i].numbers.size(); ++k) {
            const double x = ea[i].numbers[k], y = eb[i].numbers[k];
            const double scale = std::max({1.0, std::abs(x), std::abs(y)});
            if (std::abs(x - y) > relativeTolerance * scale) return false;
        }
    }
    return true;
}

bool assignConverted(Field& to, const Field& from) {
    if (std::string_view(to.typeName()) == from.typeName() && typeid(to) == typeid(from)) {
        if (!to.isDefault() && to.equals(from)) return false;
        to.copyFrom(from);
        return true;
    }
    std::vector<Element> elements;
    if (const auto* e = dynamic_cast<const SFEnum*>(&from)) {
        elements.push_back(Element{{double(e->getValue())}, {}, false});
    } else if (const auto* b = dynamic_cast<const SFBitMask*>(&from)) {
        elements.push_back(Element{{double(b->getValue())}, {}, false});
    } else if (const auto* t = dynamic_cast<const SFTrigger*>(&from)) {
        elements.push_back(Element{{double(t->count())}, {}, false});
    } else if (!AllValueTraits::elements(from, elements)) {
        cannotConvert(to, from);
    }
    if (auto* t = dynamic_cast<SFTrigger*>(&to)) {
        t->touch(); // anything arriving at a trigger fires it
        return true;
    }
    if (auto* e = dynamic_cast<SFEnum*>(&to)) {
        if (elements.empty()) return false;
        int v = 0;
        const Element& first = elements.front();
        if (first.isText ? !e->names().valueOf(first.text, v) : first.numbers.size() != 1)
            cannotConvert(to, from);
        if (!first.isText) v = int(first.numbers[0]);
        if (!e->isDefault() && e->getValue() == v) return false;
        e->setValue(v);
        return true;
    }
    if (auto* b = dynamic_cast<SFBitMask*>(&to)) {
        if (elements.empty() || elements.front().isText || elements.front().numbers.size() != 1)
            cannotConvert(to, from);
        const int v = int(elements.front().numbers[0]);
        if (!b->isDefault() && b->getValue() == v) return false;
        b->setValue(v);
        return true;
    }
    bool changed = false;
    if (AllValueTraits::assign(to, elements, changed) != 1) cannotConvert(to, from);
    return changed;
}

namespace {
template <class Traits> int keepOnly(Field& f, std::size_t i) {
    auto* mf = dynamic_cast<MField<Traits>*>(&f);
    if (!mf) return 0;
    if (i >= mf->size()) return -1;
    mf->setValues({mf->getValues()[i]});
    return 1;
}
template <class Traits> bool append(Field& to, const Field& from) {
    auto* a = dynamic_cast<MField<Traits>*>(&to);
    const auto* b = dynamic_cast<const MField<Traits>*>(&from);
    if (!a || !b) return false;
    if (b->empty()) return true;
    std::vector<typename Traits::Value> values = a->getValues();
    values.insert(values.end(), b->getValues().begin(), b->getValues().end());
    a->setValues(std::move(values));
    return true;
}
template <class... Traits> int keepOnlyAny(Field& f, std::size_t i) {
    int r = 0;
    ((r = r ? r : keepOnly<Traits>(f, i)), ...);
    return r;
}
template <class... Traits> bool appendAny(Field& to, const Field& from) {
    return (append<Traits>(to, from) || ...);
}
template <class... Traits> struct ListOps {
    static int keep(Field& f, std::size_t i) { return keepOnlyAny<Traits...>(f, i); }
    static bool add(Field& to, const Field& from) { return appendAny<Traits...>(to, from); }
};
using AllListOps =
    ListOps<FloatTraits, Int32Traits, UInt32Traits, BoolTraits, StringTraits, Vec2fTraits,
            Vec3fTraits, Vec4fTraits, ColorTraits, RotationTraits, PlaneTraits, MatrixTraits,
            NameTraits, ShortTraits, UShortTraits, DoubleTraits, TimeTraits, Vec2dTraits,
            Vec3dTraits, Vec4dTraits, ColorRGBATraits, Vec2sTraits, Vec3sTraits, Vec2i32Traits,
            Vec3i32Traits, Vec4i32Traits, EnumWordTraits, BitWordsTraits>;
} // namespace

bool keepOnlyValue(Field& list, std::size_t i) {
    if (auto* mf = dynamic_cast<MFNode*>(&list)) {
        if (i >= mf->getValues().size()) return false;
        mf->setValues({mf->getValues()[i]});
        return true;
    }
    return AllListOps::keep(list, i) == 1;
}

void appendValues(Field& to, const Field& from) {
    if (auto* a = dynamic_cast<MFNode*>(&to)) {
        const auto* b = dynamic_cast<const MFNode*>(&from);
        if (!b) typeMismatch(to, from);
        std::vector<ref_ptr<Node>> values = a->getValues();
        values.insert(values.end(), b->getValues().begin(), b->getValues().end());
        a->setValues(std::move(values));
        return;
    }
    if (!AllListOps::add(to, from)) typeMismatch(to, from);
}

std::unique_ptr<Field> cloneField(const Field& from) {
    std::unique_ptr<Field> copy;
    if (const auto* e = dynamic_cast<const SFEnum*>(&from))
        copy = std::make_unique<SFEnum>(nullptr, from.name(), e->names(), e->getValue());
    else if (const auto* b = dynamic_cast<const SFBitMask*>(&from))
        copy = std::make_unique<SFBitMask>(nullptr, from.name(), b->names(), b->getValue());
    else if (dynamic_cast<const RawValueField*>(&from))
        copy = std::make_unique<RawValueField>(nullptr, from.name());
    else
        copy = createFieldOfType(from.typeName(), nullptr, from.name());
    if (!copy) throw Error(std::string("cannot copy a ") + from.typeName() + " field");
    copy->copyFrom(from);
    copy->setDefault(from.isDefault());
    return copy;
}

// ---- factory ---------------------------------------------------------------------------------

namespace {

using FieldFactory = std::unique_ptr<Field> (*)(Node*, const char*);

template <class F> std::unique_ptr<Field> make(Node* owner, const char* name) {
    return std::make_unique<F>(owner, name);
}

template <class Traits> void addPair(std::vector<std::pair<std::string_view, FieldFactory>>& t) {
    t.emplace_back(Traits::sfName, &make<SField<Traits>>);
    t.emplace_back(Traits::mfName, &make<MField<Traits>>);
}

const std::vector<std::pair<std::string_view, FieldFactory>>& factories() {
    static const auto table = [] {
        std::vector<std::pair<std::string_view, FieldFactory>> t;
        addPair<FloatTraits>(t);
        addPair<Int32Traits>(t);
        addPair<UInt32Traits>(t);
        addPair<BoolTraits>(t);
        addPair<StringTraits>(t);
        addPair<Vec2fTraits>(t);
        addPair<Vec3fTraits>(t);
        addPair<Vec4fTraits>(t);
        addPair<ColorTraits>(t);
        addPair<RotationTraits>(t);
        addPair<PlaneTraits>(t);
        addPair<MatrixTraits>(t);
        addPair<NameTraits>(t);
        addPair<ShortTraits>(t);
        addPair<UShortTraits>(t);
        addPair<DoubleTraits>(t);
        addPair<TimeTraits>(t);
        addPair<Vec2dTraits>(t);
        addPair<Vec3dTraits>(t);
        addPair<Vec4dTraits>(t);
        addPair<ColorRGBATraits>(t);
        addPair<Vec2sTraits>(t);
        addPair<Vec3sTraits>(t);
        addPair<Vec2i32Traits>(t);
        addPair<Vec3i32Traits>(t);
        addPair<Vec4i32Traits>(t);
        // Enums of unknown nodes have no name table: their words are kept as written.
        addPair<EnumWordTraits>(t);
        addPair<BitWordsTraits>(t);
        t.emplace_back(ImageTraits::sfName, &make<SField<ImageTraits>>);
        // Inventor 2.0 names of the 32-bit integer types.
        t.emplace_back("SFLong", &make<SField<Int32Traits>>);
        t.emplace_back("MFLong", &make<MField<Int32Traits>>);
        t.emplace_back("SFULong", &make<SField<UInt32Traits>>);
        t.emplace_back("MFULong", &make<MField<UInt32Traits>>);
        t.emplace_back("SFTrigger", &make<SFTrigger>);
        t.emplace_back("SFNode", &make<SFNode>);
        t.emplace_back("MFNode", &make<MFNode>);
        return t;
    }();
    return table;
}

} // namespace

std::unique_ptr<Field> createFieldOfType(std::string_view typeName, Node* owner, const char* name) {
    for (const auto& [type, factory] : factories())
        if (type == typeName) return factory(owner, name);
    return nullptr;
}

} // namespace volsg
