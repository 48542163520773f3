#pragma once
// SceneKit: cameras, lights and child kits under one separator: cameraList (its container a
// Switch choosing the camera), lightList, childList (Inventor's SoSceneKit).
#include <volsg/nodes/BaseKit.h>

namespace volsg {

class SceneKit : public Inherit<BaseKit, SceneKit> {
public:
    static constexpr const char* typeName = "SceneKit";
    static constexpr bool inventorBuiltin() { return true; }

    SFNode topSeparator{this, "topSeparator"}; ///< private container: kept, not traversed
    SFNode cameraList{this, "cameraList"};
    SFNode lightList{this, "lightList"};
    SFNode childList{this, "childList"};

    void doAction(Action& action) override;

protected:
    ~SceneKit() override = default;
};

} // namespace volsg
