#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>
#include <volsg/engines/GlobalField.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/BinarySceneReader.h>
#include <volsg/io/ReadContext.h>
#include <volsg/io/ReaderSupport.h>
#include <volsg/io/RegularFile.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/Tokenizer.h>
#include <volsg/io/UnknownNode.h>
#include <volsg/nodes/Separator.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <unordered_map>

namespace volsg {

namespace {

using reader::FileState;
using reader::Place;

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

/// What the header line says.
struct Header {
    std::string_view body; ///< the text after the header line (for binary: after its '\n')
    float version = 2.1f;
    bool binary = false;
    std::size_t headerBytes = 0; ///< bytes before `body` in the file
};

// Checks the header line.
Header checkHeader(std::string_view text, const std::string& fileName) {
    static constexpr std::string_view expected = "#Inventor V2.1 ascii";
    Header h;
    if (startsWith(text, "\xEF\xBB\xBF")) {
        text.remove_prefix(3);
        h.headerBytes = 3;
    }
    if (text.empty())
        throw Error("empty file: expected the header '" + std::string(expected) + "'", fileName, 1,
                    1);
    const std::size_t newline = text.find('\n');
    std::string_view line = text.substr(0, newline);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
        line.remove_suffix(1);
    struct Known {
        std::string_view header;
        float version;
        bool binary;
    };
    static constexpr Known known[] = {
        {"#Inventor V2.1 ascii", 2.1f, false}, {"#Inventor V2.0 ascii", 2.0f, false},
        {"#Inventor V1.0 ascii", 1.0f, false}, {"#VRML V1.0 ascii", 2.1f, false},
        {"#Inventor V2.1 binary", 2.1f, true}, {"#Inventor V2.0 binary", 2.0f, true},
    };
    for (const Known& k : known) {
        if (startsWith(line, k.header) &&
            (line.size() == k.header.size() || line[k.header.size()] == ' ' ||
             line[k.header.size()] == '\t')) {
            h.version = k.version;
            h.binary = k.binary;
            if (h.binary) {
                // The data starts after the header line's '\n' (Inventor pads the line with
                // spaces so that it starts on a multiple of four bytes).
                if (newline == std::string_view::npos)
                    throw Error("byte " + std::to_string(h.headerBytes + text.size()) +
                                    ": unexpected end of file: the binary header line has no "
                                    "end",
                                fileName);
                h.headerBytes += newline + 1;
                h.body = text.substr(newline + 1);
            } else {
                h.body = text;
            }
            return h;
        }
    }
    if (startsWith(line, "#Inventor V1.0 binary"))
        throw Error("Inventor V1.0 binary files are not supported (header '" + printable(line) +
                        "'); convert it to V2.1 (ivcat, or Coin) first",
                    fileName, 1, 1);
    if (startsWith(line, "#Inventor") || startsWith(line, "#VRML"))
        throw Error("unsupported header '" + printable(line) + "': expected '" +
                        std::string(expected) +
                        "', '#Inventor V2.0 ascii', '#Inventor V1.0 ascii', '#VRML V1.0 ascii', "
                        "'#Inventor V2.1 binary' or '#Inventor V2.0 binary'",
                    fileName, 1, 1);
    throw Error("missing header: the first line must be '" + std::string(expected) + "', found '" +
                    printable(line) + "'",
                fileName, 1, 1);
}

bool isKeyword(const Token& t) {
    return t.kind == Token::Kind::Word && (t.text == "DEF" || t.text == "USE" || t.text == "NULL");
}

bool isNodeField(const Field& f) {
    return dynamic_cast<const SFNode*>(&f) || dynamic_cast<const MFNode*>(&f);
}

bool looksNumeric(const Token& t) {
    if (t.kind != Token::Kind::Word || t.text.empty()) return false;
    const char c = t.text[0];
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
}

/// The reader proper: a recursive-descent parser over the tokens that is also the FieldInput
/// through which SFNode/MFNode fields read their nodes.
class SceneParser final : public FieldInput {
public:
    SceneParser(std::string_view text, FileState& file)
        : tokens_(text, file.context.fileName), file_(file) {}

