// ObliqueSlice: finds its volume in the state and hands it with its plane to
// lib/volsg/sections (drawing, picking, bounds).
#include <volsg/nodes/ObliqueSlice.h>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/actions/PickAction.h>
#include <volsg/render/RenderAction.h>
#include <volsg/sections/SlicePick.h>
#include <volsg/sections/SliceRenderer.h>

namespace volsg {

std::optional<SlicePlane> ObliqueSlice::localPlane() const {
    return SlicePlane::fromPlane(glm::dvec3(plane().normal), double(plane().distance));
}

SliceStyle ObliqueSlice::style() const {
    return SliceStyle{interpolation() == OrthoSlice::LINEAR, SliceAlphaUse(alphaUse())};
}

void ObliqueSlice::render(RenderAction& action) {
    const auto volume = SliceVolume::fromState(action.state());
    const auto plane = localPlane();
    if (volume && plane) SliceRenderer::draw(action, *volume, *plane, style());
}

void ObliqueSlice::getBoundingBox(BoundingBoxAction& action) {
    const auto volume = SliceVolume::fromState(action.state());
    const auto plane = localPlane();
    if (volume && plane) action.extendByLocal(plane->polygonBounds(volume->halfExtent()));
}

void ObliqueSlice::pick(PickAction& action) {
    const auto volume = SliceVolume::fromState(action.state());
    const auto plane = localPlane();
    if (volume && plane) pickSlice(action, *volume, *plane, style());
}

} // namespace volsg
