#pragma once
// What the text and the binary scene parsers share: the node made for a type name, Inventor
// V1.0/V2.0 upgrades, connection checks. Internal to nodes/volsg/io.

#include <cstddef>
#include <memory>
#include <string>
#include <unordered_map>

#include <volsg/core/Node.h>
#include <volsg/io/ReadContext.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/UnknownNode.h>

namespace volsg {

class Field;

namespace reader {

/// The registry the reader uses: the library's node types, the animated nodes and the
/// engines (nodes/volsg/engines/EngineTypes.h).
NodeRegistry& registry();

/// The known node type whose name is nearest to `typeName` (edit distance, ignoring case),
/// when it is close enough to be a slip; else empty. For "did you mean Volume?".
std::string nearestTypeName(const std::string& typeName);

/// Where a node is read: a child or a node field's value, or the source of a field
/// connection (the only place an engine may stand).
enum class Place { Node, ConnectionSource };

/// State shared by the whole of one file.
struct FileState {
    ReadContext context;
    ReadOptions options;
    float version = 2.1f; ///< 1.0, 2.0 or 2.1
    bool binary = false;
    std::unordered_map<std::string, ref_ptr<Node>> defined;
    /// Animated nodes (Rotor, Pendulum, Shuttle, Blinker) being read, by DEF name: Coin
    /// writes their internal engines, whose inputs are connected to the node itself, inside
    /// the node (`DEF b Blinker { whichChild = TimeCounter { on = ... USE b . on } . output`).
    /// Only a connection source may name them before they are complete.
    std::unordered_map<std::string, Node*> pending;
    int depth = 0;
    std::size_t nodeCount = 0;

    /// The file's name, shared by every node's SourcePlace.
    const std::shared_ptr<const std::string>& sharedName() {
        if (!sharedName_ || *sharedName_ != context.fileName)
            sharedName_ = std::make_shared<const std::string>(context.fileName);
        return sharedName_;
    }

private:
    std::shared_ptr<const std::string> sharedName_;
};

/// The node a type name makes, or the reason it cannot (`error` set, `node` null):
/// a registered type; an UnknownNode that declares its fields (`described`); a standard
/// Inventor type the library has no class for, kept as an UnknownNode with the fields of
/// InventorTypes.h (always in binary files, in text with ReadOptions::keepUnknownTypes); in
/// text with keepUnknownTypes, any other type as an UnknownNode with raw values.
struct MadeNode {
    ref_ptr<Node> node;
    UnknownNode* unknown = nullptr;
    bool isEngine = false;
    bool isGroup = false; ///< for unknown standard types: a group in Inventor
    std::string error;
};
MadeNode makeNode(const std::string& typeName, bool described, Place place, const FileState& file);

/// A node of a registered type whose file sets a field the class does not have but the
/// standard Inventor type does (IndexedFaceSet's vertexProperty, say), kept as an UnknownNode
/// of the standard type with the fields read so far; null if the standard type has no such
/// field (then the field is an error, as before). Only where unknown types are kept.
ref_ptr<UnknownNode> demoteToInventorType(Node& node, const std::string& typeName,
                                          const std::string& fieldName, const FileState& file);

/// Coin writes shared nodes as `DEF name+N` (and unnamed ones as `DEF +N`); the suffix only
/// keeps DEF names unique in the file and is not part of the node's name.
std::string nodeNameFromDefName(const std::string& defName);

/// Whether a node of this type in a file of this version is an old form that is upgraded
/// (Coin's upgraders: ShapeHints of V1.0, PackedColor of V2.0). If so, `old` gets the old
/// fields to read into.
bool isOldForm(const std::string& typeName, float version);
ref_ptr<UnknownNode> makeOldForm(const std::string& typeName, float version);
/// The current form of a node read in its old form; its fields set from the old ones.
ref_ptr<Node> upgrade(UnknownNode& old, const FileState& file, std::string& error);

/// The field of a connection source named `name` (a field, or an engine output); on error
/// null, with `error` saying what is wrong, including when its values cannot become `target`'s.
Field* checkConnection(Field& target, Node& source, const std::string& name, std::string& error);

/// Whether the node is one whose DEF name a connection may use before the node is complete.
bool bindsEarly(const Node& node);
/// Drops the connections of the node's fields whose sources lead back to the node itself
/// (Coin's internal engines of an animated node, which computes those fields itself).
void dropSelfConnections(Node& node);

/// While an animated node is read: its DEF name is pending (connections inside it may name
/// it); when it is done, or reading fails inside it, the name is no longer pending and the
/// connections of its fields that lead back to it are dropped, so no reference cycle keeps
/// it alive.
class EarlyBinding {
public:
    EarlyBinding(FileState& file, const std::string& defName, Node& node);
    ~EarlyBinding();
    EarlyBinding(const EarlyBinding&) = delete;
    EarlyBinding& operator=(const EarlyBinding&) = delete;
    /// Ends the pending name early (children see complete nodes only).
    void endName();

private:
    FileState* file_ = nullptr;
    const std::string* defName_ = nullptr;
    Node* node_ = nullptr;
};

/// Names of the engine types whose input type is given before their fields (`type MFFloat`).
bool isTypedEngine(const Node& node);

} // namespace reader

} // namespace volsg
