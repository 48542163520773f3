#pragma once
// TextureCoordinate2: the texture coordinates the vertex shapes after it refer to.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class TextureCoordinate2 : public Inherit<Node, TextureCoordinate2> {
public:
    static constexpr const char* typeName = "TextureCoordinate2";
    static constexpr bool inventorBuiltin() { return true; }
    MFVec2f point{this, "point", {glm::vec2(0.0f)}};
    void doAction(Action& action) override;

protected:
    ~TextureCoordinate2() override = default;
};

} // namespace volsg
