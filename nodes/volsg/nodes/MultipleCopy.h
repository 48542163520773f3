#pragma once
// MultipleCopy: draws its children once per matrix, each copy under model * matrix[i] and
// separated (Inventor's SoMultipleCopy).
#include <volsg/fields/Fields.h>
#include <volsg/nodes/Group.h>

namespace volsg {

class MultipleCopy : public Inherit<Group, MultipleCopy> {
public:
    static constexpr const char* typeName = "MultipleCopy";
    static constexpr bool inventorBuiltin() { return true; }

    /// Row by row as Inventor writes them, like MatrixTransform's matrix.
    MFMatrix matrix{this, "matrix", {glm::mat4(1.0f)}};

    void doAction(Action& action) override;

protected:
    ~MultipleCopy() override = default;
};

} // namespace volsg
