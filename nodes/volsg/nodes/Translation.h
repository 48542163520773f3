#pragma once
// Translation: model = model * T(translation) (Inventor's SoTranslation).
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class Translation : public Inherit<Node, Translation> {
public:
    static constexpr const char* typeName = "Translation";
    static constexpr bool inventorBuiltin() { return true; }
    SFVec3f translation{this, "translation", glm::vec3(0.0f)};

    void doAction(Action& action) override;

protected:
    ~Translation() override = default;
};

} // namespace volsg