    ref_ptr<Node> readFile() {
        std::vector<ref_ptr<Node>> roots;
        while (!tokens_.atEnd()) {
            const Token& t = tokens_.peek();
            if (t.isPunct('}')) tokens_.failAt(t, "unexpected '}': no node is open");
            roots.push_back(readNodeValue(false, Place::Node));
        }
        if (roots.size() == 1) return roots.front();
        ref_ptr<Separator> root = Separator::create();
        for (auto& node : roots)
            root->addChild(std::move(node));
        return root;
    }

    Tokenizer& tokens() override { return tokens_; }
    ref_ptr<Node> readNode() override { return readNodeValue(true, Place::Node); }

private:
    // NULL | USE name | [DEF name] Type { ... }
    ref_ptr<Node> readNodeValue(bool allowNull, Place place) {
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
            ref_ptr<Node> node = lookUp(name, name.text);
            tokens_.next();
            return node;
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
        ref_ptr<Node> node = readNodeBody(typeToken, defName, place);
        // Bound only now that the node is complete: a USE inside its own body cannot make a
        // cycle.
        if (!defName.empty()) file_.defined[defName] = node;
        return node;
    }

    // A connection source may also be an animated node still being read (ReaderSupport.h).
    ref_ptr<Node> lookUpSource(const Token& at, const std::string& name) {
        if (!file_.defined.count(name))
            if (const auto it = file_.pending.find(name); it != file_.pending.end())
                return ref_ptr<Node>(it->second);
        return lookUp(at, name);
    }

    ref_ptr<Node> lookUp(const Token& at, const std::string& name) {
        const auto it = file_.defined.find(name);
        if (it == file_.defined.end())
            tokens_.failAt(at, "USE of undefined name '" + name + "' (no complete DEF " + name +
                                   " before it)");
        return it->second;
    }

    // Type { [fields [ ... ]] field values... children... }
    ref_ptr<Node> readNodeBody(const Token& typeToken, const std::string& defName, Place place) {
        const std::string& typeName = typeToken.text;
        const Token& brace = tokens_.peek();
        if (!brace.isPunct('{')) failNoBrace(typeToken, brace, place);
        const Token open = tokens_.next();
        if (++file_.depth > maxSceneNestingDepth)
            tokens_.failAt(open, "nodes nested deeper than " +
                                     std::to_string(maxSceneNestingDepth) + " levels");
        if (++file_.nodeCount > limits::maxSceneNodes) failTooManyNodes(typeToken);

        reader::MadeNode made = makeNode(typeToken, place);
        if (!defName.empty()) made.node->setName(reader::nodeNameFromDefName(defName));
        made.node->setSourcePlace({file_.sharedName(), typeToken.line, typeToken.column});
        const ref_ptr<Node> first = made.node; // kept alive for the binding below
        std::optional<reader::EarlyBinding> early;
        if (reader::bindsEarly(*first)) early.emplace(file_, defName, *first);
        if (tokens_.peek().isWord("fields") && !made.node->field("fields") && made.unknown &&
            made.unknown->description() == UnknownNode::Description::Declared)
            readFieldDescription(*made.node, made.unknown, typeName);

        std::vector<ref_ptr<Node>>* children = made.isGroup ? made.node->children() : nullptr;
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
            Node& node = *made.node;
            UnknownNode* unknown = made.unknown;
            Field* field = t.kind == Token::Kind::Word ? findField(node, unknown, t) : nullptr;
            if (!field && !childrenStarted && !unknown && t.kind == Token::Kind::Word &&
                demote(made, typeName, t.text)) {
                children = made.isGroup ? made.node->children() : nullptr;
                continue; // the field is read into the node it became
            }
            if (field && !childrenStarted) {
                const Token nameToken = tokens_.next();
                readFieldEntry(*field, nameToken, typeName);
            } else if (field) {
                tokens_.failAt(t, "field '" + t.text + "' of " + typeName +
                                      " must come before its children");
            } else if (unknown && !childrenStarted && isRawField(*unknown, t)) {
                readRawField(*unknown, typeName);
            } else if (children) {
                if (early) early->endName(); // children see complete nodes only
                if (children->size() >= limits::maxSceneChildren)
                    failTooManyChildren(t, typeName, open);
                children->push_back(readNodeValue(false, Place::Node));
                childrenStarted = true;
            } else if (t.kind == Token::Kind::Word) {
                failUnknownField(t, unknown, typeName);
            } else {
                tokens_.failAt(t, "expected a field name of " + typeName + " or '}', found " +
                                      Tokenizer::describe(t));
            }
        }
        --file_.depth;
        early.reset();
        if (reader::isOldForm(typeName, file_.version) && made.unknown) {
            std::string error;
            ref_ptr<Node> upgraded = reader::upgrade(*made.unknown, file_, error);
            if (!upgraded) tokens_.failAt(typeToken, error);
            return upgraded;
        }
        finish(*made.node, typeToken);
        return made.node;
    }

