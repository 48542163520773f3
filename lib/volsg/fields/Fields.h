#pragma once
// The concrete field types of docs/SCENE-FORMAT.md section 1: SF* single values and MF* lists.

#include <cstdint>
#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <volsg/fields/Field.h>
#include <volsg/fields/Values.h>

namespace volsg {

class Tokenizer;

class BinaryInput;

/// How one value type is read and written; one struct per Inventor value type. `binarySize`
/// is the least number of bytes one value takes in a binary file (a count read there is
/// checked against the bytes left with it before anything is allocated).
#define VOLSG_VALUE_TRAITS(Traits, Type, SFName, MFName, BinarySize)                               \
    struct Traits {                                                                                \
        using Value = Type;                                                                        \
        static constexpr const char* sfName = SFName;                                              \
        static constexpr const char* mfName = MFName;                                              \
        static constexpr std::size_t binarySize = BinarySize;                                      \
        static Value read(Tokenizer& in);                                                          \
        static Value readBinary(BinaryInput& in);                                                  \
        static void write(std::ostream& out, const Value& v);                                      \
    };
VOLSG_VALUE_TRAITS(FloatTraits, float, "SFFloat", "MFFloat", 4)
VOLSG_VALUE_TRAITS(Int32Traits, std::int32_t, "SFInt32", "MFInt32", 4)
VOLSG_VALUE_TRAITS(UInt32Traits, std::uint32_t, "SFUInt32", "MFUInt32", 4)
VOLSG_VALUE_TRAITS(BoolTraits, bool, "SFBool", "MFBool", 4)
VOLSG_VALUE_TRAITS(StringTraits, std::string, "SFString", "MFString", 4)
VOLSG_VALUE_TRAITS(Vec2fTraits, glm::vec2, "SFVec2f", "MFVec2f", 8)
VOLSG_VALUE_TRAITS(Vec3fTraits, glm::vec3, "SFVec3f", "MFVec3f", 12)
VOLSG_VALUE_TRAITS(Vec4fTraits, glm::vec4, "SFVec4f", "MFVec4f", 16)
VOLSG_VALUE_TRAITS(ColorTraits, glm::vec3, "SFColor", "MFColor", 12)
VOLSG_VALUE_TRAITS(RotationTraits, Rotation, "SFRotation", "MFRotation", 16)
VOLSG_VALUE_TRAITS(PlaneTraits, Plane, "SFPlane", "MFPlane", 16)
VOLSG_VALUE_TRAITS(MatrixTraits, glm::mat4, "SFMatrix", "MFMatrix", 64)
// Types no node of the library has, for engines and for Inventor nodes the reader keeps as
// unknown nodes (docs/SCENE-FORMAT.md section 1.4).
VOLSG_VALUE_TRAITS(NameTraits, std::string, "SFName", "MFName", 4)
VOLSG_VALUE_TRAITS(ShortTraits, std::int16_t, "SFShort", "MFShort", 4)
VOLSG_VALUE_TRAITS(UShortTraits, std::uint16_t, "SFUShort", "MFUShort", 4)
VOLSG_VALUE_TRAITS(DoubleTraits, double, "SFDouble", "MFDouble", 8)
VOLSG_VALUE_TRAITS(TimeTraits, double, "SFTime", "MFTime", 8)
VOLSG_VALUE_TRAITS(Vec2dTraits, glm::dvec2, "SFVec2d", "MFVec2d", 16)
VOLSG_VALUE_TRAITS(Vec3dTraits, glm::dvec3, "SFVec3d", "MFVec3d", 24)
VOLSG_VALUE_TRAITS(Vec4dTraits, glm::dvec4, "SFVec4d", "MFVec4d", 32)
VOLSG_VALUE_TRAITS(ColorRGBATraits, glm::vec4, "SFColorRGBA", "MFColorRGBA", 16)
VOLSG_VALUE_TRAITS(Vec2sTraits, glm::ivec2, "SFVec2s", "MFVec2s", 8)
VOLSG_VALUE_TRAITS(Vec3sTraits, glm::ivec3, "SFVec3s", "MFVec3s", 12)
VOLSG_VALUE_TRAITS(Vec2i32Traits, glm::ivec2, "SFVec2i32", "MFVec2i32", 8)
VOLSG_VALUE_TRAITS(Vec3i32Traits, glm::ivec3, "SFVec3i32", "MFVec3i32", 12)
VOLSG_VALUE_TRAITS(Vec4i32Traits, glm::ivec4, "SFVec4i32", "MFVec4i32", 16)
/// An enum of a node whose names the reader does not know: the word kept as written.
VOLSG_VALUE_TRAITS(EnumWordTraits, std::string, "SFEnum", "MFEnum", 4)
/// A bit mask of a node whose names the reader does not know: `(A | B)` or `A`, words kept.
VOLSG_VALUE_TRAITS(BitWordsTraits, std::vector<std::string>, "SFBitMask", "MFBitMask", 4)
VOLSG_VALUE_TRAITS(ImageTraits, ImageValue, "SFImage", "MFImage", 12)
#undef VOLSG_VALUE_TRAITS

/// A single value.
template <class Traits> class SField final : public Field {
public:
    using Value = typename Traits::Value;
    SField(Node* owner, const char* name, Value initial = Value{})
        : Field(owner, name), value_(std::move(initial)) {}

    const Value& getValue() const { return value_; }
    const Value& operator()() const { return value_; }
    void setValue(Value v) {
        value_ = std::move(v);
        changed();
    }
    SField& operator=(Value v) {
        setValue(std::move(v));
        return *this;
    }

    const char* typeName() const override { return Traits::sfName; }
    void read(FieldInput& in) override;
    void write(FieldOutput& out) const override;
    bool equals(const Field& other) const override;
    void copyFrom(const Field& other) override;

private:
    Value value_;
};

/// A list of values: `[ v1, v2 ]`, commas optional, or one value without brackets.
template <class Traits> class MField final : public Field {
public:
    using Value = typename Traits::Value;
    MField(Node* owner, const char* name, std::vector<Value> initial = {})
        : Field(owner, name), values_(std::move(initial)) {}

    const std::vector<Value>& getValues() const { return values_; }
    const std::vector<Value>& operator()() const { return values_; }
    std::size_t size() const { return values_.size(); }
    bool empty() const { return values_.empty(); }
    /// `const Value&`, except `bool` for MFBool (std::vector<bool> has no references).
    typename std::vector<Value>::const_reference operator[](std::size_t i) const {
        return values_[i];
    }
    void setValues(std::vector<Value> v) {
        values_ = std::move(v);
        changed();
    }
    void set1Value(std::size_t i, Value v) {
        if (i >= values_.size()) values_.resize(i + 1);
        values_[i] = std::move(v);
        changed();
    }
    MField& operator=(std::vector<Value> v) {
        setValues(std::move(v));
        return *this;
    }

    const char* typeName() const override { return Traits::mfName; }
    void read(FieldInput& in) override;
    void write(FieldOutput& out) const override;
    bool equals(const Field& other) const override;
    void copyFrom(const Field& other) override;

private:
    std::vector<Value> values_;
};

using SFFloat = SField<FloatTraits>;
using SFInt32 = SField<Int32Traits>;
using SFUInt32 = SField<UInt32Traits>;
using SFBool = SField<BoolTraits>;
using SFString = SField<StringTraits>;
using SFVec2f = SField<Vec2fTraits>;
using SFVec3f = SField<Vec3fTraits>;
using SFVec4f = SField<Vec4fTraits>;
using SFColor = SField<ColorTraits>;
using SFRotation = SField<RotationTraits>;
using SFPlane = SField<PlaneTraits>;
using SFMatrix = SField<MatrixTraits>;
using MFFloat = MField<FloatTraits>;
using MFInt32 = MField<Int32Traits>;
using MFUInt32 = MField<UInt32Traits>;
using MFBool = MField<BoolTraits>;
using MFString = MField<StringTraits>;
using MFVec2f = MField<Vec2fTraits>;
using MFVec3f = MField<Vec3fTraits>;
using MFVec4f = MField<Vec4fTraits>;
using MFColor = MField<ColorTraits>;
using MFRotation = MField<RotationTraits>;
using MFPlane = MField<PlaneTraits>;
using MFMatrix = MField<MatrixTraits>;
using SFName = SField<NameTraits>;
using MFName = MField<NameTraits>;
using SFShort = SField<ShortTraits>;
using MFShort = MField<ShortTraits>;
using SFUShort = SField<UShortTraits>;
using MFUShort = MField<UShortTraits>;
using SFDouble = SField<DoubleTraits>;
using MFDouble = MField<DoubleTraits>;
using SFTime = SField<TimeTraits>;
using MFTime = MField<TimeTraits>;
using SFImage = SField<ImageTraits>;
/// An enum or bit mask of a node whose names the reader does not know (words as written).
using SFEnumWord = SField<EnumWordTraits>;
using MFEnumWord = MField<EnumWordTraits>;
using SFBitWords = SField<BitWordsTraits>;

/// Inventor's SFTrigger: no value, only the event of being touched. `touch()` fires it;
/// `count()` says how often it fired, so an engine sees a new event by a changed count.
class SFTrigger final : public Field {
public:
    SFTrigger(Node* owner, const char* name) : Field(owner, name) {}
    void touch() {
        ++count_;
        changed();
    }
    std::uint64_t count() const { return count_; }

