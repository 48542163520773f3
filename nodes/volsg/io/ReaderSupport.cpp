#include <volsg/core/Error.h>
#include <volsg/engines/AnimatedNodes.h>
#include <volsg/engines/Engine.h>
#include <volsg/engines/EngineTypes.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/InventorTypes.h>
#include <volsg/io/ReaderSupport.h>
#include <volsg/io/Tokenizer.h>
#include <volsg/nodes/BuiltinNodes.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <mutex>
#include <sstream>
#include <typeinfo>
#include <unordered_set>
#include <vector>

namespace volsg::reader {

NodeRegistry& registry() {
    static std::once_flag once;
    NodeRegistry& r = nodeTypes();
    std::call_once(once, [&r] {
        // Both add a type only where the registry has none of that name yet, so a class the
        // node layer registers later under the same name wins.
        addAnimatedNodeTypes(r);
        addEngineTypes(r);
    });
    return r;
}

namespace {

// Edit distance (insertions, deletions, substitutions), ignoring case: "volume" is 0 from
// "Volume", "Volum" 1.
std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                              std::tolower(static_cast<unsigned char>(b[j - 1]));
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

} // namespace

std::string nearestTypeName(const std::string& typeName) {
    // Close enough to be a slip: at most a third of the name's letters (at least 2) differ.
    std::size_t best = std::max<std::size_t>(2, typeName.size() / 3) + 1;
    std::string nearest;
    if (typeName.size() > 64) return nearest;
    for (const NodeType* type : registry().all()) {
        if (type->isAbstract()) continue;
        const std::size_t d = editDistance(typeName, type->name());
        if (d < best) {
            best = d;
            nearest = type->name();
        }
    }
    return nearest;
}

MadeNode makeNode(const std::string& typeName, bool described, Place place, const FileState& file) {
    MadeNode made;
    if (const NodeType* type = registry().find(typeName)) {
        if (type->isAbstract()) {
            made.error = "node type '" + typeName + "' is abstract: it cannot appear in a file";
            return made;
        }
        made.isEngine = type->isDerivedFrom(Engine::classType());
        if (made.isEngine && place != Place::ConnectionSource) {
            made.error = "'" + typeName +
                         "' is an engine: it can only be the source of a field connection "
                         "(field = " +
                         typeName + " { ... } . output)";
            return made;
        }
        made.node = type->create();
        made.isGroup = made.node->children() != nullptr;
        return made;
    }
    const InventorType* inventor = findInventorType(typeName);
    const bool keep = file.binary || file.options.keepUnknownTypes;
    if (!described && !(keep && (inventor || !file.binary))) {
        if (inventor)
            made.error = "node type '" + typeName +
                         "' is a standard Inventor type this library has no class for (read "
                         "with ReadOptions::keepUnknownTypes to keep it as an unknown node, "
                         "or describe its fields: " +
                         typeName + " { fields [ SFFloat a, ... ] ... })";
        else if (file.binary)
            made.error = "unknown node type '" + typeName +
                         "' without a description of its fields (the binary file gives no "
                         "field types for it)";
        else if (const std::string nearest = nearestTypeName(typeName); !nearest.empty())
            made.error =
                "unknown node type '" + typeName + "' (did you mean " + nearest +
                "? A type this reader does not know must describe its fields: " + typeName +
                " { fields [ SFFloat a, ... ] ... })";
        else
            made.error =
                "unknown node type '" + typeName +
                "' (a type this reader does not know must describe its fields: " + typeName +
                " { fields [ SFFloat a, ... ] ... })";
        return made;
    }
    ref_ptr<UnknownNode> u = UnknownNode::create(typeName);
    made.unknown = u.get();
    made.isGroup = true;
    if (described) {
        u->setDescription(UnknownNode::Description::Declared);
    } else if (inventor) {
        u->setDescription(UnknownNode::Description::Inventor);
        made.isGroup = inventor->isGroup;
        // Types of fields this library cannot hold (SFPath, SFEngine, SFImage3) are left out:
        // a file that sets one is refused with a message naming the type.
        for (const auto& [name, fieldType] : inventor->fields)
            u->addField(fieldType, name);
    } else {
        u->setDescription(UnknownNode::Description::Raw);
    }
    made.node = u;
    return made;
}

namespace {

class TextOutput final : public FieldOutput {
public:
    std::ostream& stream() override { return out; }
    void writeNode(const Node*) override { throw Error("node values are not copied as text"); }
    void newline() override { out << ' '; }
    std::ostringstream out;
};

class TextInput final : public FieldInput {
public:
    explicit TextInput(const std::string& text) : text_(text), tokens_(text_, "<copy>") {}
    Tokenizer& tokens() override { return tokens_; }
    ref_ptr<Node> readNode() override { tokens_.fail("no node values here"); }

private:
    std::string text_;
    Tokenizer tokens_;
};

// The value of `from` into `to`, a field of another class of the same Inventor type (an enum
// with names into one that keeps words): through its text.
void copyValue(Field& to, const Field& from) {
    if (typeid(to) == typeid(from)) {
        to.copyFrom(from);
        return;
    }
    TextOutput out;
    from.write(out);
    TextInput in(out.out.str());
    to.read(in);
}

} // namespace

ref_ptr<UnknownNode> demoteToInventorType(Node& node, const std::string& typeName,
                                          const std::string& fieldName, const FileState& file) {
    if (!(file.binary || file.options.keepUnknownTypes)) return nullptr;
    const InventorType* inventor = findInventorType(typeName);
    if (!inventor || dynamic_cast<UnknownNode*>(&node)) return nullptr;
    bool has = false;
    for (const auto& [name, type] : inventor->fields)
        has = has || name == fieldName;
    if (!has) return nullptr;
    ref_ptr<UnknownNode> u = UnknownNode::create(typeName);
    u->setDescription(UnknownNode::Description::Inventor);
    u->setName(node.getName());
    for (const auto& [name, type] : inventor->fields) {
        Field* to = u->addField(type, name);
        const Field* from = node.field(name);
        if (!to || !from) continue;
        if (!from->isDefault()) copyValue(*to, *from);
        to->setDefault(from->isDefault());
        to->setIgnored(from->isIgnored());
        if (const FieldConnection* c = from->connection())
            to->connectFrom(c->source, c->sourceField);
    }
    return u;
}

std::string nodeNameFromDefName(const std::string& defName) {
    return defName.substr(0, defName.find('+'));
}

bool isOldForm(const std::string& typeName, float version) {
    return (version == 1.0f && typeName == "ShapeHints") ||
           (version == 2.0f && typeName == "PackedColor");
}

ref_ptr<UnknownNode> makeOldForm(const std::string& typeName, float version) {
    ref_ptr<UnknownNode> old = UnknownNode::create(typeName);
    old->setDescription(UnknownNode::Description::Inventor);
    if (typeName == "ShapeHints" && version == 1.0f) {
        old->addField("SFBitMask", "hints");
        old->addField("SFFloat", "creaseAngle");
    } else if (typeName == "PackedColor" && version == 2.0f) {
        old->addField("MFUInt32", "rgba");
    }
    return old;
}

namespace {

void setFromText(Node& node, const char* name, const std::string& text, bool ignored) {
    Field* f = node.field(name);
    if (!f) return;
    TextInput in(text);
    f->read(in);
    f->setIgnored(ignored);
}

} // namespace

// Coin's upgraders (src/upgraders): V1.0 ShapeHints had one bit mask `hints` (SOLID, ORDERED,
// CONVEX set the three V2.1 enums); V2.0 PackedColor had `rgba`, packed as ABGR, which V2.1
// calls `orderedRGBA`, packed as RGBA.
ref_ptr<Node> upgrade(UnknownNode& old, const FileState& file, std::string& error) {
    FileState current = file;
    current.options.keepUnknownTypes = true; // the V2.1 type, known or kept as Inventor's
    MadeNode made = makeNode(old.fileTypeName(), false, Place::Node, current);
    if (!made.node) {
        error = made.error;
        return nullptr;
    }
    Node& node = *made.node;
    node.setName(old.getName());
    if (old.fileTypeName() == "ShapeHints") {
        if (const auto* hints = dynamic_cast<const SFBitWords*>(old.findField("hints"));
            hints && !hints->isDefault()) {
            auto has = [&](const char* bit) {
                for (const std::string& w : hints->getValue())
                    if (w == bit) return true;
                return false;
            };
            const bool ignored = hints->isIgnored();
            setFromText(node, "shapeType", has("SOLID") ? "SOLID" : "UNKNOWN_SHAPE_TYPE", ignored);
            setFromText(node, "vertexOrdering",
                        has("ORDERED") ? "COUNTERCLOCKWISE" : "UNKNOWN_ORDERING", ignored);
            setFromText(node, "faceType", has("CONVEX") ? "CONVEX" : "UNKNOWN_FACE_TYPE", ignored);
        }
        if (const Field* crease = old.findField("creaseAngle");
            crease && (!crease->isDefault() || crease->isIgnored()))
            if (Field* f = node.field("creaseAngle")) {
                if (!crease->isDefault()) f->copyFrom(*crease);
                f->setIgnored(crease->isIgnored());
            }
    } else if (old.fileTypeName() == "PackedColor") {
        if (const auto* rgba = dynamic_cast<const MFUInt32*>(old.findField("rgba"));
            rgba && !rgba->isDefault())
            if (auto* ordered = dynamic_cast<MFUInt32*>(node.field("orderedRGBA"))) {
                std::vector<std::uint32_t> values;
                values.reserve(rgba->size());
                for (std::uint32_t v : rgba->getValues())
                    values.push_back((v << 24) | ((v << 8) & 0xff0000u) | ((v >> 8) & 0xff00u) |
                                     (v >> 24));
                ordered->setValues(std::move(values));
                ordered->setIgnored(rgba->isIgnored());
            }
    }
    node.readDone(file.context);
    return made.node;
}

Field* checkConnection(Field& target, Node& source, const std::string& name, std::string& error) {
    Field* from = connectionSourceField(source, name);
    const char* sourceType = source.type().name();
    if (const auto* u = dynamic_cast<const UnknownNode*>(&source))
        sourceType = u->fileTypeName().c_str();
    if (!from) {
        error = "no field or output '" + name + "' in " + sourceType;
        return nullptr;
    }
    if (dynamic_cast<RawValueField*>(from) || dynamic_cast<RawValueField*>(&target)) {
        error =
            "cannot connect a field whose type is not known ('" + name + "' of " + sourceType + ")";
        return nullptr;
    }
    try {
        std::unique_ptr<Field> probe = cloneField(target);
        assignConverted(*probe, *from);
    } catch (const Error& e) {
        error = "cannot connect '" + std::string(target.name()) + "' to '" + name + "' of " +
                sourceType + ": " + e.message();
        return nullptr;
    }
    return from;
}

bool bindsEarly(const Node& node) {
    return dynamic_cast<const Animated*>(&node) != nullptr;
}

void dropSelfConnections(Node& node) {
    for (std::size_t i = 0, n = node.fieldCount(); i < n; ++i) {
        Field* field = node.fieldAt(i);
        const FieldConnection* c = field ? field->connection() : nullptr;
        if (!c) continue;
        // Does the source, or a source of its fields' connections, ... lead back here?
        std::vector<Node*> stack{c->source.get()};
        std::unordered_set<const Node*> seen;
        bool cycle = false;
        while (!stack.empty() && !cycle) {
            Node* at = stack.back();
            stack.pop_back();
            if (!at || !seen.insert(at).second) continue;
            if (at == &node) {
                cycle = true;
                break;
            }
            for (std::size_t k = 0, m = at->fieldCount(); k < m; ++k)
                if (const Field* f = at->fieldAt(k); f && f->connection())
                    stack.push_back(f->connection()->source.get());
        }
        if (cycle) field->disconnect();
    }
}

EarlyBinding::EarlyBinding(FileState& file, const std::string& defName, Node& node) {
    if (defName.empty() || !bindsEarly(node)) return;
    file_ = &file;
    defName_ = &defName;
    node_ = &node;
    file.pending[defName] = &node;
}

void EarlyBinding::endName() {
    if (file_) file_->pending.erase(*defName_);
}

EarlyBinding::~EarlyBinding() {
    if (!file_) return;
    endName();
    dropSelfConnections(*node_);
}

bool isTypedEngine(const Node& node) {
    const char* name = node.type().name();
    return std::strcmp(name, "SelectOne") == 0 || std::strcmp(name, "Gate") == 0 ||
           std::strcmp(name, "Concatenate") == 0;
}

} // namespace volsg::reader
