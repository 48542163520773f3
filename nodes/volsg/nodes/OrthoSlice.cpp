// OrthoSlice: its plane and style as lib/volsg/sections takes them, and its clip plane (the
// render, bounding box and pick actions hand them over with the volume in scope).
#include <volsg/nodes/OrthoSlice.h>

#include <volsg/actions/Action.h>
#include <volsg/nodes/VolumeData.h>

namespace volsg {

const EnumValues OrthoSlice::axisNames{{"X", X}, {"Y", Y}, {"Z", Z}};
const EnumValues OrthoSlice::interpolationNames{{"NEAREST", NEAREST}, {"LINEAR", LINEAR}};
const EnumValues OrthoSlice::alphaUseNames{
    {"ALPHA_AS_IS", ALPHA_AS_IS}, {"ALPHA_OPAQUE", ALPHA_OPAQUE}, {"ALPHA_BINARY", ALPHA_BINARY}};
const EnumValues OrthoSlice::clippingSideNames{{"FRONT", FRONT}, {"BACK", BACK}};

SliceStyle OrthoSlice::style() const {
    // The node's enums are in SliceAlphaUse's order.
    return SliceStyle{interpolation() == LINEAR, SliceAlphaUse(alphaUse())};
}

SlicePlane OrthoSlice::localPlane(const VolumeGrid& data) const {
    return SlicePlane::orthogonal(data, axis(), sliceNumber());
}

void OrthoSlice::doAction(Action& action) {
    if (!clipping()) return;
    const VolumeData* node = action.state().nearestNode<VolumeData>();
    const ref_ptr<const VolumeGrid> data = node ? node->grid() : nullptr;
    if (!data) return;
    const SlicePlane plane = localPlane(*data);
    // BACK removes the side below the slice along its axis (keeps n . p >= d), FRONT the side
    // above it.
    const float sign = clippingSide() == BACK ? 1.0f : -1.0f;
    const Plane kept{glm::vec3(plane.normal) * sign, float(plane.distance) * sign};
    if (!clipPlane_) clipPlane_ = ClipPlane::create();
    if (!(clipPlane_->plane() == kept)) clipPlane_->plane = kept;
    action.state().add(*clipPlane_);
}

} // namespace volsg
