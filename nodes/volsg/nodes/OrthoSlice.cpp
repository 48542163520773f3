// OrthoSlice: finds its volume and plane in the state and hands them to lib/volsg/sections
// (drawing, picking, bounds).
#include <volsg/nodes/OrthoSlice.h>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/actions/PickAction.h>
#include <volsg/render/RenderAction.h>
#include <volsg/sections/SlicePick.h>
#include <volsg/sections/SliceRenderer.h>

namespace volsg {

const EnumValues OrthoSlice::axisNames{{"X", X}, {"Y", Y}, {"Z", Z}};
const EnumValues OrthoSlice::interpolationNames{{"NEAREST", NEAREST}, {"LINEAR", LINEAR}};
const EnumValues OrthoSlice::alphaUseNames{
    {"ALPHA_AS_IS", ALPHA_AS_IS}, {"ALPHA_OPAQUE", ALPHA_OPAQUE}, {"ALPHA_BINARY", ALPHA_BINARY}};
const EnumValues OrthoSlice::clippingSideNames{{"FRONT", FRONT}, {"BACK", BACK}};

namespace {

SlicePlane orthoPlane(const OrthoSlice& slice, const SliceVolume& volume) {
    return SlicePlane::orthogonal(*volume.data, slice.axis(), slice.sliceNumber());
}

} // namespace

SliceStyle OrthoSlice::style() const {
    // The node's enums are in SliceAlphaUse's order.
    return SliceStyle{interpolation() == LINEAR, SliceAlphaUse(alphaUse())};
}

void OrthoSlice::doAction(Action& action) {
    addClipPlane(action);
}

void OrthoSlice::addClipPlane(Action& action) {
    if (!clipping()) return;
    const auto volume = SliceVolume::fromState(action.state());
    if (!volume) return;
    const SlicePlane plane = orthoPlane(*this, *volume);
    // BACK removes the side below the slice along its axis (keeps n . p >= d), FRONT the side
    // above it.
    const float sign = clippingSide() == BACK ? 1.0f : -1.0f;
    const Plane kept{glm::vec3(plane.normal) * sign, float(plane.distance) * sign};
    if (!clipPlane_) clipPlane_ = ClipPlane::create();
    if (!(clipPlane_->plane() == kept)) clipPlane_->plane = kept;
    action.state().add(*clipPlane_);
}

void OrthoSlice::render(RenderAction& action) {
    // The slice itself is not clipped by its own plane: it draws before the plane is in scope.
    if (const auto volume = SliceVolume::fromState(action.state()))
        SliceRenderer::draw(action, *volume, orthoPlane(*this, *volume), style());
    addClipPlane(action);
}

void OrthoSlice::getBoundingBox(BoundingBoxAction& action) {
    if (const auto volume = SliceVolume::fromState(action.state()))
        action.extendByLocal(orthoPlane(*this, *volume).polygonBounds(volume->halfExtent()));
    addClipPlane(action);
}

void OrthoSlice::pick(PickAction& action) {
    if (const auto volume = SliceVolume::fromState(action.state()))
        pickSlice(action, *volume, orthoPlane(*this, *volume), style());
    addClipPlane(action);
}

} // namespace volsg
