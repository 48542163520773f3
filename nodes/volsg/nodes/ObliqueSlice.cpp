// ObliqueSlice: its plane and style as lib/volsg/sections takes them (the render, bounding
// box and pick actions hand them over with the volume in scope).
#include <volsg/nodes/ObliqueSlice.h>

namespace volsg {

std::optional<SlicePlane> ObliqueSlice::localPlane() const {
    return SlicePlane::fromPlane(glm::dvec3(plane().normal), double(plane().distance));
}

SliceStyle ObliqueSlice::style() const {
    return SliceStyle{interpolation() == OrthoSlice::LINEAR, SliceAlphaUse(alphaUse())};
}

} // namespace volsg
