#pragma once
// MatrixTransform: model = model * matrix. The file lists the matrix row by row as Inventor
// does (translation in the last row, since SbMatrix is row-vector).
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class MatrixTransform : public Inherit<Node, MatrixTransform> {
public:
    static constexpr const char* typeName = "MatrixTransform";
    static constexpr bool inventorBuiltin() { return true; }
    /// Stored as a column-major GLM matrix acting on column vectors (the transpose of the
    /// file's row-vector matrix); MatrixTraits reads and writes the file's order.
    SFMatrix matrix{this, "matrix", glm::mat4(1.0f)};

    void doAction(Action& action) override;

protected:
    ~MatrixTransform() override = default;
};

} // namespace volsg
