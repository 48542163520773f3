#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/ReadContext.h>
#include <volsg/io/RegularFile.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/Tokenizer.h>
#include <volsg/io/UnknownNode.h>
#include <volsg/nodes/BuiltinNodes.h>
#include <volsg/nodes/Separator.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <unordered_map>
#include <unordered_set>

namespace volsg {

namespace {

bool startsWith(std::string_view s, std::string_view prefix) {
    return s.substr(0, prefix.size()) == prefix;
}

std::string printable(std::string_view s) {
    constexpr std::size_t maxShown = 60;
    std::string out;
    for (std::size_t i = 0; i < s.size() && i < maxShown; ++i) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        out += (c < 0x20 || c >= 0x7f) ? '?' : char(c);
    }
    if (s.size() > maxShown) out += "...";
    return out;
}

std::string position(const Token& t) {
    return std::to_string(t.line) + ":" + std::to_string(t.column);
}

// Checks the header line and returns the text after a UTF-8 byte order mark, if any.
std::string_view checkHeader(std::string_view text, const std::string& fileName) {
    static constexpr std::string_view expected = "#Inventor V2.1 ascii";
    if (startsWith(text, "\xEF\xBB\xBF")) text.remove_prefix(3);
    if (text.empty())
        throw Error("empty file: expected the header '" + std::string(expected) + "'", fileName, 1,
                    1);
    std::string_view line = text.substr(0, text.find('\n'));
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
        line.remove_suffix(1);
    for (std::string_view accepted : {expected, std::string_view("#Inventor V2.0 ascii"),
                                      std::string_view("#VRML V1.0 ascii")}) {
        if (startsWith(line, accepted) &&
            (line.size() == accepted.size() || line[accepted.size()] == ' ' ||
             line[accepted.size()] == '\t'))
            return text;
    }
    if (startsWith(line, "#Inventor") && line.find("binary") != std::string_view::npos)
        throw Error("binary Inventor files are not supported (header '" + printable(line) +
                        "'); save the scene as ASCII ('" + std::string(expected) + "')",
                    fileName, 1, 1);
    if (startsWith(line, "#Inventor") || startsWith(line, "#VRML"))
        throw Error("unsupported header '" + printable(line) + "': expected '" +
                        std::string(expected) + "', '#Inventor V2.0 ascii' or '#VRML V1.0 ascii'",
                    fileName, 1, 1);
    throw Error("missing header: the first line must be '" + std::string(expected) + "', found '" +
                    printable(line) + "'",
                fileName, 1, 1);
}

// Coin writes shared nodes as `DEF name+N` (and unnamed ones as `DEF +N`); the suffix only
// keeps DEF names unique in the file and is not part of the node's name.
std::string nodeNameFromDefName(const std::string& defName) {
    return defName.substr(0, defName.find('+'));
}

bool isKeyword(const Token& t) {
    return t.kind == Token::Kind::Word && (t.text == "DEF" || t.text == "USE" || t.text == "NULL");
}

bool isNodeField(const Field& f) {
    return dynamic_cast<const SFNode*>(&f) || dynamic_cast<const MFNode*>(&f);
}

/// The reader proper: a recursive-descent parser over the tokens that is also the FieldInput
/// through which SFNode/MFNode fields read their nodes.
class SceneParser final : public FieldInput {
public:
    SceneParser(std::string_view text, const std::string& fileName, ReadContext context)
        : tokens_(text, fileName), context_(std::move(context)),
          fileName_(std::make_shared<const std::string>(fileName)) {}

    ref_ptr<Node> readFile() {
        std::vector<ref_ptr<Node>> roots;
        while (!tokens_.atEnd()) {
            const Token& t = tokens_.peek();
            if (t.isPunct('}')) tokens_.failAt(t, "unexpected '}': no node is open");
            roots.push_back(readNodeValue(false));
        }
        if (roots.size() == 1) return roots.front();
        ref_ptr<Separator> root = Separator::create();
        for (auto& node : roots)
            root->addChild(std::move(node));
        return root;
    }

