#include "SceneTextSave.h"

#include <algorithm>
#include <cctype>
#include <cstring>

#include <volsg/core/Error.h>
#include <volsg/editors/FieldText.h>
#include <volsg/fields/Field.h>
#include <volsg/io/SceneWriter.h>

namespace volsg {

namespace {

/// A token of Inventor ASCII with its byte span (what the reader's Tokenizer reads, without
/// values: comments and white space skipped, strings kept whole with their quotes).
struct Span {
    enum class Kind { End, Word, String, Punct } kind = Kind::End;
    std::size_t begin = 0, end = 0;
};

bool isPunctChar(char c) {
    return std::strchr("{}[](),|", c) != nullptr && c != '\0';
}

} // namespace

/// Walks the text alongside the graph it was read into, recording each node's braces and its
/// fields' value spans. Throws Error (the refusal) where the two do not match.
class SceneTextWalker {
public:
    SceneTextWalker(const std::string& text, SceneTextSnapshot& snapshot)
        : text_(text), snapshot_(snapshot) {}

    void walkFile(Node& root) {
        std::size_t header = text_.find('\n');
        if (text_.rfind("#Inventor V2.1 ascii", 0) != 0 || header == std::string::npos)
            throw Error("not an Inventor V2.1 ASCII file");
        pos_ = header + 1;
        snapshot_.topLevelStart_ = pos_;
        std::vector<Node*> top;
        // How many top-level nodes: one is the root itself, several the reader's wrapper.
        std::size_t count = 0;
        {
            const std::size_t save = pos_;
            while (peek().kind != Span::Kind::End) {
                skipNodeSpec();
                ++count;
            }
            pos_ = save;
        }
        if (count == 1) {
            walkNode(&root);
        } else {
            snapshot_.rootIsWrapper_ = true;
            auto* children = root.children();
            if (!children || children->size() != count)
                throw Error("the file's top-level nodes are not the scene's");
            SceneTextSnapshot::NodeRecord& record = snapshot_.nodes_[&root];
            record.values.resize(root.fieldCount());
            record.spans.resize(root.fieldCount());
            for (const auto& child : *children) {
                record.children.push_back(child.get());
                walkNode(child.get());
            }
        }
        if (peek().kind != Span::Kind::End) throw Error("text after the last node");
    }

private:
    Span peek() {
        const std::size_t save = pos_;
        const Span s = next();
        pos_ = save;
        return s;
    }

