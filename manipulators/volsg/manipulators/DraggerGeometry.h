#pragma once
// The visible, pickable handles of a manipulator: a small scene graph of coloured parts, each
// under its own Transform, that the manipulator re-places as its fields change.

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <volsg/core/Node.h>

namespace volsg {

class Separator;
class Transform;
class Material;

class DraggerGeometry {
public:
    DraggerGeometry();
    ~DraggerGeometry();
    DraggerGeometry(const DraggerGeometry&) = delete;
    DraggerGeometry& operator=(const DraggerGeometry&) = delete;

    /// Adds a part drawn with `shape` in `color` (emissive, so it reads without lights), with
    /// `transparency` as Material's; returns its id (0, 1, ... in order of adding).
    int addPart(ref_ptr<Node> shape, const glm::vec3& color, float transparency = 0.0f);
    /// Places part `id`: its shape is rotated by `rotation`, then moved to `position`.
    void place(int id, const glm::dvec3& position, const glm::dquat& rotation = {1, 0, 0, 0});
    /// The part's shape node (to resize it).
    Node& shape(int id) const;
    /// Part `id` is drawn highlighted (the one being dragged); -1 for none.
    void highlight(int id);

    /// The part a pick path went through, or -1 when it hit none of these handles.
    int partOnPath(const std::vector<Node*>& path) const;

    /// The graph to traverse (a Separator, so the parts' state stays inside).
    Node& root() const;

private:
    struct Part {
        ref_ptr<Separator> group;
        ref_ptr<Transform> transform;
        ref_ptr<Material> material;
        ref_ptr<Node> shape;
        glm::vec3 color;
    };
    ref_ptr<Separator> root_;
    std::vector<Part> parts_;
    int highlighted_ = -1;
};

} // namespace volsg
