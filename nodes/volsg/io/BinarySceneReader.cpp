// The binary Inventor format, V2.1 and V2.0 (docs/SCENE-FORMAT.md section 1.9), as Coin and
// SGI Inventor write it: every item a big-endian 32-bit word, a 64-bit double, or a string
// (its byte count as a word, then the bytes padded to four).
//
//   node    := name [flags (2.1)] [type-prefix] fieldword [descriptions] field* [count node*]
//   name    := "DEF" defname typename | "USE" defname | "NULL" | typename
//   field   := fieldname value fieldflags [connection-source sourcefield (if CONNECTED)]
//
// flags: IS_ENGINE 1, IS_GROUP 2 (2.0 files have no flags: a group is a type that is one).
// fieldword: the number of fields in the low byte, NOT_BUILTIN 0x40 in the next (then the
// field descriptions, type and name for each, come first). fieldflags: IGNORED 1, CONNECTED 2,
// DEFAULT 4. A V2.0 Group has no field word.
#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>
#include <volsg/engines/GlobalField.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/BinaryInput.h>
#include <volsg/io/BinarySceneReader.h>
#include <volsg/io/Tokenizer.h>
#include <volsg/nodes/Separator.h>

#include <cstdio>
#include <optional>

namespace volsg {

namespace {

using reader::FileState;
using reader::Place;

constexpr std::uint32_t isEngineFlag = 0x01;
constexpr std::uint32_t isGroupFlag = 0x02;
constexpr std::uint32_t notBuiltinFlag = 0x40;
constexpr std::uint32_t ignoredFlag = 0x01;
constexpr std::uint32_t connectedFlag = 0x02;
constexpr std::uint32_t defaultFlag = 0x04;

std::string hex(std::uint32_t v) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "0x%X", unsigned(v));
    return buffer;
}

class BinaryParser final : public FieldInput {
public:
    BinaryParser(std::string_view data, std::size_t headerBytes, FileState& file)
        : in_(data, file.context.fileName, headerBytes, file.version), file_(file) {}

    ref_ptr<Node> readFile() {
        std::vector<ref_ptr<Node>> roots;
        while (!in_.atEnd())
            roots.push_back(readNodeValue(false, Place::Node));
        if (roots.size() == 1) return roots.front();
        ref_ptr<Separator> root = Separator::create();
        for (auto& node : roots)
            root->addChild(std::move(node));
        return root;
    }

    Tokenizer& tokens() override {
        in_.fail("internal error: a field asked for text in a binary file");
    }
    BinaryInput* binary() override { return &in_; }
    ref_ptr<Node> readNode() override { return readNodeValue(true, Place::Node); }

private:
    ref_ptr<Node> readNodeValue(bool allowNull, Place place) {
        const std::size_t at = in_.offset();
        std::string name = in_.readString("a node type name");
        if (name == "NULL") {
            if (!allowNull) in_.failAt(at, "NULL is only allowed as the value of a node field");
            return nullptr;
        }
        if (name == "USE") {
            const std::size_t nameAt = in_.offset();
            const std::string ref = in_.readString("the name after USE");
            // A connection source may also be an animated node still being read.
            if (place == Place::ConnectionSource && !file_.defined.count(ref))
                if (const auto p = file_.pending.find(ref); p != file_.pending.end())
                    return ref_ptr<Node>(p->second);
            const auto it = file_.defined.find(ref);
            if (it == file_.defined.end())
                in_.failAt(nameAt, "USE of undefined name '" + ref + "' (no complete DEF " + ref +
                                       " before it)");
            return it->second;
        }
        std::string defName;
        std::size_t typeAt = at;
        if (name == "DEF") {
            const std::size_t nameAt = in_.offset();
            defName = in_.readString("the name after DEF");
            if (defName.empty()) in_.failAt(nameAt, "empty name after DEF");
            typeAt = in_.offset();
            name = in_.readString("a node type name");
        }
        if (name.empty() || name == "DEF" || name == "USE" || name == "NULL")
            in_.failAt(typeAt,
                       "expected a node type name, found " +
                           (name.empty() ? std::string("an empty string") : "'" + name + "'"));
        ref_ptr<Node> node = readNodeBody(name, typeAt, defName, place);
        if (!defName.empty()) file_.defined[defName] = node;
        return node;
    }

