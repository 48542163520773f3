#pragma once
// Run-time type of a node class: name, parent, factory and field table.

#include <cstddef>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include <volsg/core/Object.h>

namespace volsg {

class Node;
class Field;

/// One node class. Its field table (names and offsets, in declaration order) is recorded
/// from a prototype instance the first time it is asked for.
class NodeType {
public:
    using Factory = ref_ptr<Node> (*)();
    struct FieldEntry {
        std::string name;
        std::ptrdiff_t offset; ///< from the Node base of an instance
    };

    NodeType(const char* name, const NodeType* parent, Factory factory, bool inventorBuiltin);
    NodeType(const NodeType&) = delete;
    NodeType& operator=(const NodeType&) = delete;

    const char* name() const { return name_; }
    const NodeType* parent() const { return parent_; }
    bool isAbstract() const { return factory_ == nullptr; }
    bool isInventorBuiltin() const { return inventorBuiltin_; }
    bool isDerivedFrom(const NodeType& other) const;
    ref_ptr<Node> create() const; ///< null for abstract types
    const std::vector<FieldEntry>& fields() const;

    /// Called by Field's constructor: records the field while a prototype is being built.
    static void recordField(const Node* owner, const Field* field, const char* name);

private:
    const char* name_;
    const NodeType* parent_;
    Factory factory_;
    bool inventorBuiltin_;
    mutable std::once_flag fieldsOnce_;
    mutable std::vector<FieldEntry> fields_;
};

/// Node types by name, for the reader. The library's own types are added by the node layer
/// (nodeTypes(), nodes/volsg/nodes/BuiltinNodes.h); applications add theirs with add().
class NodeRegistry {
public:
    static NodeRegistry& instance();
    void add(const NodeType& type);
    const NodeType* find(std::string_view name) const;
    std::vector<const NodeType*> all() const;

private:
    NodeRegistry();
    mutable std::mutex mutex_;
    std::vector<const NodeType*> types_;
};

} // namespace volsg
