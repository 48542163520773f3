#pragma once
// Base of every typed field: a named value of a node, readable and writable as Inventor ASCII.

#include <iosfwd>
#include <memory>
#include <string>

#include <volsg/core/Node.h>
#include <volsg/core/Object.h>

namespace volsg {

class BinaryInput;
class Tokenizer;

/// What a field needs from the scene reader: tokens, and nodes for SFNode/MFNode values.
class FieldInput {
public:
    virtual ~FieldInput() = default;
    virtual Tokenizer& tokens() = 0;
    /// Non-null when the value is read from a binary Inventor file (io/BinaryInput.h): the
    /// field reads its binary layout from there instead of tokens().
    virtual BinaryInput* binary() { return nullptr; }
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

/// Where a connected field takes its value from (Inventor's `field = Source . output`): a
/// field of a node, or an output of an engine (an Engine is a Node that is never a child,
/// nodes/volsg/engines/Engine.h). The connection keeps its source alive.
struct FieldConnection {
    ref_ptr<Node> source;
    std::string sourceField; ///< the source's field or engine output
    /// The source value last copied (owned by the evaluator, nodes/volsg/engines): a value
    /// is copied again only when the source changes.
    std::shared_ptr<Field> lastCopied;
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

    /// Inventor's ignore flag (`value ~` in a file): kept and written back.
    bool isIgnored() const { return isIgnored_; }
    void setIgnored(bool ignored);

    /// The connection this field takes its value from, or null.
    const FieldConnection* connection() const { return connection_.get(); }
    FieldConnection* connection() { return connection_.get(); }
    /// Connects the field to `sourceField` of `source` (a node field or an engine output);
    /// the evaluator (nodes/volsg/engines/Evaluator.h) copies the value.
    void connectFrom(ref_ptr<Node> source, std::string sourceField);
    void disconnect();

protected:
    void changed(); ///< marks the field set and bumps the owner's version

private:
    Node* owner_;
    const char* name_;
    bool isDefault_ = true;
    bool isIgnored_ = false;
    std::unique_ptr<FieldConnection> connection_;
};

} // namespace volsg
