#pragma once
// TextureCoordinateDefault: back to the shapes' own default texture coordinates.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class TextureCoordinateDefault : public Inherit<Node, TextureCoordinateDefault> {
public:
    static constexpr const char* typeName = "TextureCoordinateDefault";
    static constexpr bool inventorBuiltin() { return true; }

    void doAction(Action& action) override;

protected:
    ~TextureCoordinateDefault() override = default;
};

} // namespace volsg