    ref_ptr<Node> readNodeBody(const std::string& typeName, std::size_t typeAt,
                               const std::string& defName, Place place) {
        if (++file_.depth > maxSceneNestingDepth) failTooDeep(typeAt);
        if (++file_.nodeCount > limits::maxSceneNodes) failTooManyNodes(typeAt);
        std::uint32_t flags = 0;
        if (file_.version >= 2.1f) {
            const std::size_t flagsAt = in_.offset();
            flags = in_.readUInt32("the node flags");
            if (flags & ~(isEngineFlag | isGroupFlag))
                in_.failAt(flagsAt, "unknown node flags " + hex(flags) + " for " + typeName);
        }
        if ((flags & isEngineFlag) && place != Place::ConnectionSource)
            in_.failAt(typeAt, "'" + typeName +
                                   "' is an engine: it can only be the source of a field "
                                   "connection");

        reader::MadeNode made = makeNode(typeName, typeAt, place);
        if (!defName.empty()) made.node->setName(reader::nodeNameFromDefName(defName));
        made.node->setSourcePlace({file_.sharedName(), 0, 0}); // binary: the file alone
        const ref_ptr<Node> first = made.node;                 // kept alive for the binding below
        std::optional<reader::EarlyBinding> early;
        if (reader::bindsEarly(*first)) early.emplace(file_, defName, *first);
        typeAt_ = typeAt;
        readFields(made, typeName); // may replace made.node (a described standard type)
        Node& node = *made.node;
        early.reset(); // children see complete nodes only

        const bool hasChildren = file_.version >= 2.1f ? (flags & isGroupFlag) != 0 : made.isGroup;
        if (hasChildren) readChildren(node, typeName);
        --file_.depth;
        if (reader::isOldForm(typeName, file_.version) && made.unknown) {
            std::string error;
            ref_ptr<Node> upgraded = reader::upgrade(*made.unknown, file_, error);
            if (!upgraded) in_.failAt(typeAt, error);
            return upgraded;
        }
        finish(node, typeAt);
        return made.node;
    }

    [[gnu::noinline]] void finish(Node& node, std::size_t typeAt) {
        try {
            node.readDone(file_.context);
        } catch (const Error& e) {
            in_.failAt(typeAt, e.message());
        }
    }

    [[gnu::noinline]] reader::MadeNode makeNode(const std::string& typeName, std::size_t typeAt,
                                                Place place) {
        reader::MadeNode made;
        if (reader::isOldForm(typeName, file_.version)) {
            ref_ptr<UnknownNode> old = reader::makeOldForm(typeName, file_.version);
            made.unknown = old.get();
            made.node = old;
            return made;
        }
        // Whether the type describes its fields is only known from the field word, after it:
        // an unknown type is made as described here and its description read (or, when the
        // word says it is built in, its fields come from the table of Inventor's types).
        made = reader::makeNode(typeName, false, place, file_);
        if (!made.node) {
            made = reader::makeNode(typeName, true, place, file_);
            describedOnly_ = true;
            if (!made.node) in_.failAt(typeAt, made.error);
        } else {
            describedOnly_ = false;
        }
        return made;
    }

    [[gnu::noinline]] void readFields(reader::MadeNode& made, const std::string& typeName) {
        Node& node = *made.node;
        const bool onlyIfDescribed = describedOnly_;
        if (auto* global = dynamic_cast<GlobalField*>(&node)) {
            readGlobalField(*global);
            return;
        }
        if (reader::isTypedEngine(node)) readEngineType(node, typeName);
        if (file_.version < 2.1f && typeName == "Group") {
            if (onlyIfDescribed) failNoFieldTypes(typeName);
            return; // a V2.0 Group has no field word
        }
        const std::size_t wordAt = in_.offset();
        const std::uint32_t word = in_.readUInt32("the field count");
        const std::uint32_t count = word & 0xFF;
        const std::uint32_t fieldFlags = (word >> 8) & 0xFF;
        if ((word >> 16) != 0 || (fieldFlags & ~notBuiltinFlag) != 0)
            in_.failAt(wordAt, "unknown field flags " + hex(word >> 8) + " in the field word of " +
                                   typeName);
        const bool described = (fieldFlags & notBuiltinFlag) != 0;
        if (!described && onlyIfDescribed) failNoFieldTypes(typeName);
        if (described) {
            if (made.unknown && !onlyIfDescribed &&
                made.unknown->description() == UnknownNode::Description::Inventor) {
                // A standard type written with its description: keep what the file says.
                ref_ptr<UnknownNode> fresh = UnknownNode::create(typeName);
                fresh->setName(node.getName());
                made.unknown = fresh.get();
                made.node = fresh;
            }
            if (made.unknown) made.unknown->setDescription(UnknownNode::Description::Declared);
            readDescriptions(*made.node, made.unknown, count, typeName);
        }
        for (std::uint32_t i = 0; i < count; ++i)
            readField(made, typeName);
    }

