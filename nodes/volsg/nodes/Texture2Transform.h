#pragma once
// Texture2Transform: moves the texture coordinates of the shapes after it (accumulating with
// the ones before it): p' = T(translation) T(center) R(rotation) S(scaleFactor) T(-center) p.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class Texture2Transform : public Inherit<Node, Texture2Transform> {
public:
    static constexpr const char* typeName = "Texture2Transform";
    static constexpr bool inventorBuiltin() { return true; }
    SFVec2f translation{this, "translation", glm::vec2(0.0f)};
    SFFloat rotation{this, "rotation", 0.0f};
    SFVec2f scaleFactor{this, "scaleFactor", glm::vec2(1.0f)};
    SFVec2f center{this, "center", glm::vec2(0.0f)};

    /// The matrix that maps a texture coordinate (s, t, 0, 1).
    glm::mat4 matrix() const;
    void doAction(Action& action) override;

protected:
    ~Texture2Transform() override = default;
};

} // namespace volsg
