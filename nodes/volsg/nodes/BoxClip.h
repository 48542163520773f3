#pragma once
// BoxClip: changes opacity and colour inside and outside a box, for the volumes after it in
// scope (the seed's box clipping); with opacity 0 it also removes polygon geometry.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>
#include <volsg/volume/VolumeModel.h>

namespace volsg {

class BoxClip : public Inherit<Node, BoxClip> {
public:
    static constexpr const char* typeName = "BoxClip";

    SFVec3f origin{this, "origin", glm::vec3(-0.5f)}; ///< minimum corner, local coordinates
    SFVec3f extent{this, "extent", glm::vec3(1.0f)};
    SFFloat insideOpacity{this, "insideOpacity", 1.0f}; ///< extinction multipliers (0 removes)
    SFFloat outsideOpacity{this, "outsideOpacity", 0.0f};
    SFColor insideColor{this, "insideColor", glm::vec3(1.0f)};
    SFFloat insideColorWeight{this, "insideColorWeight", 0.0f};
    SFColor outsideColor{this, "outsideColor", glm::vec3(1.0f)};
    SFFloat outsideColorWeight{this, "outsideColorWeight", 0.0f};

    /// The box as the rendering model takes it; `model` maps its coordinates to world (the
    /// model matrix at this node in the state).
    RayCastBoxClip describe(const glm::dmat4& model) const;

    void doAction(Action& action) override;

protected:
    ~BoxClip() override = default;
};

} // namespace volsg