    [[gnu::noinline]] [[noreturn]] void failNoFieldTypes(const std::string& typeName) {
        reader::MadeNode made = reader::makeNode(typeName, false, Place::Node, file_);
        in_.failAt(typeAt_,
                   made.error.empty() ? "unknown node type '" + typeName + "'" : made.error);
    }

    // SelectOne, Gate, Concatenate: "type" and the input's field type come first.
    [[gnu::noinline]] void readEngineType(Node& node, const std::string& typeName) {
        const std::size_t at = in_.offset();
        if (in_.readString("the word 'type'") != "type")
            in_.failAt(at, "expected 'type' and the input type of " + typeName);
        const std::size_t typeAt = in_.offset();
        const std::string inputType = in_.readString("the input type");
        auto* type = dynamic_cast<SFName*>(node.field("type"));
        if (!type || !createFieldOfType(inputType, nullptr, "probe") ||
            inputType.substr(0, 2) != "MF")
            in_.failAt(typeAt, "'" + inputType + "' is not a list field type (the input type of " +
                                   typeName + ")");
        type->setValue(inputType);
    }

    // "type" field-type, a field count that must be 1, the field's name, its value and flags.
    [[gnu::noinline]] void readGlobalField(GlobalField& global) {
        const std::size_t at = in_.offset();
        if (in_.readString("the word 'type'") != "type")
            in_.failAt(at, "expected 'type' and the field type of a GlobalField");
        const std::size_t typeAt = in_.offset();
        global.type.setValue(in_.readString("the field type"));
        const std::size_t countAt = in_.offset();
        const std::uint32_t count = in_.readUInt32("the field count");
        if (count != 1)
            in_.failAt(countAt,
                       "a GlobalField has one field, the file says " + std::to_string(count));
        const std::size_t nameAt = in_.offset();
        const std::string name = in_.readString("the field name");
        Field* value = global.makeValueField(name);
        if (!value) {
            if (name.empty()) in_.failAt(nameAt, "empty field name in a GlobalField");
            in_.failAt(typeAt, "GlobalField type '" + global.type() + "' is not a field type");
        }
        readValueAndFlags(*value, name, "GlobalField");
    }

    [[gnu::noinline]] void readDescriptions(Node& node, UnknownNode* unknown, std::uint32_t count,
                                            const std::string& typeName) {
        for (std::uint32_t i = 0; i < count; ++i) {
            const std::size_t typeAt = in_.offset();
            std::string fieldType = in_.readString("a field type");
            // VRML 2 descriptions may say field, exposedField, eventIn, eventOut first.
            if (fieldType == "field" || fieldType == "exposedField" || fieldType == "eventIn" ||
                fieldType == "eventOut")
                fieldType = in_.readString("a field type");
            const std::size_t nameAt = in_.offset();
            const std::string fieldName = in_.readString("a field name");
            if (fieldName.empty()) in_.failAt(nameAt, "empty field name in " + typeName);
            if (unknown) {
                if (unknown->findField(fieldName))
                    in_.failAt(nameAt,
                               "field '" + fieldName + "' is declared twice in " + typeName);
                if (!unknown->addField(fieldType, fieldName))
                    in_.failAt(typeAt, "unknown field type '" + fieldType +
                                           "' in the fields description of " + typeName);
            } else {
                const Field* f = node.field(fieldName);
                if (!f)
                    in_.failAt(nameAt, typeName + " has no field '" + fieldName +
                                           "' (declared in its fields description)");
                if (fieldType != f->typeName())
                    in_.failAt(typeAt, "field '" + fieldName + "' of " + typeName + " is " +
                                           f->typeName() + ", but the file declares it " +
                                           fieldType);
            }
        }
    }