    Tokenizer& tokens() override { return tokens_; }
    ref_ptr<Node> readNode() override { return readNodeValue(true); }

private:
    // NULL | USE name | [DEF name] Type { ... }
    ref_ptr<Node> readNodeValue(bool allowNull) {
        const Token& t = tokens_.peek();
        if (t.kind != Token::Kind::Word)
            tokens_.failAt(t, std::string("expected a node (a node type, DEF or USE") +
                                  (allowNull ? ", or NULL" : "") + "), found " +
                                  Tokenizer::describe(t));
        if (t.text == "NULL") {
            if (!allowNull) tokens_.failAt(t, "NULL is only allowed as the value of a node field");
            tokens_.next();
            return nullptr;
        }
        if (t.text == "USE") {
            tokens_.next();
            const Token& name = tokens_.peek();
            if (name.kind != Token::Kind::Word)
                tokens_.failAt(name,
                               "expected a name after USE, found " + Tokenizer::describe(name));
            const auto it = defined_.find(name.text);
            if (it == defined_.end())
                tokens_.failAt(name, "USE of undefined name '" + name.text + "' (no complete DEF " +
                                         name.text + " before it)");
            tokens_.next();
            return it->second;
        }
        std::string defName;
        if (t.text == "DEF") {
            tokens_.next();
            const Token& name = tokens_.peek();
            if (name.kind != Token::Kind::Word || isKeyword(name))
                tokens_.failAt(name,
                               "expected a name after DEF, found " + Tokenizer::describe(name));
            defName = tokens_.next().text;
            const Token& type = tokens_.peek();
            if (type.kind != Token::Kind::Word || isKeyword(type))
                tokens_.failAt(type, "expected a node type after 'DEF " + defName + "', found " +
                                         Tokenizer::describe(type));
        }
        const Token typeToken = tokens_.next();
        ref_ptr<Node> node = readNodeBody(typeToken, defName);
        // Bound only now that the node is complete: a USE inside its own body cannot make a
        // cycle.
        if (!defName.empty()) defined_[defName] = node;
        return node;
    }

    // Type { [fields [ ... ]] field values... children... }
    ref_ptr<Node> readNodeBody(const Token& typeToken, const std::string& defName) {
        const std::string& typeName = typeToken.text;
        const NodeType* type = nodeTypes().find(typeName);
        const Token& brace = tokens_.peek();
        if (!brace.isPunct('{')) {
            if (!type) tokens_.failAt(typeToken, "unknown node type '" + typeName + "'");
            tokens_.failAt(brace, "expected '{' after node type '" + typeName + "', found " +
                                      Tokenizer::describe(brace));
        }
        const Token open = tokens_.next();
        if (++depth_ > maxSceneNestingDepth)
            tokens_.failAt(open, "nodes nested deeper than " +
                                     std::to_string(maxSceneNestingDepth) + " levels");

        if (++nodeCount_ > limits::maxSceneNodes) failTooManyNodes(typeToken);
        ref_ptr<Node> node = type ? type->create() : nullptr;
        const bool described = tokens_.peek().isWord("fields") && !(node && node->field("fields"));
        UnknownNode* unknown = nullptr;
        if (!node) {
            if (type)
                tokens_.failAt(typeToken, "node type '" + typeName +
                                              "' is abstract: it cannot "
                                              "appear in a file");
            if (!described)
                tokens_.failAt(typeToken,
                               "unknown node type '" + typeName +
                                   "' (a type this reader does not know must describe its "
                                   "fields: " +
                                   typeName + " { fields [ SFFloat a, ... ] ... })");
            ref_ptr<UnknownNode> u = UnknownNode::create(typeName);
            unknown = u.get();
            node = u;
        }
        if (!defName.empty()) node->setName(nodeNameFromDefName(defName));
        node->setSourcePlace({fileName_, typeToken.line, typeToken.column});
        if (described) readFieldDescription(*node, unknown, typeName);

        std::vector<ref_ptr<Node>>* children = node->children();
        bool childrenStarted = false;
        while (true) {
            const Token& t = tokens_.peek();
            if (t.isPunct('}')) {
                tokens_.next();
                break;
            }
            if (t.kind == Token::Kind::End)
                tokens_.failAt(t, "unexpected end of file: " + typeName + " opened at " +
                                      position(open) + " has no closing '}'");
            Field* field =
                t.kind == Token::Kind::Word ? findField(*node, unknown, t.text) : nullptr;
            if (field && !childrenStarted) {
                const Token nameToken = tokens_.next();
                readFieldValue(*field, nameToken, typeName);
            } else if (field) {
                tokens_.failAt(t, "field '" + t.text + "' of " + typeName +
                                      " must come before its children");
            } else if (children) {
                if (children->size() >= limits::maxSceneChildren)
                    failTooManyChildren(t, typeName, open);
                children->push_back(readNodeValue(false));
                childrenStarted = true;
            } else if (t.kind == Token::Kind::Word) {
                tokens_.failAt(t, "unknown field '" + t.text + "' in " + typeName);
            } else {
                tokens_.failAt(t, "expected a field name of " + typeName + " or '}', found " +
                                      Tokenizer::describe(t));
            }
        }
        --depth_;
        node->readDone(context_);
        return node;
    }

    // Out of line: readNodeBody recurses once per nesting level, so the strings of these
    // messages must not widen its stack frame (1000 levels under AddressSanitizer).
    [[gnu::noinline]] [[noreturn]] void failTooManyNodes(const Token& at) {
        tokens_.failAt(at,
                       "more than " + std::to_string(limits::maxSceneNodes) + " nodes in one file");
    }
    [[gnu::noinline]] [[noreturn]] void
    failTooManyChildren(const Token& at, const std::string& typeName, const Token& open) {
        tokens_.failAt(at, typeName + " opened at " + position(open) + " has more than " +
                               std::to_string(limits::maxSceneChildren) + " children");
    }

