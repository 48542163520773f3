#pragma once
// RTVR's direct interaction: drag on the active object to change how it looks. Up and down
// change its opacity; left and right change the contrast of a volume's transfer function (how
// steeply its opacity rises). A volume edits the TransferFunction in its scope (alpha channel),
// a shape the Material in its scope (transparency). One drag is one undo step.

#include <vector>

#include <glm/glm.hpp>

#include <volsg/core/Node.h>

namespace volsg {

class EditHistory;

class ActiveObjectDrag {
public:
    /// Pixels of mouse travel that double (or halve) opacity or contrast (at most 16x).
    static constexpr double pixelsPerDoubling = 100.0;

    explicit ActiveObjectDrag(EditHistory& history);

    /// Starts a drag on `object` (a Volume or a shape under `root`); false when there is
    /// nothing in its scope to change.
    bool begin(Node& root, Node& object);
    /// The mouse is now `delta` pixels from where the drag began (x right, y down).
    void update(const glm::dvec2& delta);
    void end();
    bool isActive() const { return target_ != nullptr; }
    /// The node being changed (a TransferFunction or a Material).
    Node* target() const { return target_.get(); }

    /// The curve min(1, factor * alpha) (a point added where it crosses 1).
    static std::vector<glm::vec2> scaleOpacity(const std::vector<glm::vec2>& alpha, double factor);
    /// The curve squeezed in x about the middle of the span where it changes, by `factor` (> 1
    /// steeper, < 1 gentler); points pushed past 0 or 1 are replaced by the curve's value there.
    static std::vector<glm::vec2> scaleContrast(const std::vector<glm::vec2>& alpha, double factor);

private:
    EditHistory& history_;
    ref_ptr<Node> target_;
    std::vector<glm::vec2> startAlpha_;
    float startTransparency_ = 0.0f;
};

} // namespace volsg
