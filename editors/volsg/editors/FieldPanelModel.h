#pragma once
// The model behind RTVR's "automatically generated control panel": the fields of any selected
// node, each with the kind of widget that edits it, and changes that go through the history.

#include <functional>
#include <string>
#include <vector>

#include <volsg/core/Node.h>

namespace volsg {

class EditHistory;
class Field;

class FieldPanelModel {
public:
    /// The widget a field gets. Text: every other type (MF lists, planes, matrices), edited as
    /// the text a scene file holds.
    enum class Kind { Float, Int, Bool, Enum, Color, Vec2, Vec3, Rotation, String, Text, Node };
    struct Entry {
        Field* field = nullptr;
        Kind kind = Kind::Text;
    };
    static Kind kindOf(const Field& field);

    explicit FieldPanelModel(EditHistory& history);

    void setNode(Node* node);
    Node* node() const { return node_.get(); }
    const std::vector<Entry>& entries() const { return entries_; }

    /// Runs `set` (which changes entry i's field) as an undoable edit; within
    /// beginChange/endChange (a slider held down) the changes are one edit.
    void change(std::size_t i, const std::function<void()>& set);
    void beginChange(std::size_t i);
    void endChange();

    /// The field's value as text, and setting it from text (one edit). On a parse error the
    /// field is unchanged, `error` gets the message and the result is false.
    std::string text(std::size_t i) const;
    bool setText(std::size_t i, const std::string& text, std::string* error = nullptr);

private:
    EditHistory& history_;
    ref_ptr<Node> node_;
    std::vector<Entry> entries_;
    bool changing_ = false;
};

} // namespace volsg
