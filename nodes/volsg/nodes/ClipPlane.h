#pragma once
// ClipPlane: keeps the points p with normal . p >= distance (local coordinates) for every
// shape and volume after it in scope.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class ClipPlane : public Inherit<Node, ClipPlane> {
public:
    static constexpr const char* typeName = "ClipPlane";
    static constexpr bool inventorBuiltin() { return true; }
    SFPlane plane{this, "plane", Plane{glm::vec3(1.0f, 0.0f, 0.0f), 0.0f}};
    SFBool on{this, "on", true};

    /// The plane in world coordinates, as (a, b, c, d) with kept points a*x+b*y+c*z >= d,
    /// given the model matrix at the node.
    static glm::dvec4 worldPlane(const Plane& local, const glm::dmat4& model);
    void doAction(Action& action) override;

protected:
    ~ClipPlane() override = default;
};

} // namespace volsg
