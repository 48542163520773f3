#pragma once
// VertexProperty: the vertex data of a shape in one node (Inventor's SoVertexProperty): as a
// shape's vertexProperty field it is that shape's data; in the graph it sets the coordinates,
// normals, texture coordinates and packed colours of the shapes after it. Empty fields leave
// the state alone. orderedRGBA packs 0xRRGGBBAA (alpha = 1 - transparency).
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>
#include <volsg/nodes/Bindings.h>

namespace volsg {

class VertexProperty : public Inherit<Node, VertexProperty> {
public:
    static constexpr const char* typeName = "VertexProperty";
    static constexpr bool inventorBuiltin() { return true; }
    static const EnumValues normalBindingNames, materialBindingNames;

    MFVec3f vertex{this, "vertex", {}};
    MFVec3f normal{this, "normal", {}};
    MFVec2f texCoord{this, "texCoord", {}};
    MFUInt32 orderedRGBA{this, "orderedRGBA", {}};
    SFEnum normalBinding{this, "normalBinding", normalBindingNames, PER_VERTEX_INDEXED};
    SFEnum materialBinding{this, "materialBinding", materialBindingNames, OVERALL};

    void doAction(Action& action) override;

protected:
    ~VertexProperty() override = default;
};

/// 0xRRGGBBAA as colour and alpha in [0, 1].
glm::vec4 unpackRGBA(std::uint32_t packed);

} // namespace volsg
