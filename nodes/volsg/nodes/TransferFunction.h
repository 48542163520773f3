#pragma once
// TransferFunction: data value -> colour and opacity for the volumes after it in scope, for one
// tag (or every voxel without its own, tag -1). docs/SCENE-FORMAT.md sections 3-4.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class TransferFunction1D;
class VolumeGrid;

class TransferFunction : public Inherit<Node, TransferFunction> {
public:
    static constexpr const char* typeName = "TransferFunction";

    SFInt32 tag{this, "tag", -1};
    /// Data values mapped to v = 0 and v = 1. Unset (default): the data type's range.
    SFVec2f dataRange{this, "dataRange", glm::vec2(0.0f, 255.0f)};
    MFVec2f red{this, "red", {glm::vec2(0, 0), glm::vec2(1, 1)}}; ///< (v, output) points
    MFVec2f green{this, "green", {glm::vec2(0, 0), glm::vec2(1, 1)}};
    MFVec2f blue{this, "blue", {glm::vec2(0, 0), glm::vec2(1, 1)}};
    MFVec2f alpha{this, "alpha", {glm::vec2(0, 0), glm::vec2(1, 1)}};

    /// The exact function (dataRange left unset when the field is default). Throws Error for
    /// an empty channel or non-finite values.
    TransferFunction1D function() const;
    void doAction(Action& action) override;

protected:
    ~TransferFunction() override = default;
};

} // namespace volsg