    Span next() {
        for (;;) {
            while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])))
                ++pos_;
            if (pos_ < text_.size() && text_[pos_] == '#') {
                while (pos_ < text_.size() && text_[pos_] != '\n')
                    ++pos_;
                continue;
            }
            break;
        }
        Span s;
        s.begin = pos_;
        if (pos_ >= text_.size()) return s;
        const char c = text_[pos_];
        if (c == '"') {
            s.kind = Span::Kind::String;
            ++pos_;
            while (pos_ < text_.size() && text_[pos_] != '"')
                pos_ += text_[pos_] == '\\' ? 2 : 1;
            pos_ = std::min(pos_ + 1, text_.size());
        } else if (isPunctChar(c)) {
            s.kind = Span::Kind::Punct;
            ++pos_;
        } else {
            s.kind = Span::Kind::Word;
            while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_])) &&
                   text_[pos_] != '"' && text_[pos_] != '#' && !isPunctChar(text_[pos_]))
                ++pos_;
        }
        s.end = pos_;
        return s;
    }

    std::string_view textOf(const Span& s) const {
        return std::string_view(text_).substr(s.begin, s.end - s.begin);
    }
    bool isPunct(const Span& s, char c) const {
        return s.kind == Span::Kind::Punct && text_[s.begin] == c;
    }

    /// Past a balanced group that starts at the '{', '[' or '(' just read.
    void skipGroup(char open) {
        const char close = open == '{' ? '}' : open == '[' ? ']' : ')';
        int depth = 1;
        while (depth > 0) {
            const Span s = next();
            if (s.kind == Span::Kind::End) throw Error("unbalanced brackets");
            if (isPunct(s, open)) ++depth;
            if (isPunct(s, close)) --depth;
        }
    }

    /// Past `USE name`, `NULL` or `[DEF name] Type { ... }`.
    void skipNodeSpec() {
        Span s = next();
        if (s.kind != Span::Kind::Word) throw Error("expected a node");
        if (textOf(s) == "USE") {
            next();
            return;
        }
        if (textOf(s) == "NULL") return;
        if (textOf(s) == "DEF") {
            next();
            s = next();
        }
        if (!isPunct(next(), '{')) throw Error("expected '{'");
        skipGroup('{');
    }

    /// A node at pos_: records it (the first time it appears) and walks its contents.
    void walkNode(Node* node) {
        Span s = next();
        if (textOf(s) == "USE") { // a shared node, walked where it was DEF'd
            next();
            if (!snapshot_.nodes_.count(node)) throw Error("USE before DEF");
            return;
        }
        if (textOf(s) == "DEF") {
            next();
            s = next();
        }
        const Span open = next();
        if (s.kind != Span::Kind::Word || !isPunct(open, '{')) throw Error("expected a node");
        if (textOf(s) != node->type().name())
            throw Error("the file's " + std::string(textOf(s)) + " is the scene's " +
                        node->type().name());
        SceneTextSnapshot::NodeRecord& record = snapshot_.nodes_[node];
        record.open = open.begin;
        record.lastEntryEnd = open.end;
        record.values.resize(node->fieldCount());
        record.spans.resize(node->fieldCount());
        std::vector<ref_ptr<Node>> none;
        const auto& children = node->children() ? *node->children() : none;
        std::size_t child = 0;
        for (;;) {
            const Span t = peek();
            if (t.kind == Span::Kind::End) throw Error("a node without its '}'");
            if (isPunct(t, '}')) {
                next();
                record.close = t.begin;
                break;
            }
            const std::string word(textOf(t));
            Field* field = t.kind == Span::Kind::Word ? node->field(word) : nullptr;
            if (word == "fields" && !field) { // a described node's field list
                next();
                if (isPunct(next(), '[')) skipGroup('[');
                continue;
            }
            if (field) {
                next();
                walkValue(*node, *field, record);
                continue;
            }
            // A child node.
            if (child >= children.size()) throw Error("more children in the file than read");
            record.children.push_back(children[child].get());
            walkNode(children[child++].get());
        }
        if (child != children.size()) throw Error("fewer children in the file than read");
    }

    /// A field's value after its name: up to the next field name, child node or '}'.
    void walkValue(Node& node, Field& field, SceneTextSnapshot::NodeRecord& record) {
        std::size_t index = 0;
        while (index < node.fieldCount() && node.fieldAt(index) != &field)
            ++index;
        SceneTextSnapshot::ValueSpan span;
        span.present = true;
        span.begin = span.end = peek().begin;
        if (!isTextField(field)) { // a node value: skipped, never rewritten
            span.connected = true;
            const Span s = peek();
            if (isPunct(s, '[')) {
                next();
                while (!isPunct(peek(), ']'))
                    skipNodeSpec();
                next();
            } else {
                skipNodeSpec();
            }
            span.end = pos_;
        } else {
            for (;;) {
                const Span s = peek();
                if (s.kind == Span::Kind::End || isPunct(s, '}')) break;
                if (s.kind == Span::Kind::Word) {
                    const std::string word(textOf(s));
                    if (word == "~") {
                        span.connected = true;
                    } else if (word == "=") { // a connection: its source node and output
                        span.connected = true;
                        next();
                        skipNodeSpec();
                        // `.output` (or `. output`) after the source node.
                        if (peek().kind == Span::Kind::Word && textOf(peek()).front() == '.') {
                            const bool alone = textOf(next()) == ".";
                            if (alone) next();
                        }
                        span.end = pos_;
                        continue;
                    } else if (node.field(word) || word == "DEF" || word == "USE") {
                        break; // the next field or a child
                    } else {
                        const std::size_t save = pos_;
                        next();
                        const bool childFollows = isPunct(peek(), '{');
                        pos_ = save;
                        if (childFollows) break;
                    }
                }
                next();
                if (isPunct(s, '[') || isPunct(s, '(')) skipGroup(text_[s.begin]);
                span.end = pos_;
            }
        }
        if (index < record.spans.size()) record.spans[index] = span;
        record.lastEntryEnd = std::max(record.lastEntryEnd, span.end);
    }

    const std::string& text_;
    SceneTextSnapshot& snapshot_;
    std::size_t pos_ = 0;
};

