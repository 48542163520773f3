#pragma once
// Text2: screen-aligned text (Inventor's SoText2). Its origin is the projected local origin;
// glyphs are the Font's size in pixels, unlit in the diffuse colour of the material in scope,
// at the origin's depth. Drawn by nodes/volsg/render/TextRendering.cpp (lib/volsg/text).
#include <volsg/fields/Fields.h>
#include <volsg/nodes/Shape.h>

namespace volsg {

class Text2 : public Inherit<Shape, Text2> {
public:
    static constexpr const char* typeName = "Text2";
    static constexpr bool inventorBuiltin() { return true; }
    enum Justification { LEFT = 1, RIGHT = 2, CENTER = 3 };
    static const EnumValues justificationNames;
    MFString string{this, "string", {""}};
    SFFloat spacing{this, "spacing", 1.0f};
    SFEnum justification{this, "justification", justificationNames, LEFT};

protected:
    ~Text2() override = default;
    /// No mesh: Text2 draws, bounds and picks in screen space (its own action methods).
    void buildMesh(const State& state, Mesh& out) const override;
};

} // namespace volsg
