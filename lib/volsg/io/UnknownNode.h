#pragma once
// A node of a type the reader does not know, kept from its self-description so that it is
// written back unchanged.

#include <deque>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <volsg/core/Node.h>

namespace volsg {

/// Read from `Foo { fields [ SFFloat a, MFVec3f b ] a 1 b [ 0 0 0 ] Child { } }`: keeps the
/// type name, the declared fields (per instance, in declaration order) with their values, and
/// any children. It does nothing in actions (as Coin's SoUnknownNode); the writer writes it
/// back with the same type name, `fields [...]` description, values and children.
class UnknownNode : public Inherit<Node, UnknownNode> {
public:
    static constexpr const char* typeName = "UnknownNode";

    UnknownNode() = default;
    explicit UnknownNode(std::string fileTypeName) : fileTypeName_(std::move(fileTypeName)) {}

    /// The type name as written in the file ("Foo").
    const std::string& fileTypeName() const { return fileTypeName_; }
    void setFileTypeName(std::string name) { fileTypeName_ = std::move(name); }

    /// Declares a field; null if the type name is not a field type or the name is taken.
    Field* addField(std::string_view fieldType, std::string_view name);
    /// The field of that name in constant time (Node::field() scans, and a file may declare
    /// many fields).
    Field* findField(std::string_view name) const;

    std::size_t fieldCount() const override { return fields_.size(); }
    Field* fieldAt(std::size_t i) override;
    using Node::fieldAt;
    std::vector<ref_ptr<Node>>* children() override { return &children_; }
    using Node::children;

protected:
    ~UnknownNode() override;

private:
    std::string fileTypeName_;
    std::deque<std::string> fieldNames_; // stable storage: fields keep a pointer to their name
    std::vector<std::unique_ptr<Field>> fields_;
    std::unordered_map<std::string_view, Field*> byName_; // views into fieldNames_
    std::vector<ref_ptr<Node>> children_;
};

} // namespace volsg
