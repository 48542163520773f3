#pragma once
// CameraKit: a camera (a PerspectiveCamera unless set) placed by its transform part, both in a
// TransformSeparator (transformGroup) (Inventor's SoCameraKit).
#include <volsg/nodes/BaseKit.h>

namespace volsg {

class CameraKit : public Inherit<BaseKit, CameraKit> {
public:
    static constexpr const char* typeName = "CameraKit";
    static constexpr bool inventorBuiltin() { return true; }

    SFNode transformGroup{this, "transformGroup"}; ///< private container: kept, not traversed
    SFNode transform{this, "transform"};
    SFNode camera{this, "camera"};

    /// What `camera` stands for: its node once set (NULL too), else a PerspectiveCamera of the
    /// kit's own.
    Node* cameraNode() { return partOrDefault(camera, default_, &makePerspectiveCamera); }
    void doAction(Action& action) override;

protected:
    ~CameraKit() override = default;

private:
    static ref_ptr<Node> makePerspectiveCamera();
    ref_ptr<Node> default_; ///< made when first needed: Inventor's default camera part
};

} // namespace volsg
