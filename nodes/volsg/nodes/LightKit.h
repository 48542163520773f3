#pragma once
// LightKit: a light (a DirectionalLight unless set) placed by its transform part, both in a
// TransformSeparator (transformGroup), so the light stays in scope after the kit but the
// transform does not; an optional icon in a separator (Inventor's SoLightKit).
#include <volsg/nodes/BaseKit.h>

namespace volsg {

class LightKit : public Inherit<BaseKit, LightKit> {
public:
    static constexpr const char* typeName = "LightKit";
    static constexpr bool inventorBuiltin() { return true; }

    SFNode transformGroup{this, "transformGroup"}; ///< private container: kept, not traversed
    SFNode transform{this, "transform"};
    SFNode light{this, "light"};
    SFNode iconSeparator{this, "iconSeparator"}; ///< private container: kept, not traversed
    SFNode icon{this, "icon"};

    /// What `light` stands for: its node once set (NULL too), else a DirectionalLight of the kit's
    /// own.
    Node* lightNode() { return partOrDefault(light, default_, &makeDirectionalLight); }
    void doAction(Action& action) override;

protected:
    ~LightKit() override = default;

private:
    static ref_ptr<Node> makeDirectionalLight();
    ref_ptr<Node> default_; ///< made when first needed: Inventor's default light part
};

} // namespace volsg
