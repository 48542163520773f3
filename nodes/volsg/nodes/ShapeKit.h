#pragma once
// ShapeKit: a SeparatorKit with the property parts of a shape and the shape itself (a Cube
// unless set), drawn under localTransform in a separator of its own (Inventor's SoShapeKit).
// Order under topSeparator: the SeparatorKit's parts up to texture2Transform, the bindings,
// shape hints, coordinates, normals, texture coordinates and profiles, childList,
// textureCoordinateFunction, localTransform, then shapeSeparator { shape }.
#include <volsg/nodes/SeparatorKit.h>

namespace volsg {

class ShapeKit : public Inherit<SeparatorKit, ShapeKit> {
public:
    static constexpr const char* typeName = "ShapeKit";
    static constexpr bool inventorBuiltin() { return true; }

    SFNode materialBinding{this, "materialBinding"};
    SFNode normalBinding{this, "normalBinding"};
    SFNode textureCoordinateBinding{this, "textureCoordinateBinding"};
    SFNode shapeHints{this, "shapeHints"};
    SFNode coordinate3{this, "coordinate3"};
    SFNode coordinate4{this, "coordinate4"};
    SFNode normal{this, "normal"};
    SFNode textureCoordinate2{this, "textureCoordinate2"};
    SFNode textureCoordinateFunction{this, "textureCoordinateFunction"};
    SFNode profileCoordinate2{this, "profileCoordinate2"};
    SFNode profileCoordinate3{this, "profileCoordinate3"};
    SFNode profileList{this, "profileList"};
    SFNode localTransform{this, "localTransform"};
    SFNode shapeSeparator{this, "shapeSeparator"}; ///< private container: kept, not traversed
    SFNode shape{this, "shape"};

    /// What `shape` stands for: its node once set (NULL too), else a Cube of the kit's own.
    Node* shapeNode() { return partOrDefault(shape, default_, &makeCube); }
    void doAction(Action& action) override;

protected:
    ~ShapeKit() override = default;

private:
    static ref_ptr<Node> makeCube();
    ref_ptr<Node> default_; ///< made when first needed: Inventor's default shape part
};

} // namespace volsg
