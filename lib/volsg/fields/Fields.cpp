// Reading and writing of every field type in Inventor ASCII, and the field factory used for
// self-described (unknown) nodes.
#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/Tokenizer.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <ostream>
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

// Internal value types: only self-described unknown nodes have fields of these types.

// An enum of a node we do not know: its words are kept as written.
struct EnumWordTraits {
    using Value = std::string;
    static constexpr const char* sfName = "SFEnum";
    static constexpr const char* mfName = "MFEnum";
    static Value read(Tokenizer& in) { return in.expectWord("an enum name"); }
    static void write(std::ostream& out, const Value& v) { out << v; }
};

// A bit mask of a node we do not know: `(A | B)` or `A`, words kept as written.
struct BitWordsTraits {
    using Value = std::vector<std::string>;
    static constexpr const char* sfName = "SFBitMask";
    static Value read(Tokenizer& in) {
        Value words;
        if (!in.acceptPunct('(')) {
            words.push_back(in.expectWord("a bit name"));
            return words;
        }
        if (in.acceptPunct(')')) return words;
        while (true) {
            words.push_back(in.expectWord("a bit name"));
            if (in.acceptPunct(')')) return words;
            if (!in.acceptPunct('|'))
                in.failAt(in.peek(), "expected '|' or ')' in a bit mask, found " +
                                         Tokenizer::describe(in.peek()));
        }
    }
    static void write(std::ostream& out, const Value& v) {
        if (v.size() == 1) {
            out << v[0];
            return;
        }
        out << '(';
        for (std::size_t i = 0; i < v.size(); ++i)
            out << (i ? " | " : "") << v[i];
        out << ')';
    }
};

struct NameTraits {
    using Value = std::string;
    static constexpr const char* sfName = "SFName";
    static constexpr const char* mfName = "MFName";
    static Value read(Tokenizer& in) { return in.expectString(); }
    static void write(std::ostream& out, const Value& v) {
        if (isPlainWord(v))
            out << v;
        else
            writeQuoted(out, v);
    }
};

template <class Int, const char* SF, const char* MF> struct ShortTraits {
    using Value = Int;
    static constexpr const char* sfName = SF;
    static constexpr const char* mfName = MF;
    static Value read(Tokenizer& in) {
        const std::int32_t v = in.readInt32();
        if (v < std::numeric_limits<Int>::min() || v > std::numeric_limits<Int>::max())
            in.fail("value " + std::to_string(v) + " is out of range for " + SF);
        return static_cast<Int>(v);
    }
    static void write(std::ostream& out, const Value& v) { writeNumber(out, std::int32_t(v)); }
};
constexpr char sfShort[] = "SFShort", mfShort[] = "MFShort";
constexpr char sfUShort[] = "SFUShort", mfUShort[] = "MFUShort";

template <int N, const char* SF, const char* MF> struct DoubleTraits {
    using Value = std::conditional_t<N == 1, double, glm::vec<N, double>>;
    static constexpr const char* sfName = SF;
    static constexpr const char* mfName = MF;
    static Value read(Tokenizer& in) {
        if constexpr (N == 1) {
            return in.readDouble();
        } else {
            Value v;
            for (int i = 0; i < N; ++i)
                v[i] = in.readDouble();
            return v;
        }
    }
    static void write(std::ostream& out, const Value& v) {
        if constexpr (N == 1) {
            writeNumber(out, v);
        } else {
            for (int i = 0; i < N; ++i) {
                if (i) out << ' ';
                writeNumber(out, v[i]);
            }
        }
    }
};
constexpr char sfDouble[] = "SFDouble", mfDouble[] = "MFDouble";
constexpr char sfTime[] = "SFTime", mfTime[] = "MFTime";
constexpr char sfVec2d[] = "SFVec2d", mfVec2d[] = "MFVec2d";
constexpr char sfVec3d[] = "SFVec3d", mfVec3d[] = "MFVec3d";
constexpr char sfVec4d[] = "SFVec4d", mfVec4d[] = "MFVec4d";

struct ColorRGBATraits {
    using Value = glm::vec4;
    static constexpr const char* sfName = "SFColorRGBA";
    static constexpr const char* mfName = "MFColorRGBA";
    static Value read(Tokenizer& in) { return Vec4fTraits::read(in); }
    static void write(std::ostream& out, const Value& v) { Vec4fTraits::write(out, v); }
};

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

// ---- SField / MField -------------------------------------------------------------------------

template <class Traits> void SField<Traits>::read(FieldInput& in) {
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
    Tokenizer& tokens = in.tokens();
    std::vector<Value> values;
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

void SFEnum::read(FieldInput& in) {
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
    Tokenizer& tokens = in.tokens();
    std::vector<ref_ptr<Node>> values;
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
        addPair<ShortTraits<std::int16_t, sfShort, mfShort>>(t);
        addPair<ShortTraits<std::uint16_t, sfUShort, mfUShort>>(t);
        addPair<DoubleTraits<1, sfDouble, mfDouble>>(t);
        addPair<DoubleTraits<1, sfTime, mfTime>>(t);
        addPair<DoubleTraits<2, sfVec2d, mfVec2d>>(t);
        addPair<DoubleTraits<3, sfVec3d, mfVec3d>>(t);
        addPair<DoubleTraits<4, sfVec4d, mfVec4d>>(t);
        addPair<ColorRGBATraits>(t);
        // Enums of unknown nodes have no name table: their words are kept as written.
        addPair<EnumWordTraits>(t);
        t.emplace_back(BitWordsTraits::sfName, &make<SField<BitWordsTraits>>);
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
