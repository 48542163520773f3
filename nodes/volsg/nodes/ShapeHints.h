#pragma once
// ShapeHints: what the shapes after it are like (Inventor's SoShapeHints): the vertex order of
// their faces, whether they are closed solids, whether their faces are convex, and the crease
// angle below which generated normals are smoothed across faces.
//
// Drawing follows Inventor's rules (as Coin's SoShapeHintsElement): ordered and SOLID: back
// faces are culled; ordered and of unknown shape type: two-sided lighting; unordered: both
// sides drawn, lit one-sided (a face seen from behind keeps its normal, so it is dark).
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class ShapeHints : public Inherit<Node, ShapeHints> {
public:
    static constexpr const char* typeName = "ShapeHints";
    static constexpr bool inventorBuiltin() { return true; }
    enum VertexOrdering { UNKNOWN_ORDERING, CLOCKWISE, COUNTERCLOCKWISE };
    enum ShapeType { UNKNOWN_SHAPE_TYPE, SOLID };
    enum FaceType { UNKNOWN_FACE_TYPE, CONVEX };
    static const EnumValues vertexOrderingNames, shapeTypeNames, faceTypeNames;

    SFEnum vertexOrdering{this, "vertexOrdering", vertexOrderingNames, UNKNOWN_ORDERING};
    SFEnum shapeType{this, "shapeType", shapeTypeNames, UNKNOWN_SHAPE_TYPE};
    SFEnum faceType{this, "faceType", faceTypeNames, CONVEX};
    SFFloat creaseAngle{this, "creaseAngle", 0.0f}; ///< radians

    void doAction(Action& action) override;

protected:
    ~ShapeHints() override = default;
};

} // namespace volsg