    const char* typeName() const override { return "SFTrigger"; }
    void read(FieldInput& in) override;
    void write(FieldOutput& out) const override;
    bool equals(const Field& other) const override;
    void copyFrom(const Field& other) override;

private:
    std::uint64_t count_ = 0;
};

/// A value of a node of unknown type read without a description (ReadOptions::keepUnknownTypes,
/// docs/SCENE-FORMAT.md section 1.4): its tokens as written, given back unchanged. Node values
/// inside it are not supported: those become SFNode/MFNode fields.
class RawValueField final : public Field {
public:
    struct Piece {
        enum class Kind { Word, String, Punct } kind;
        std::string text;
        bool operator==(const Piece&) const = default;
    };
    RawValueField(Node* owner, const char* name) : Field(owner, name) {}
    const std::vector<Piece>& pieces() const { return pieces_; }
    void setPieces(std::vector<Piece> p) {
        pieces_ = std::move(p);
        changed();
    }

    const char* typeName() const override { return "RawValue"; }
    void read(FieldInput& in) override;
    void write(FieldOutput& out) const override;
    bool equals(const Field& other) const override;
    void copyFrom(const Field& other) override;

private:
    std::vector<Piece> pieces_;
};

/// Names of an SFEnum or SFBitMask field's values, as written in files.
struct EnumValues {
    std::vector<std::pair<const char*, int>> entries;
    EnumValues(std::initializer_list<std::pair<const char*, int>> e) : entries(e) {}
    const char* nameOf(int value) const; ///< null if none
    bool valueOf(std::string_view name, int& value) const;
};

/// One of a fixed set of named values (`renderMode DVR`).
class SFEnum final : public Field {
public:
    SFEnum(Node* owner, const char* name, const EnumValues& names, int initial)
        : Field(owner, name), names_(&names), value_(initial) {}
    int getValue() const { return value_; }
    int operator()() const { return value_; }
    void setValue(int v) {
        value_ = v;
        changed();
    }
    SFEnum& operator=(int v) {
        setValue(v);
        return *this;
    }
    const EnumValues& names() const { return *names_; }

