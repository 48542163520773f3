#pragma once
// TextureCoordinateEnvironment: sphere-map coordinates from the reflected view direction.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class TextureCoordinateEnvironment : public Inherit<Node, TextureCoordinateEnvironment> {
public:
    static constexpr const char* typeName = "TextureCoordinateEnvironment";
    static constexpr bool inventorBuiltin() { return true; }

    void doAction(Action& action) override;

protected:
    ~TextureCoordinateEnvironment() override = default;
};

} // namespace volsg
