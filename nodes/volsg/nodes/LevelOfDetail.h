#pragma once
// LevelOfDetail: a Group that traverses one child, chosen by the area in pixels that the
// bounding box of all its children covers on the screen (Inventor's SoLevelOfDetail): the
// first child i whose screenArea[i] is below that area, else the last child.
//
// Its doAction (bounding boxes, searches and every walk without a camera) traverses all the
// children, as Inventor's bounding box and search actions do; RenderAction and PickAction
// choose one (nodes/volsg/render/InventorRendering.cpp, nodes/volsg/actions/PickAction.cpp).
#include <volsg/fields/Fields.h>
#include <volsg/math/Box3.h>
#include <volsg/nodes/Group.h>

namespace volsg {

class LevelOfDetail : public Inherit<Group, LevelOfDetail> {
public:
    static constexpr const char* typeName = "LevelOfDetail";
    static constexpr bool inventorBuiltin() { return true; }

    MFFloat screenArea{this, "screenArea", {0.0f}}; ///< descending areas in square pixels

    /// The projected size of `localBox` (the children's box in this node's coordinates) as
    /// Coin's SoShape::getScreenSize computes it: the screen rectangle of the eight corners
    /// under `projection * view * model`, each side clamped to 10 NDC units, in whole pixels.
    static glm::ivec2 screenSize(const Box3& localBox, const glm::dmat4& modelViewProjection,
                                 int viewportWidth, int viewportHeight);
    /// The child for a projected area in square pixels; -1 when there are no children.
    int childFor(double projectedArea) const;

protected:
    ~LevelOfDetail() override = default;
};

} // namespace volsg
