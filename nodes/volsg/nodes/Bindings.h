#pragma once
// MaterialBinding, NormalBinding, TextureCoordinateBinding: how the materials, normals and
// texture coordinates in scope map to the parts, faces and vertices of the shapes after them
// (lib/volsg/geometry/VertexShapes.h says what a part and a face are for each shape).
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>
#include <volsg/geometry/VertexShapes.h>

namespace volsg {

/// Inventor's binding values (DEFAULT and NONE are read as Inventor 2.1 maps them and written
/// back as the value they stand for).
enum BindingValue {
    OVERALL = 2,
    PER_PART = 3,
    PER_PART_INDEXED = 4,
    PER_FACE = 5,
    PER_FACE_INDEXED = 6,
    PER_VERTEX = 7,
    PER_VERTEX_INDEXED = 8,
};
/// The names of the values, with DEFAULT and NONE meaning `defaultValue`.
EnumValues bindingNames(int defaultValue);
Binding toBinding(int value);

class MaterialBinding : public Inherit<Node, MaterialBinding> {
public:
    static constexpr const char* typeName = "MaterialBinding";
    static constexpr bool inventorBuiltin() { return true; }
    static const EnumValues valueNames;
    SFEnum value{this, "value", valueNames, OVERALL};
    void doAction(Action& action) override;

protected:
    ~MaterialBinding() override = default;
};

class NormalBinding : public Inherit<Node, NormalBinding> {
public:
    static constexpr const char* typeName = "NormalBinding";
    static constexpr bool inventorBuiltin() { return true; }
    static const EnumValues valueNames;
    SFEnum value{this, "value", valueNames, PER_VERTEX_INDEXED};
    void doAction(Action& action) override;

protected:
    ~NormalBinding() override = default;
};

/// PER_VERTEX or PER_VERTEX_INDEXED only.
class TextureCoordinateBinding : public Inherit<Node, TextureCoordinateBinding> {
public:
    static constexpr const char* typeName = "TextureCoordinateBinding";
    static constexpr bool inventorBuiltin() { return true; }
    static const EnumValues valueNames;
    SFEnum value{this, "value", valueNames, PER_VERTEX_INDEXED};
    void doAction(Action& action) override;

protected:
    ~TextureCoordinateBinding() override = default;
};

} // namespace volsg
