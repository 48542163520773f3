#pragma once
// Base of every typed field: a named value of a node, readable and writable as Inventor ASCII.

#include <iosfwd>
#include <volsg/core/Object.h>

namespace volsg {

class Node;
class Tokenizer;

/// What a field needs from the scene reader: tokens, and nodes for SFNode/MFNode values.
class FieldInput {
public:
    virtual ~FieldInput() = default;
    virtual Tokenizer& tokens() = 0;
    /// Reads one node value (`Type { ... }`, `DEF name Type { ... }`, `USE name`, or `NULL`,
    /// which gives null).
    virtual ref_ptr<Node> readNode() = 0;
};

/// What a field needs from the scene writer: the stream, and nodes for SFNode/MFNode values.
class FieldOutput {
public:
    virtual ~FieldOutput() = default;
    virtual std::ostream& stream() = 0;
    virtual void writeNode(const Node* node) = 0; ///< writes `NULL` for null
    virtual void newline() = 0;                   ///< a new line at the current indentation
};

/// A named, typed value owned by a node. Setting it bumps the owner's version, so caches
/// built from the node know they are stale.
class Field {
public:
    Field(Node* owner, const char* name);
    Field(const Field&) = delete;
    Field& operator=(const Field&) = delete;
    virtual ~Field() = default;

    const char* name() const { return name_; }
    Node* owner() const { return owner_; }

    virtual const char* typeName() const = 0; ///< "SFFloat", "MFVec3f", ...
    virtual void read(FieldInput& in) = 0;    ///< reads the value after the field name
    virtual void write(FieldOutput& out) const = 0;
    virtual bool equals(const Field& other) const = 0; ///< same type and value
    virtual void copyFrom(const Field& other) = 0;     ///< same type required

    /// A field that was never set keeps its default and is not written.
    bool isDefault() const { return isDefault_; }
    void setDefault(bool d) { isDefault_ = d; }

protected:
    void changed(); ///< marks the field set and bumps the owner's version

private:
    Node* owner_;
    const char* name_;
    bool isDefault_ = true;
};

} // namespace volsg
