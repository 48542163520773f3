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

class RawValueField;

/// Read from `Foo { fields [ SFFloat a, MFVec3f b ] a 1 b [ 0 0 0 ] Child { } }`: keeps the
/// type name, the declared fields (per instance, in declaration order) with their values, and
/// any children; the writer writes it back with the same type name, description, values and
/// children (docs/SCENE-FORMAT.md section 1.4).
///
/// In actions it stands for its alternate representation, as Coin's SoUnknownNode: the node
/// of an SFNode field `alternateRep`, if it has one. A node that declares `isA` (VRML 1.0's
/// MFString naming the type it extends) as "Group" or "Separator" and has no alternateRep
/// traverses its children like that group. Otherwise it does nothing.
class UnknownNode : public Inherit<Node, UnknownNode> {
public:
    static constexpr const char* typeName = "UnknownNode";

    /// Where its field types came from, which decides how it is written.
    enum class Description {
        Declared, ///< `fields [ ... ]` in the file (or the binary not-built-in flag): written
        Inventor, ///< a standard Inventor type the reader knows the fields of: not written
        Raw,      ///< no description (ReadOptions::keepUnknownTypes): values kept as text
    };
    Description description() const { return description_; }
    void setDescription(Description d) { description_ = d; }

    UnknownNode() = default;
    explicit UnknownNode(std::string fileTypeName) : fileTypeName_(std::move(fileTypeName)) {}

    /// The type name as written in the file ("Foo").
    const std::string& fileTypeName() const { return fileTypeName_; }
    void setFileTypeName(std::string name) { fileTypeName_ = std::move(name); }

    /// Declares a field; null if the type name is not a field type or the name is taken.
    Field* addField(std::string_view fieldType, std::string_view name);
    /// Declares a field kept as the text of its value (Description::Raw); null if taken.
    RawValueField* addRawField(std::string_view name);
    /// The field of that name in constant time (Node::field() scans, and a file may declare
    /// many fields).
    Field* findField(std::string_view name) const;

    std::size_t fieldCount() const override { return fields_.size(); }
    Field* fieldAt(std::size_t i) override;
    using Node::fieldAt;
    std::vector<ref_ptr<Node>>* children() override { return &children_; }
    using Node::children;

    void doAction(Action& action) override;

protected:
    ~UnknownNode() override;

private:
    Field* adopt(std::unique_ptr<Field> field);
    std::string fileTypeName_;
    Description description_ = Description::Declared;
    std::deque<std::string> fieldNames_; // stable storage: fields keep a pointer to their name
    std::vector<std::unique_ptr<Field>> fields_;
    std::unordered_map<std::string_view, Field*> byName_; // views into fieldNames_
    std::vector<ref_ptr<Node>> children_;
};

} // namespace volsg
