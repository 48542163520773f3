#pragma once
// LOD: a Group that traverses one child, chosen by the distance from the camera to `center`
// (Inventor's SoLOD). Child i is used for distances below range[i] (and at or above
// range[i-1]); past the last range the next child, clamped to the last one.
//
// Its doAction (bounding boxes, searches and every walk without a camera) traverses all the
// children, as Inventor's bounding box and search actions do; RenderAction and PickAction
// choose one (nodes/volsg/render/InventorRendering.cpp, nodes/volsg/actions/PickAction.cpp).
#include <volsg/fields/Fields.h>
#include <volsg/nodes/Group.h>

namespace volsg {

class LOD : public Inherit<Group, LOD> {
public:
    static constexpr const char* typeName = "LOD";
    static constexpr bool inventorBuiltin() { return true; }

    SFVec3f center{this, "center", glm::vec3(0.0f)}; ///< in the node's local coordinates
    MFFloat range{this, "range"};                    ///< ascending distances (world units)

    /// The child to traverse for a camera at `eye` (world), with `model` the model matrix at
    /// this node; -1 when there are no children.
    int childFor(const glm::dvec3& eye, const glm::dmat4& model) const;

protected:
    ~LOD() override = default;
};

} // namespace volsg
