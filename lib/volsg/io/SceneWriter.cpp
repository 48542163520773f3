#include <volsg/core/Error.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/AtomicFile.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/io/UnknownNode.h>

#include <algorithm>
#include <cstring>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace volsg {

namespace {

// A name as it can stand after DEF: letters, digits, '_' (and UTF-8 bytes), not starting with
// a digit, and not a keyword. '+' is reserved for the writer's own suffixes.
std::string fileSafeName(const std::string& name) {
    std::string out = name;
    for (char& c : out) {
        const unsigned char u = static_cast<unsigned char>(c);
        const bool ok = (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') ||
                        (u >= '0' && u <= '9') || u == '_' || u >= 0x80;
        if (!ok) c = '_';
    }
    if (!out.empty() && out[0] >= '0' && out[0] <= '9') out.insert(out.begin(), '_');
    if (out == "DEF" || out == "USE" || out == "NULL") out += '_';
    return out;
}

const char* fileTypeName(const Node& node) {
    if (const auto* unknown = dynamic_cast<const UnknownNode*>(&node))
        return unknown->fileTypeName().c_str();
    return node.type().name();
}

bool describesFields(const Node& node) {
    if (const auto* unknown = dynamic_cast<const UnknownNode*>(&node))
        return unknown->description() == UnknownNode::Description::Declared;
    return !node.type().isInventorBuiltin();
}

/// A field is written when it has a value, an ignore flag or a connection.
bool isWritten(const Field& field) {
    return !field.isDefault() || field.isIgnored() || field.connection();
}

/// Two passes: the first walks the graph in writing order to count how often each node is
/// reached and choose DEF names; the second writes.
class SceneEmitter final : public FieldOutput {
public:
    explicit SceneEmitter(std::ostream& out) : out_(out) {}

    void write(const Node& root) {
        countReferences(&root);
        chooseNames();
        out_ << "#Inventor V2.1 ascii\n\n";
        writeNode(&root);
        out_ << '\n';
    }

    std::ostream& stream() override { return out_; }

    void newline() override {
        out_ << '\n';
        for (int i = 0; i < indent_; ++i)
            out_ << "  ";
    }

    void writeNode(const Node* node) override {
        if (!node) {
            out_ << "NULL";
            return;
        }
        Visit& visit = visits_[node]; // a node only a custom field type reaches: written in full
        if (visit.written && !visit.defName.empty()) {
            out_ << "USE " << visit.defName;
            return;
        }
        visit.written = true;
        if (!visit.defName.empty()) out_ << "DEF " << visit.defName << ' ';
        out_ << fileTypeName(*node) << " {";
        ++indent_;
        if (describesFields(*node)) writeFieldDescription(*node);
        for (std::size_t i = 0, n = node->fieldCount(); i < n; ++i) {
            const Field* field = node->fieldAt(i);
            if (field && isWritten(*field)) writeField(*node, *field);
        }
        if (const auto* children = node->children())
            for (const auto& child : *children) {
                if (!child) continue; // a group cannot hold NULL in a file
                newline();
                writeNode(child.get());
            }
        --indent_;
        newline();
        out_ << '}';
    }

private:
    struct Visit {
        std::size_t first = 0; ///< event index of the first time the writer reaches the node
        std::size_t last = 0;  ///< ... and of the last time (its last USE)
        std::size_t end = 0;   ///< event index just after its body (fields and children)
        int count = 0;
        std::string defName;
        bool written = false;
    };

    // Mirrors writeNode()'s order exactly: per written field its SFNode/MFNode value (when not
    // default) and its connection's source, then the children.
    void countReferences(const Node* node) {
        if (!node) return;
        const auto [it, firstTime] = visits_.try_emplace(node);
        Visit& visit = it->second; // stable: unordered_map never moves its elements
        visit.last = events_++;
        ++visit.count;
        if (!firstTime) return;
        visit.first = visit.last;
        order_.push_back(node);
        for (std::size_t i = 0, n = node->fieldCount(); i < n; ++i) {
            const Field* field = node->fieldAt(i);
            if (!field || !isWritten(*field)) continue;
            if (!field->isDefault()) {
                if (const auto* sf = dynamic_cast<const SFNode*>(field))
                    countReferences(sf->getValue());
                else if (const auto* mf = dynamic_cast<const MFNode*>(field))
                    for (const auto& value : mf->getValues())
                        countReferences(value.get());
            }
            if (const FieldConnection* c = field->connection()) countReferences(c->source.get());
        }
        if (const auto* children = node->children())
            for (const auto& child : *children)
                countReferences(child.get());
        visit.end = events_;
    }

    // A named node keeps its name unless that could make a USE mean another node, in Coin
    // (which binds a DEF name where the node starts) or in our reader (which binds it where
    // the node ends, so a node cannot contain itself). Then, and for unnamed shared nodes, a
    // unique `+N` suffix is added, which readers drop again.
    void chooseNames() {
        std::unordered_map<std::string, std::vector<const Visit*>> holders; // by written name
        int counter = 0;
        for (const Node* node : order_) {
            Visit& visit = visits_[node];
            const std::string base = fileSafeName(node->getName());
            if (base.empty() && visit.count < 2) continue;
            if (!base.empty()) {
                std::vector<const Visit*>& earlier = holders[base];
                // Nodes whose body and uses all lie before this one can no longer interfere.
                std::erase_if(earlier, [&](const Visit* a) {
                    return a->last < visit.first && a->end <= visit.first;
                });
                const bool clash = std::any_of(earlier.begin(), earlier.end(), [&](const Visit* a) {
                    // `a` is used after this DEF, or `a` contains this node and ends (binding
                    // its name in our reader) before this node's last use.
                    return a->last > visit.first || (a->end > visit.first && visit.last >= a->end);
                });
                if (!clash) {
                    visit.defName = base;
                    earlier.push_back(&visit);
                    continue;
                }
            }
            visit.defName = base + "+" + std::to_string(counter++);
        }
    }

    void writeFieldDescription(const Node& node) {
        newline();
        out_ << "fields [";
        for (std::size_t i = 0, n = node.fieldCount(); i < n; ++i) {
            const Field* field = node.fieldAt(i);
            if (!field) continue;
            out_ << (i ? ", " : " ") << field->typeName() << ' ' << field->name();
        }
        out_ << " ]";
    }

    // name [value] [~] [= source . output]
    void writeField(const Node& node, const Field& field) {
        newline();
        out_ << field.name();
        // A trigger has no value to write.
        if (!field.isDefault() && !dynamic_cast<const SFTrigger*>(&field)) {
            out_ << ' ';
            // Continuation lines of a value go one level deeper; a single node value stays
            // level with its field, so its closing brace lines up with the field name.
            const int valueIndent = dynamic_cast<const SFNode*>(&field) ? 0 : 1;
            indent_ += valueIndent;
            try {
                field.write(*this);
            } catch (const Error& e) {
                throw Error("cannot write field '" + std::string(field.name()) + "' of " +
                            fileTypeName(node) + ": " + e.message());
            }
            indent_ -= valueIndent;
        }
        if (field.isIgnored()) out_ << " ~";
        if (const FieldConnection* c = field.connection()) {
            out_ << " = ";
            writeNode(c->source.get());
            out_ << " . " << c->sourceField;
        }
    }

    std::ostream& out_;
    int indent_ = 0;
    std::size_t events_ = 0;
    std::unordered_map<const Node*, Visit> visits_;
    std::vector<const Node*> order_; ///< nodes by first reach, which is DEF order
};

} // namespace

void writeScene(std::ostream& out, const Node& root) {
    SceneEmitter emitter(out);
    emitter.write(root);
}

std::string writeSceneToString(const Node& root) {
    std::ostringstream out;
    writeScene(out, root);
    return std::move(out).str();
}

void writeSceneToFile(const std::string& path, const Node& root) {
    writeFileAtomically(path, [&root](std::ostream& out) { writeScene(out, root); });
}

} // namespace volsg