    [[gnu::noinline]] void readField(reader::MadeNode& made, const std::string& typeName) {
        const std::size_t nameAt = in_.offset();
        const std::string name = in_.readString("a field name");
        Field* field = made.unknown ? made.unknown->findField(name) : made.node->field(name);
        if (!field && !made.unknown) {
            // A field of the standard type that our class lacks: kept as the standard type.
            if (ref_ptr<UnknownNode> u =
                    reader::demoteToInventorType(*made.node, typeName, name, file_)) {
                made.isGroup = made.node->children() != nullptr;
                made.node = u;
                made.unknown = u.get();
                field = u->findField(name);
            }
        }
        UnknownNode* unknown = made.unknown;
        if (!field) {
            if (unknown && unknown->description() == UnknownNode::Description::Inventor)
                in_.failAt(nameAt, "unknown field '" + name + "' in " + typeName +
                                       " (not a field of the standard Inventor type, or of a "
                                       "field type this reader cannot hold: SFPath, SFEngine, "
                                       "SFImage3)");
            in_.failAt(nameAt, "unknown field '" + name + "' in " + typeName);
        }
        readValueAndFlags(*field, name, typeName);
    }

    void readValueAndFlags(Field& field, const std::string& name, const std::string& typeName) {
        if (dynamic_cast<SFNode*>(&field) || dynamic_cast<MFNode*>(&field))
            field.read(*this);
        else
            readPlainValue(field, name, typeName);
        const std::size_t flagsAt = in_.offset();
        const std::uint32_t flags = in_.readUInt32("the field flags");
        if (flags & ~(ignoredFlag | connectedFlag | defaultFlag))
            in_.failAt(flagsAt,
                       "unknown field flags " + hex(flags) + " of '" + name + "' of " + typeName);
        if (flags & ignoredFlag) field.setIgnored(true);
        if (flags & defaultFlag) field.setDefault(true);
        if (flags & connectedFlag) readConnection(field, name, typeName);
    }

    [[gnu::noinline]] void readPlainValue(Field& field, const std::string& name,
                                          const std::string& typeName) {
        try {
            field.read(*this);
        } catch (const Error&) {
            in_.failAt(in_.lastErrorOffset(), "field '" + name + "' of " + typeName + " expects " +
                                                  field.typeName() + ": " + in_.lastErrorMessage());
        }
    }

    [[gnu::noinline]] void readConnection(Field& field, const std::string& name,
                                          const std::string& typeName) {
        const std::size_t at = in_.offset();
        ref_ptr<Node> source = readNodeValue(false, Place::ConnectionSource);
        const std::string output = in_.readString("the name of a field or output");
        std::string error;
        if (!reader::checkConnection(field, *source, output, error))
            in_.failAt(at, "field '" + name + "' of " + typeName + ": " + error);
        field.connectFrom(std::move(source), output);
    }

    [[gnu::noinline]] void readChildren(Node& node, const std::string& typeName) {
        const std::size_t at = in_.offset();
        const std::uint32_t count = in_.readUInt32("the number of children");
        std::vector<ref_ptr<Node>>* children = node.children();
        if (!children)
            in_.failAt(at, typeName + " is not a group here, but the file gives it " +
                               std::to_string(count) + " children");
        if (count > limits::maxSceneChildren)
            in_.failAt(at, typeName + " has more than " + std::to_string(limits::maxSceneChildren) +
                               " children");
        // A child takes at least its type name (8 bytes) and a word.
        in_.requireItems(count, 12, "the children", at);
        for (std::uint32_t i = 0; i < count; ++i)
            children->push_back(readNodeValue(false, Place::Node));
    }

    [[gnu::noinline]] [[noreturn]] void failTooDeep(std::size_t at) {
        in_.failAt(at,
                   "nodes nested deeper than " + std::to_string(maxSceneNestingDepth) + " levels");
    }
    [[gnu::noinline]] [[noreturn]] void failTooManyNodes(std::size_t at) {
        in_.failAt(at, "more than " + std::to_string(limits::maxSceneNodes) + " nodes in one file");
    }

    BinaryInput in_;
    FileState& file_;
    bool describedOnly_ = false;
    std::size_t typeAt_ = 0; ///< where the type name of the node whose fields are read is
};

} // namespace

ref_ptr<Node> readBinaryScene(std::string_view data, std::size_t headerBytes,
                              reader::FileState& file) {
    BinaryParser parser(data, headerBytes, file);
    return parser.readFile();
}

} // namespace volsg
