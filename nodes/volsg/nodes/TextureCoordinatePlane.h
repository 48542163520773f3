#pragma once
// TextureCoordinatePlane: s = directionS . p, t = directionT . p in the shape's local
// coordinates.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class TextureCoordinatePlane : public Inherit<Node, TextureCoordinatePlane> {
public:
    static constexpr const char* typeName = "TextureCoordinatePlane";
    static constexpr bool inventorBuiltin() { return true; }
    SFVec3f directionS{this, "directionS", glm::vec3(1.0f, 0.0f, 0.0f)};
    SFVec3f directionT{this, "directionT", glm::vec3(0.0f, 1.0f, 0.0f)};
    void doAction(Action& action) override;

protected:
    ~TextureCoordinatePlane() override = default;
};

} // namespace volsg
