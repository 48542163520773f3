// LightModel: puts itself in scope; ShapeRenderer reads the nearest one.
#include <volsg/nodes/LightModel.h>

#include <volsg/actions/Action.h>

namespace volsg {

const EnumValues LightModel::modelNames{{"BASE_COLOR", BASE_COLOR}, {"PHONG", PHONG}};

void LightModel::doAction(Action& action) {
    action.state().add(*this);
}

} // namespace volsg
