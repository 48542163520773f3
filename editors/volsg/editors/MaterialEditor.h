#pragma once
// The model of the material editor: the colours and scalars of a Material, or of a BoxClip's
// inside and outside (colour, colour weight, opacity), as a list of named properties that a
// panel shows as colour pickers and sliders. Each change is an undoable edit.

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/core/Node.h>

namespace volsg {

class EditHistory;
class Field;

class MaterialEditor {
public:
    struct Property {
        std::string label;
        bool isColor = false;
        float minimum = 0.0f, maximum = 1.0f; ///< for scalars
        Field* field = nullptr;               ///< MFColor/SFColor or MFFloat/SFFloat
    };

    explicit MaterialEditor(EditHistory& history);

    /// Edits a Material or a BoxClip; any other node (or null) leaves nothing to edit. Returns
    /// whether the node is editable.
    bool setNode(Node* node);
    Node* node() const { return node_.get(); }
    const std::vector<Property>& properties() const { return properties_; }

    glm::vec3 color(std::size_t i) const;
    float scalar(std::size_t i) const;
    /// Sets a property. Within beginChange/endChange (a slider being dragged) all changes are
    /// one undo step; outside, each set is its own.
    void setColor(std::size_t i, const glm::vec3& value);
    void setScalar(std::size_t i, float value);
    void beginChange(std::size_t i);
    void endChange();

private:
    void edit(std::size_t i, const char* label);
    EditHistory& history_;
    ref_ptr<Node> node_;
    std::vector<Property> properties_;
    bool changing_ = false;
};

} // namespace volsg
