// ResetTransform: Inventor's SoResetTransform.
#include <volsg/nodes/ResetTransform.h>

#include <volsg/actions/Action.h>

namespace volsg {

const EnumValues ResetTransform::whatToResetNames{{"TRANSFORM", TRANSFORM}, {"BBOX", BBOX}};

void ResetTransform::doAction(Action& action) {
    if (whatToReset() & TRANSFORM) action.state().setModelMatrix(glm::dmat4(1.0));
}

} // namespace volsg
