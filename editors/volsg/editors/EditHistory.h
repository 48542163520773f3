#pragma once
// Undo and redo for every editor and manipulator: an edit is the before and after values (as
// text, FieldText.h) of the fields it touched, so one history serves all field types.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <volsg/core/Node.h>

namespace volsg {

class Field;

class EditHistory {
public:
    /// Starts an edit of these fields: their current values are its "before". A still open edit
    /// is committed first. Node-valued fields are ignored.
    void begin(std::string label, const std::vector<Field*>& fields);
    /// Adds fields to the open edit (their values now become their "before"); starts an edit
    /// when none is open.
    void include(const std::vector<Field*>& fields);
    /// Ends the open edit: records the fields' values as its "after". An edit that changed
    /// nothing is dropped. Any redo steps are discarded.
    void commit();
    /// Ends the open edit by putting the "before" values back.
    void cancel();
    bool isOpen() const { return open_; }

    bool canUndo() const { return done_ > 0; }
    bool canRedo() const { return done_ < edits_.size(); }
    /// Puts the last edit's "before" values back; false when there is nothing to undo.
    bool undo();
    /// Applies the next undone edit's "after" values again.
    bool redo();
    std::size_t size() const { return edits_.size(); }
    /// The label of the edit undo() would revert ("" when none).
    std::string undoLabel() const;
    void clear();
    /// Counts every commit, undo and redo (never reset): a change of it is a change of the
    /// edited state, e.g. since a save.
    std::uint64_t changeCount() const { return changes_; }

private:
    struct FieldState {
        ref_ptr<Node> node;
        std::string field;
        std::string before, after;
        bool beforeDefault = true, afterDefault = true;
    };
    struct Edit {
        std::string label;
        std::vector<FieldState> fields;
    };
    static void restore(const FieldState& f, bool after);
    std::vector<Edit> edits_;
    std::size_t done_ = 0; ///< edits_[0, done_) are applied; the rest can be redone
    Edit pending_;
    bool open_ = false;
    std::uint64_t changes_ = 0;
};

} // namespace volsg
