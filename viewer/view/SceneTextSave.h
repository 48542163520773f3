#pragma once
// Saving a scene the way its author wrote it: the file's text with only what changed rewritten.
//
// Taken when a scene is read, a SceneTextSnapshot keeps the file's text and every node's field
// values (as text). On save, the fields whose value differs are found and only their values'
// spans in the text are replaced (a field the file did not set is added to its node), so
// comments, blank lines, the order and layout of untouched nodes and fields stay byte for byte.
// The viewer chose this over keeping comments on nodes in the reader: the reader stays as it
// is, and everything the reader does not model (comment placement, number spelling, line
// breaks inside lists) survives too.
//
// A node inserted by the viewer as the first child of the root (the camera written into a
// scene that had none) is written in full there. Anything else (a node added, removed or moved,
// a node-valued field changed, a changed field with a connection, a file that is not V2.1
// ASCII, a file changed on disk since it was read) makes patched() refuse with the reason; the
// caller then writes the whole scene.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <volsg/core/Node.h>

namespace volsg {

class SceneTextSnapshot {
public:
    /// Of the scene `root` just read from `text` (the file's bytes). Never fails: a text that
    /// cannot be patched (binary, V1.0, ...) is remembered as such and patched() refuses.
    static SceneTextSnapshot take(std::string text, Node& root);

    /// The scene's text now: the snapshot's text with each changed field's value replaced or
    /// added, and an inserted first child of the root written in. `reason` says why not when
    /// it returns std::nullopt.
    std::optional<std::string> patched(Node& root, std::string& reason) const;

    const std::string& text() const { return text_; }

private:
    /// Where a field's value is in text_: [begin, end) (begin == end: not in the text).
    struct ValueSpan {
        std::size_t begin = 0, end = 0;
        bool present = false;
        bool connected = false; ///< `~` or `= ...`: never rewritten
    };
    struct NodeRecord {
        std::vector<std::string> values; ///< per field, as text when taken (empty: not text)
        std::vector<ValueSpan> spans;    ///< per field
        std::vector<Node*> children;     ///< a group's children when taken
        std::size_t open = 0, close = 0; ///< offsets of its '{' and '}'
        std::size_t lastEntryEnd = 0;    ///< end of its last field value (else after '{')
    };
    friend class SceneTextWalker;
    std::string text_;
    std::string refusal_; ///< non-empty: this text cannot be patched
    std::map<const Node*, NodeRecord> nodes_;
    bool rootIsWrapper_ = false;    ///< several top-level nodes: the root is the reader's group
    std::size_t topLevelStart_ = 0; ///< after the header line
};

} // namespace volsg