SceneTextSnapshot SceneTextSnapshot::take(std::string text, Node& root) {
    SceneTextSnapshot snapshot;
    snapshot.text_ = std::move(text);
    try {
        SceneTextWalker(snapshot.text_, snapshot).walkFile(root);
    } catch (const Error& e) {
        snapshot.nodes_.clear();
        snapshot.refusal_ = e.what();
        return snapshot;
    }
    for (auto& [node, record] : snapshot.nodes_)
        for (std::size_t i = 0; i < node->fieldCount(); ++i)
            if (isTextField(*node->fieldAt(i)))
                record.values[i] = fieldValueText(*node->fieldAt(i));
    return snapshot;
}

namespace {

/// The indentation of the line holding `offset`.
std::string indentAt(const std::string& text, std::size_t offset) {
    std::size_t start = text.rfind('\n', offset == 0 ? 0 : offset - 1);
    start = start == std::string::npos ? 0 : start + 1;
    std::size_t end = start;
    while (end < text.size() && (text[end] == ' ' || text[end] == '\t'))
        ++end;
    return text.substr(start, end - start);
}

/// A node written as text (SceneWriter), without the header, each line indented.
std::string nodeText(const Node& node, const std::string& indent) {
    std::string text = writeSceneToString(node);
    const std::size_t body = text.find("\n\n");
    text = body == std::string::npos ? text : text.substr(body + 2);
    std::string out;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        if (end > start) out += indent + text.substr(start, end - start);
        out += '\n';
        start = end + 1;
    }
    return out;
}

struct Edit {
    std::size_t begin, end;
    std::string text;
};

} // namespace

std::optional<std::string> SceneTextSnapshot::patched(Node& root, std::string& reason) const {
    if (!refusal_.empty()) {
        reason = refusal_;
        return std::nullopt;
    }
    std::vector<Edit> edits;
    for (const auto& [constNode, record] : nodes_) {
        Node& node = const_cast<Node&>(*constNode);
        // Children: as read, or one node inserted in front of the root's.
        std::vector<Node*> now;
        if (const auto* children = node.children())
            for (const auto& c : *children)
                now.push_back(c.get());
        if (now != record.children) {
            const bool inserted =
                &node == &root && now.size() == record.children.size() + 1 &&
                std::equal(record.children.begin(), record.children.end(), now.begin() + 1) &&
                !nodes_.count(now.front());
            if (!inserted) {
                reason = "nodes were added, removed or moved";
                return std::nullopt;
            }
            if (rootIsWrapper_) {
                edits.push_back({topLevelStart_, topLevelStart_, nodeText(*now.front(), "")});
            } else {
                const std::string indent = indentAt(text_, record.open) + "  ";
                std::string written = nodeText(*now.front(), indent);
                written.pop_back(); // its last newline: the one after '{' comes before it
                edits.push_back({record.open + 1, record.open + 1, "\n" + written});
            }
        }
        if (&node == &root && rootIsWrapper_) continue; // no text of its own
        for (std::size_t i = 0; i < node.fieldCount() && i < record.values.size(); ++i) {
            const Field& field = *node.fieldAt(i);
            if (!isTextField(field)) continue;
            const std::string value = fieldValueText(field);
            if (value == record.values[i]) continue;
            const ValueSpan& span = record.spans[i];
            if (span.connected) {
                reason = std::string("the connected field ") + field.name() + " changed";
                return std::nullopt;
            }
            if (span.present) {
                edits.push_back({span.begin, span.end, value});
                continue;
            }
            // A field the file did not set: after the node's last field, on its own line when
            // the node spans several lines.
            const std::string body = text_.substr(record.open, record.close - record.open);
            const std::string entry = std::string(field.name()) + " " + value;
            if (body.find('\n') == std::string::npos) {
                edits.push_back({record.lastEntryEnd, record.lastEntryEnd, " " + entry});
            } else {
                const std::size_t at = record.lastEntryEnd;
                const std::string indent = at == record.open + 1
                                               ? indentAt(text_, record.open) + "  "
                                               : indentAt(text_, at);
                edits.push_back({at, at, "\n" + indent + entry});
            }
        }
    }
    // Back to front, so earlier offsets stay valid; insertions at one place keep their order.
    std::stable_sort(edits.begin(), edits.end(),
                     [](const Edit& a, const Edit& b) { return a.begin > b.begin; });
    std::string out = text_;
    for (const Edit& e : edits)
        out.replace(e.begin, e.end - e.begin, e.text);
    return out;
}

} // namespace volsg