    const char* typeName() const override { return "SFEnum"; }
    void read(FieldInput& in) override;
    void write(FieldOutput& out) const override;
    bool equals(const Field& other) const override;
    void copyFrom(const Field& other) override;

private:
    const EnumValues* names_;
    int value_;
};

/// A set of named bits: `(A | B)` or a single name.
class SFBitMask final : public Field {
public:
    SFBitMask(Node* owner, const char* name, const EnumValues& bits, int initial)
        : Field(owner, name), bits_(&bits), value_(initial) {}
    int getValue() const { return value_; }
    int operator()() const { return value_; }
    void setValue(int v) {
        value_ = v;
        changed();
    }
    const EnumValues& names() const { return *bits_; }

    const char* typeName() const override { return "SFBitMask"; }
    void read(FieldInput& in) override;
    void write(FieldOutput& out) const override;
    bool equals(const Field& other) const override;
    void copyFrom(const Field& other) override;

private:
    const EnumValues* bits_;
    int value_;
};

/// A node value (`Cube { }`, `USE name`, or `NULL`).
class SFNode final : public Field {
public:
    SFNode(Node* owner, const char* name);
    ~SFNode() override;
    Node* getValue() const;
    void setValue(ref_ptr<Node> n);

    const char* typeName() const override { return "SFNode"; }
    void read(FieldInput& in) override;
    void write(FieldOutput& out) const override;
    bool equals(const Field& other) const override;
    void copyFrom(const Field& other) override;

private:
    ref_ptr<Node> value_;
};

/// A list of node values.
class MFNode final : public Field {
public:
    MFNode(Node* owner, const char* name);
    ~MFNode() override;
    const std::vector<ref_ptr<Node>>& getValues() const { return values_; }
    void setValues(std::vector<ref_ptr<Node>> v);

    const char* typeName() const override { return "MFNode"; }
    void read(FieldInput& in) override;
    void write(FieldOutput& out) const override;
    bool equals(const Field& other) const override;
    void copyFrom(const Field& other) override;

private:
    std::vector<ref_ptr<Node>> values_;
};

/// Sets `to` from `from` as Inventor's field converters do (nodes/volsg/engines: connections):
/// the same type is copied; numbers convert between the number types (a bool is 0 or 1, an
/// integer is truncated), a single value to a list of one, a list to its first value (none:
/// `to` is left as it is), vectors, rotations, planes and matrices to a type of as many
/// numbers, and anything to SFString/MFString as its text. Returns whether `to` changed (its
/// owner's version is bumped only then); throws volsg::Error for types that do not convert.
bool assignConverted(Field& to, const Field& from);

/// Leaves only value `i` of a list field (MF*); false if it has none or is not a list.
bool keepOnlyValue(Field& list, std::size_t i);
/// Appends the values of `from`, a list field of the same type, to `to`.
void appendValues(Field& to, const Field& from);

/// Whether two fields of the same type hold the same values, numbers allowed to differ by
/// `relativeTolerance` of their magnitude (at least of 1): text written with 8 significant
/// digits, as Coin writes floats, reads back within 1e-7 of the float it came from.
bool valuesClose(const Field& a, const Field& b, double relativeTolerance);

/// A new field of the same type and value as `from`, without owner (a snapshot).
std::unique_ptr<Field> cloneField(const Field& from);

/// Creates an empty field of a type named in a file (`fields [ SFFloat a ]`), for nodes the
/// reader keeps as opaque; null for an unknown type name.
std::unique_ptr<Field> createFieldOfType(std::string_view typeName, Node* owner, const char* name);

} // namespace volsg
