#include <volsg/nodes/BoxClip.h>

#include <volsg/actions/Action.h>

namespace volsg {

// The box is read by the volume renderers from the state, in the coordinates at this node.
void BoxClip::doAction(Action& action) {
    action.state().add(*this);
}

} // namespace volsg
