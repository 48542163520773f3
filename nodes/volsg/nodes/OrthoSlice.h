#pragma once
// OrthoSlice: one axis-aligned plane of the current VolumeData through its TransferFunction(s),
// drawn as a textured polygon (Open Inventor VolumeViz SoOrthoSlice). With clipping TRUE the
// plane also clips the volumes and shapes after it in scope, like a ClipPlane.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/sections/SlicePlane.h>
#include <volsg/sections/SliceSampler.h>

namespace volsg {

class OrthoSlice : public Inherit<Node, OrthoSlice> {
public:
    static constexpr const char* typeName = "OrthoSlice";
    enum Axis { X, Y, Z };
    enum Interpolation { NEAREST, LINEAR };
    enum AlphaUse { ALPHA_AS_IS, ALPHA_OPAQUE, ALPHA_BINARY };
    enum ClippingSide { FRONT, BACK };
    static const EnumValues axisNames, interpolationNames, alphaUseNames, clippingSideNames;

    /// Voxel index along axis (clamped to the data); the slice passes through voxel centres.
    SFInt32 sliceNumber{this, "sliceNumber", 0};
    SFEnum axis{this, "axis", axisNames, Z};
    SFEnum interpolation{this, "interpolation", interpolationNames, LINEAR};
    SFEnum alphaUse{this, "alphaUse", alphaUseNames, ALPHA_BINARY};
    SFBool clipping{this, "clipping", false};
    /// The side removed when clipping: FRONT removes the +axis side, BACK the -axis side.
    SFEnum clippingSide{this, "clippingSide", clippingSideNames, BACK};

    SliceStyle style() const; ///< interpolation and alphaUse as lib/volsg/sections takes them
    /// The slice's plane through `data` (sliceNumber clamped to it).
    SlicePlane localPlane(const VolumeGrid& data) const;

    /// With clipping: puts the slice plane in scope as a ClipPlane (kept by this node, not part
    /// of the graph), so every consumer of ClipPlanes (Volume, ShearWarpVolume, shapes, picking,
    /// the reference) clips with it unchanged. The slice itself draws before its plane is in
    /// scope, so it is not clipped by it.
    void doAction(Action& action) override;

protected:
    ~OrthoSlice() override = default;

private:
    /// Made on first use, not in the constructor: fields constructed while a prototype of this
    /// type records its field table would be taken for this node's (NodeType::fields()).
    ref_ptr<ClipPlane> clipPlane_;
};

} // namespace volsg
