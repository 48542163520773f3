#pragma once
// File: includes another Inventor file (Inventor's SoFile). The reader reads the named file
// when it reads the File node (relative names against the folder of the scene file that holds
// the File node) and the File traverses what it read as hidden children: every action sees
// them, the writer writes only `File { name "..." }`. docs/SCENE-FORMAT.md section 2.5.
#include <cstdint>
#include <optional>
#include <string>

#include <volsg/core/Error.h>
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

/// File's `name`: an SFString that also keeps where its value was read from a file (line and
/// column of the value), so that errors about the included file point at the File node.
class FileNameField final : public Field {
public:
    FileNameField(Node* owner, const char* name, std::string initial)
        : Field(owner, name), value_(std::move(initial)) {}

    const std::string& getValue() const { return value_; }
    const std::string& operator()() const { return value_; }
    void setValue(std::string v); ///< forgets the position: the value comes from code
    FileNameField& operator=(std::string v) {
        setValue(std::move(v));
        return *this;
    }
    int line() const { return line_; } ///< 0 when the value was not read from a file
    int column() const { return column_; }

    const char* typeName() const override { return "SFString"; }
    void read(FieldInput& in) override;
    void write(FieldOutput& out) const override;
    bool equals(const Field& other) const override;
    void copyFrom(const Field& other) override;

private:
    std::string value_;
    int line_ = 0, column_ = 0;
};

class File : public Inherit<Node, File> {
public:
    static constexpr const char* typeName = "File";
    static constexpr bool inventorBuiltin() { return true; }
    /// Inventor's default name: a File with it (or with an empty name) reads nothing.
    static constexpr const char* undefinedName = "<Undefined file>";
    /// Longest chain of files including one another.
    static constexpr int maxIncludeDepth = 1000;

    FileNameField name{this, "name", undefinedName};

    /// What the named file holds (the node readScene() returns for it), or null: no name, or
    /// the file could not be opened (readError()).
    Node* contents() const { return contents_.get(); }
    /// Why the named file could not be opened (missing, not a regular file, unreadable), with
    /// the scene file and the File node's line; render, bounding box and pick actions throw
    /// it. Errors inside the file, and files that include themselves, are thrown by the reader.
    const std::optional<Error>& readError() const { return readError_; }

    /// Reads the named file again if `name` changed since it was read (Inventor re-reads when
    /// the field changes). Errors of any kind are kept in readError(). Traversals call it.
    void update();

    void readDone(const ReadContext& context) override;
    void doAction(Action& action) override;

protected:
    ~File() override = default;

private:
    friend struct FileIncluder;
    std::string directory_; ///< of the scene file holding the node (relative names)
    std::string sceneFile_; ///< that scene file, for messages and the include chain
    ref_ptr<Node> contents_;
    std::optional<Error> readError_;
    std::uint64_t readVersion_ = 0; ///< version() when the file was read
};

} // namespace volsg
