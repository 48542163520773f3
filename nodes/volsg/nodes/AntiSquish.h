#pragma once
// AntiSquish (Inventor's SoAntiSquish): makes the scale of the model matrix uniform, so what
// follows keeps its proportions under a non-uniform scale (draggers use it for their handles).
// The model matrix is decomposed (translation, rotation, scale, scale orientation) and put
// back with every scale set to the one `sizing` picks: one axis, the average, the biggest or
// smallest, or half the longest diagonal of the transformed cube [-1, 1]^3.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

#include <glm/glm.hpp>

namespace volsg {

class AntiSquish : public Inherit<Node, AntiSquish> {
public:
    static constexpr const char* typeName = "AntiSquish";
    static constexpr bool inventorBuiltin() { return true; }
    enum Sizing {
        X,
        Y,
        Z,
        AVERAGE_DIMENSION,
        BIGGEST_DIMENSION,
        SMALLEST_DIMENSION,
        LONGEST_DIAGONAL
    };
    static const EnumValues sizingNames;

    SFBool recalcAlways{this, "recalcAlways", true}; ///< kept; volsg recomputes every time
    SFEnum sizing{this, "sizing", sizingNames, AVERAGE_DIMENSION};

    /// The model matrix after this node, given the one before it.
    glm::dmat4 unsquished(const glm::dmat4& model) const;

    void doAction(Action& action) override;

protected:
    ~AntiSquish() override = default;
};

} // namespace volsg