    static Field* findField(Node& node, UnknownNode* unknown, std::string_view name) {
        return unknown ? unknown->findField(name) : node.field(name);
    }

    // fields [ SFFloat a, MFVec3f b ]: declares an unknown node's fields, or must match the
    // fields of a type we know.
    // Out of line (as the value reader below): only readNodeBody's own frame is on the stack
    // once per nesting level.
    [[gnu::noinline]] void readFieldDescription(Node& node, UnknownNode* unknown,
                                                const std::string& typeName) {
        tokens_.next(); // "fields"
        if (!tokens_.peek().isPunct('['))
            tokens_.failAt(tokens_.peek(), "expected '[' after 'fields' in " + typeName +
                                               ", found " + Tokenizer::describe(tokens_.peek()));
        const Token open = tokens_.next();
        std::size_t declared = 0;
        while (!tokens_.acceptPunct(']')) {
            const Token& ft = tokens_.peek();
            if (++declared > limits::maxDeclaredFields)
                tokens_.failAt(ft, "the fields description of " + typeName +
                                       " declares more than " +
                                       std::to_string(limits::maxDeclaredFields) + " fields");
            if (ft.kind == Token::Kind::End)
                tokens_.failAt(ft, "unexpected end of file: the fields description of " + typeName +
                                       " opened at " + position(open) + " has no closing ']'");
            if (ft.kind != Token::Kind::Word)
                tokens_.failAt(ft, "expected a field type (SFFloat, MFVec3f, ...) in the fields "
                                   "description of " +
                                       typeName + ", found " + Tokenizer::describe(ft));
            const Token fieldType = tokens_.next();
            const Token& fn = tokens_.peek();
            if (fn.kind != Token::Kind::Word)
                tokens_.failAt(fn, "expected a field name after '" + fieldType.text +
                                       "' in the fields description of " + typeName + ", found " +
                                       Tokenizer::describe(fn));
            const Token fieldName = tokens_.next();
            if (unknown) {
                if (unknown->findField(fieldName.text))
                    tokens_.failAt(fieldName, "field '" + fieldName.text +
                                                  "' is declared twice in " + typeName);
                if (!unknown->addField(fieldType.text, fieldName.text))
                    tokens_.failAt(fieldType, "unknown field type '" + fieldType.text +
                                                  "' in the fields description of " + typeName);
            } else {
                const Field* f = node.field(fieldName.text);
                if (!f)
                    tokens_.failAt(fieldName, typeName + " has no field '" + fieldName.text +
                                                  "' (declared in its fields description)");
                if (fieldType.text != f->typeName())
                    tokens_.failAt(fieldType, "field '" + fieldName.text + "' of " + typeName +
                                                  " is " + f->typeName() +
                                                  ", but the file declares it " + fieldType.text);
            }
            tokens_.acceptPunct(',');
        }
    }

    void readFieldValue(Field& field, const Token& nameToken, const std::string& typeName) {
        // Errors inside a node value belong to that node and carry their own context.
        if (isNodeField(field)) {
            field.read(*this);
            return;
        }
        readNonNodeFieldValue(field, nameToken, typeName);
    }

    [[gnu::noinline]] void readNonNodeFieldValue(Field& field, const Token& nameToken,
                                                 const std::string& typeName) {
        try {
            field.read(*this);
        } catch (const Error& e) {
            throw Error("field '" + nameToken.text + "' of " + typeName + " expects " +
                            field.typeName() + ": " + e.message(),
                        e.file(), e.line(), e.column());
        }
    }

    Tokenizer tokens_;
    ReadContext context_;
    std::shared_ptr<const std::string> fileName_; ///< shared by every node's SourcePlace
    std::unordered_map<std::string, ref_ptr<Node>> defined_;
    int depth_ = 0;
    std::size_t nodeCount_ = 0;
};

ref_ptr<Node> parse(std::string_view text, const std::string& fileName, std::string directory) {
    text = checkHeader(text, fileName);
    SceneParser parser(text, fileName, ReadContext{fileName, std::move(directory)});
    return parser.readFile();
}

} // namespace

ref_ptr<Node> readScene(const std::string& path) {
    const std::uintmax_t size = regularFileSize(path, "cannot read scene file", maxSceneFileSize);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(std::string("cannot open scene file: ") + std::strerror(errno), path);
    std::string text(static_cast<std::size_t>(size), '\0');
    in.read(text.data(), static_cast<std::streamsize>(size));
    if (in.gcount() != static_cast<std::streamsize>(size))
        throw Error("cannot read scene file: it changed while being read", path);
    return parse(text, path, std::filesystem::path(path).parent_path().string());
}

ref_ptr<Node> readSceneFromString(std::string_view text, const std::string& fileName) {
    std::string directory;
    if (!fileName.empty() && fileName.front() != '<')
        directory = std::filesystem::path(fileName).parent_path().string();
    return parse(text, fileName, std::move(directory));
}

} // namespace volsg