    [[gnu::noinline]] void finish(Node& node, const Token& typeToken) {
        try {
            node.readDone(file_.context);
        } catch (const Error& e) {
            if (e.line() > 0) throw; // already at its place (a File's name, an included file)
            tokens_.failAt(typeToken, e.message());
        }
    }

    // A field of the standard Inventor type that our class of it lacks: the node is kept as
    // an unknown node of that type instead (ReaderSupport.h).
    [[gnu::noinline]] bool demote(reader::MadeNode& made, const std::string& typeName,
                                  const std::string& fieldName) {
        ref_ptr<UnknownNode> u =
            reader::demoteToInventorType(*made.node, typeName, fieldName, file_);
        if (!u) return false;
        made.isGroup = made.node->children() != nullptr;
        made.node = u;
        made.unknown = u.get();
        return true;
    }

    [[gnu::noinline]] reader::MadeNode makeNode(const Token& typeToken, Place place) {
        reader::MadeNode made;
        if (reader::isOldForm(typeToken.text, file_.version)) {
            ref_ptr<UnknownNode> old = reader::makeOldForm(typeToken.text, file_.version);
            made.unknown = old.get();
            made.node = old;
            return made;
        }
        const bool described = tokens_.peek().isWord("fields");
        made = reader::makeNode(typeToken.text, described, place, file_);
        // A registered type may carry the description too; it must then match its fields.
        if (made.node && !made.unknown && described && !made.node->field("fields"))
            readFieldDescription(*made.node, nullptr, typeToken.text);
        if (!made.node) tokens_.failAt(typeToken, made.error);
        return made;
    }

