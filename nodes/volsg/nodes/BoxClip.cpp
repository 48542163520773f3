#include <volsg/nodes/BoxClip.h>

#include <cmath>
#include <string>

#include <volsg/actions/Action.h>
#include <volsg/core/Error.h>

namespace volsg {

RayCastBoxClip BoxClip::describe(const glm::dmat4& model) const {
    RayCastBoxClip box;
    box.origin = glm::dvec3(origin());
    box.extent = glm::dvec3(extent());
    box.model = model;
    box.insideOpacity = insideOpacity();
    box.outsideOpacity = outsideOpacity();
    box.insideColor = glm::dvec3(insideColor());
    box.insideColorWeight = insideColorWeight();
    box.outsideColor = glm::dvec3(outsideColor());
    box.outsideColorWeight = outsideColorWeight();
    return box;
}

namespace {

// A file cannot hold NaN or infinity (the reader refuses them), code can: refused here, where
// the box enters the state, so no volume path blends with it or compares against it.
void requireFinite(const SFFloat& f) {
    if (!std::isfinite(f())) throw Error(std::string(f.name()) + " is not a finite number");
}
void requireFinite(const SField<Vec3fTraits>& f) {
    const glm::vec3 v = f();
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        throw Error(std::string(f.name()) + " is not a finite number");
}
void requireFinite(const SField<ColorTraits>& f) {
    const glm::vec3 v = f();
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        throw Error(std::string(f.name()) + " is not a finite number");
}

} // namespace

// The box is read by the volume renderers from the state, in the coordinates at this node.
void BoxClip::doAction(Action& action) {
    requireFinite(origin);
    requireFinite(extent);
    requireFinite(insideOpacity);
    requireFinite(outsideOpacity);
    requireFinite(insideColor);
    requireFinite(insideColorWeight);
    requireFinite(outsideColor);
    requireFinite(outsideColorWeight);
    action.state().add(*this);
}

} // namespace volsg
