#pragma once
// AsciiText: Inventor 2.1's flat 3D text (SoAsciiText): the front faces of Text3 at z = 0,
// lit. A width > 0 for a line stretches its pen positions to that length (the glyphs keep
// their shape).
#include <cstdint>

#include <volsg/fields/Fields.h>
#include <volsg/nodes/Shape.h>

namespace volsg {

class AsciiText : public Inherit<Shape, AsciiText> {
public:
    static constexpr const char* typeName = "AsciiText";
    static constexpr bool inventorBuiltin() { return true; }
    enum Justification { LEFT = 1, RIGHT = 2, CENTER = 3 };
    static const EnumValues justificationNames;
    MFString string{this, "string", {""}};
    SFFloat spacing{this, "spacing", 1.0f};
    SFEnum justification{this, "justification", justificationNames, LEFT};
    MFFloat width{this, "width", {0.0f}};

    std::uint64_t meshKey(const State& state) const override;

protected:
    ~AsciiText() override = default;
    void buildMesh(const State& state, Mesh& out) const override;
};

} // namespace volsg