    [[gnu::noinline]] [[noreturn]] void failNoBrace(const Token& typeToken, const Token& brace,
                                                    Place place) {
        const bool known = reader::registry().find(typeToken.text) != nullptr;
        if (!known && !file_.options.keepUnknownTypes) {
            reader::MadeNode made = reader::makeNode(typeToken.text, false, place, file_);
            if (!made.node) tokens_.failAt(typeToken, made.error);
        }
        tokens_.failAt(brace, "expected '{' after node type '" + typeToken.text + "', found " +
                                  Tokenizer::describe(brace));
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
    [[gnu::noinline]] [[noreturn]] void failUnknownField(const Token& t, UnknownNode* unknown,
                                                         const std::string& typeName) {
        if (unknown && unknown->description() == UnknownNode::Description::Inventor)
            tokens_.failAt(t, "unknown field '" + t.text + "' in " + typeName +
                                  " (not a field of the standard Inventor type, or of a field "
                                  "type this reader cannot hold: SFPath, SFEngine, SFImage3)");
        tokens_.failAt(t, "unknown field '" + t.text + "' in " + typeName);
    }

    [[gnu::noinline]] Field* findField(Node& node, UnknownNode* unknown, const Token& t) {
        if (unknown) return unknown->findField(t.text);
        Field* f = node.field(t.text);
        if (!f) {
            // A GlobalField's value field is named by the file.
            if (auto* global = dynamic_cast<GlobalField*>(&node);
                global && !global->valueField() && !global->type.isDefault() && !isKeyword(t) &&
                !tokens_.peekSecond().isPunct('{')) {
                f = global->makeValueField(t.text);
                if (!f)
                    tokens_.failAt(t,
                                   "GlobalField type '" + global->type() + "' is not a field type");
            }
        }
        return f;
    }

    // A node kept with raw values: a word that is not a child (`Type {`, DEF, USE) names a
    // field.
    bool isRawField(const UnknownNode& unknown, const Token& t) {
        return unknown.description() == UnknownNode::Description::Raw &&
               t.kind == Token::Kind::Word && !isKeyword(t) && !tokens_.peekSecond().isPunct('{');
    }

    // The value of a field of a raw node: a node (an SFNode field), a bracketed list of nodes
    // (MFNode), or tokens: a bracketed or parenthesised group, a run of numbers, or one word
    // or string. Then, as for any field, `~` and a connection.
    [[gnu::noinline]] void readRawField(UnknownNode& unknown, const std::string& typeName) {
        const Token nameToken = tokens_.next();
        if (unknown.findField(nameToken.text))
            tokens_.failAt(nameToken,
                           "field '" + nameToken.text + "' is given twice in " + typeName);
        if (unknown.fieldCount() >= limits::maxDeclaredFields)
            tokens_.failAt(nameToken, typeName + " has more than " +
                                          std::to_string(limits::maxDeclaredFields) + " fields");
        const Token& first = tokens_.peek();
        const bool nodeValue =
            isKeyword(first) || (first.kind == Token::Kind::Word && !first.isWord("~") &&
                                 !first.isWord("=") && tokens_.peekSecond().isPunct('{'));
        if (nodeValue) {
            Field* f = unknown.addField("SFNode", nameToken.text);
            readFieldEntry(*f, nameToken, typeName);
            return;
        }
        if (first.isPunct('[')) {
            const Token& second = tokens_.peekSecond();
            // `[ Type {`, `[ DEF`, `[ USE`, `[ NULL`: a list of nodes (decided on the first
            // element: a word followed by '{' is only known one token later, so a list whose
            // first node is not named is told by the words DEF/USE/NULL or the type alone:
            // a list of words in brackets that is not followed by '{' stays raw).
            if (isKeyword(second)) {
                Field* f = unknown.addField("MFNode", nameToken.text);
                readFieldEntry(*f, nameToken, typeName);
                return;
            }
        }
        RawValueField* raw = unknown.addRawField(nameToken.text);
        std::vector<RawValueField::Piece> pieces;
        auto take = [&] {
            Token t = tokens_.next();
            if (pieces.size() >= limits::maxFieldValues)
                tokens_.failAt(t, "more than " + std::to_string(limits::maxFieldValues) +
                                      " values in one field");
            const auto kind = t.kind == Token::Kind::String  ? RawValueField::Piece::Kind::String
                              : t.kind == Token::Kind::Punct ? RawValueField::Piece::Kind::Punct
                                                             : RawValueField::Piece::Kind::Word;
            pieces.push_back({kind, std::move(t.text)});
        };
        auto takeGroup = [&](char close, const char* what) {
            const Token open = tokens_.peek();
            int level = 0;
            do {
                const Token& t = tokens_.peek();
                if (t.kind == Token::Kind::End)
                    tokens_.failAt(t, std::string("unexpected end of file: the ") + what +
                                          " started at " + position(open) + " has no closing '" +
                                          close + "'");
                if (t.isPunct('{') || t.isPunct('}'))
                    tokens_.failAt(t, "the value of '" + nameToken.text + "' of " + typeName +
                                          " holds nodes, which a node of unknown type without "
                                          "a description cannot keep");
                if (t.isPunct(open.text[0])) ++level;
                if (t.isPunct(close)) --level;
                take();
            } while (level > 0);
        };
        const Token& t = tokens_.peek();
        if (t.isWord("~") || t.isWord("=")) {
            // no value: the flag or connection follows
        } else if (t.isPunct('[')) {
            takeGroup(']', "list");
        } else if (t.isPunct('(')) {
            takeGroup(')', "bit mask");
        } else if (looksNumeric(t)) {
            while (looksNumeric(tokens_.peek()))
                take();
        } else if (t.kind == Token::Kind::Word || t.kind == Token::Kind::String) {
            take();
        } else {
            tokens_.failAt(t, "expected a value for '" + nameToken.text + "' of " + typeName +
                                  ", found " + Tokenizer::describe(t));
        }
        if (!pieces.empty()) raw->setPieces(std::move(pieces));
        readFlagsAndConnection(*raw, nameToken, typeName);
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

    // name [value] [~] [= source . output]: the value may be left out when the ignore flag or
    // a connection follows (the field then keeps its default).
    void readFieldEntry(Field& field, const Token& nameToken, const std::string& typeName) {
        const Token& t = tokens_.peek();
        if (!t.isWord("~") && !t.isWord("=")) readFieldValue(field, nameToken, typeName);
        readFlagsAndConnection(field, nameToken, typeName);
    }

    [[gnu::noinline]] void readFlagsAndConnection(Field& field, const Token& nameToken,
                                                  const std::string& typeName) {
        if (tokens_.peek().isWord("~")) {
            tokens_.next();
            field.setIgnored(true);
        }
        if (tokens_.peek().isWord("=")) {
            tokens_.next();
            readConnection(field, nameToken, typeName);
        }
    }

    // USE name . output | USE name.output | [DEF name] Type { ... } . output
    [[gnu::noinline]] void readConnection(Field& field, const Token& nameToken,
                                          const std::string& typeName) {
        const Token start = tokens_.peek();
        ref_ptr<Node> source;
        std::string output;
        if (start.isWord("USE")) {
            tokens_.next();
            const Token name = tokens_.peek();
            if (name.kind != Token::Kind::Word)
                tokens_.failAt(name,
                               "expected a name after USE, found " + Tokenizer::describe(name));
            const std::size_t dot = name.text.find('.');
            if (dot != std::string::npos && !file_.defined.count(name.text) &&
                !file_.pending.count(name.text)) {
                source = lookUpSource(name, name.text.substr(0, dot));
                output = name.text.substr(dot + 1);
            } else {
                source = lookUpSource(name, name.text);
            }
            tokens_.next();
        } else {
            source = readNodeValue(false, Place::ConnectionSource);
        }
        if (output.empty()) {
            const Token& dot = tokens_.peek();
            if (dot.isWord(".")) {
                tokens_.next();
                output = tokens_.expectWord("the name of a field or output after '.'");
            } else if (dot.kind == Token::Kind::Word && dot.text.size() > 1 && dot.text[0] == '.') {
                output = tokens_.next().text.substr(1);
            } else {
                tokens_.failAt(dot, "expected '.' and the name of a field or output after the "
                                    "source of the connection of '" +
                                        nameToken.text + "' of " + typeName + ", found " +
                                        Tokenizer::describe(dot));
            }
        }
        std::string error;
        if (!reader::checkConnection(field, *source, output, error))
            tokens_.failAt(start, "field '" + nameToken.text + "' of " + typeName + ": " + error);
        field.connectFrom(std::move(source), std::move(output));
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
    FileState& file_;
};

ref_ptr<Node> parse(std::string_view text, const std::string& fileName, std::string directory,
                    const ReadOptions& options) {
    const Header header = checkHeader(text, fileName);
    FileState file;
    file.context = ReadContext{fileName, std::move(directory)};
    file.options = options;
    file.version = header.version;
    file.binary = header.binary;
    if (header.binary) return readBinaryScene(header.body, header.headerBytes, file);
    SceneParser parser(header.body, file);
    return parser.readFile();
}

} // namespace

ref_ptr<Node> readScene(const std::string& path, const ReadOptions& options) {
    const std::uintmax_t size = regularFileSize(path, "cannot read scene file", maxSceneFileSize);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(std::string("cannot open scene file: ") + std::strerror(errno), path);
    std::string text(static_cast<std::size_t>(size), '\0');
    in.read(text.data(), static_cast<std::streamsize>(size));
    if (in.gcount() != static_cast<std::streamsize>(size))
        throw Error("cannot read scene file: it changed while being read", path);
    return parse(text, path, std::filesystem::path(path).parent_path().string(), options);
}

ref_ptr<Node> readSceneFromString(std::string_view text, const std::string& fileName,
                                  const ReadOptions& options) {
    std::string directory;
    if (!fileName.empty() && fileName.front() != '<')
        directory = std::filesystem::path(fileName).parent_path().string();
    return parse(text, fileName, std::move(directory), options);
}

} // namespace volsg
