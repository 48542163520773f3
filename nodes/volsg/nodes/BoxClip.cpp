#include <volsg/nodes/BoxClip.h>

#include <volsg/actions/Action.h>

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

// The box is read by the volume renderers from the state, in the coordinates at this node.
void BoxClip::doAction(Action& action) {
    action.state().add(*this);
}

} // namespace volsg
