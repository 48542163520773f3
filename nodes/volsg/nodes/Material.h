#pragma once
// Material: Phong parameters for the shapes that follow. Fields are lists as in Inventor; the
// first value of each is used.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class Material : public Inherit<Node, Material> {
public:
    static constexpr const char* typeName = "Material";
    static constexpr bool inventorBuiltin() { return true; }
    MFColor ambientColor{this, "ambientColor", {glm::vec3(0.2f)}};
    MFColor diffuseColor{this, "diffuseColor", {glm::vec3(0.8f)}};
    MFColor specularColor{this, "specularColor", {glm::vec3(0.0f)}};
    MFColor emissiveColor{this, "emissiveColor", {glm::vec3(0.0f)}};
    MFFloat shininess{this, "shininess", {0.2f}};
    MFFloat transparency{this, "transparency", {0.0f}};

    void doAction(Action& action) override;

protected:
    ~Material() override = default;
};

} // namespace volsg
