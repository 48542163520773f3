#pragma once
// Traversal state: the model matrix and the property nodes in scope, pushed and popped by
// Separator.

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace volsg {

class Node;

/// A property node in scope (Material, a light, a ClipPlane, VolumeData, ...) with the model
/// matrix at its place in the graph.
struct StateEntry {
    const Node* node;
    glm::dmat4 model;
};

/// Where an action looks from, for the nodes that choose their children by it (LOD,
/// LevelOfDetail; docs/SCENE-FORMAT.md section 2.5). PickAction sets it from its camera, or from
/// the origin of a ray given directly; RenderAction's methods read the frame's view instead.
struct StateView {
    glm::dvec3 eye{0.0}; ///< world position of the camera (Inventor's projection point)
    /// `view`, `projection`, `width` and `height` are known (a pick through a pixel): nodes can
    /// measure projected sizes in pixels.
    bool projected = false;
    glm::dmat4 view{1.0};       ///< world to eye
    glm::dmat4 projection{1.0}; ///< eye to clip
    int width = 0, height = 0;  ///< viewport in pixels
};

/// The state of a traversal. Instead of one class per element (Inventor's SoElement), a
/// property node adds itself to the scope; shapes ask for the nearest entry of a type or for
/// all of them (lights, clip planes, per-tag transfer functions). push() and pop() restore
/// scope in O(1), with no copies.
class State {
public:
    State();

    void push(); ///< Separator enters
    void pop();  ///< Separator leaves: everything since the matching push is gone
    std::size_t depth() const { return marks_.size(); }
    /// Everything back to the start of a traversal (no view, no entries, this model matrix).
    void reset(const glm::dmat4& model = glm::dmat4(1.0));

    /// The viewpoint of the action, or null when it has none (bounding boxes, searches).
    /// Kept across push() and pop(); reset() clears it.
    const StateView* view() const { return hasView_ ? &view_ : nullptr; }
    void setView(const StateView& view) {
        view_ = view;
        hasView_ = true;
    }

    const glm::dmat4& modelMatrix() const { return models_.back(); }
    void setModelMatrix(const glm::dmat4& m);
    void multModelMatrix(const glm::dmat4& m); ///< model = model * m

    void add(const Node& property); ///< the node is in scope from here on

    /// The nearest entry whose node is a T, or null.
    template <class T> const StateEntry* nearest() const {
        for (auto it = entries_.rbegin(); it != entries_.rend(); ++it)
            if (it->node->template isA<T>()) return &*it;
        return nullptr;
    }
    template <class T> const T* nearestNode() const {
        const StateEntry* e = nearest<T>();
        return e ? static_cast<const T*>(e->node) : nullptr;
    }
    /// All entries whose node is a T, outermost first.
    template <class T> std::vector<const StateEntry*> all() const {
        std::vector<const StateEntry*> out;
        for (const auto& e : entries_)
            if (e.node->template isA<T>()) out.push_back(&e);
        return out;
    }
    const std::vector<StateEntry>& entries() const { return entries_; }

private:
    struct Mark {
        std::size_t models, entries;
    };
    std::vector<glm::dmat4> models_;
    std::vector<StateEntry> entries_;
    std::vector<Mark> marks_;
    StateView view_;
    bool hasView_ = false;
};

} // namespace volsg
