#include <volsg/actions/Action.h>
#include <volsg/nodes/PickStyle.h>

namespace volsg {

const EnumValues PickStyle::styleNames{{"SHAPE", SHAPE},
                                       {"BOUNDING_BOX", BOUNDING_BOX},
                                       {"UNPICKABLE", UNPICKABLE},
                                       {"SHAPE_ON_TOP", SHAPE_ON_TOP},
                                       {"BOUNDING_BOX_ON_TOP", BOUNDING_BOX_ON_TOP},
                                       {"SHAPE_FRONTFACES", SHAPE_FRONTFACES}};

PickStyle::Style PickStyle::inScope(const State& state) {
    const PickStyle* p = state.nearestNode<PickStyle>();
    if (!p) return SHAPE;
    switch (p->style()) {
    case BOUNDING_BOX:
    case BOUNDING_BOX_ON_TOP:
        return BOUNDING_BOX;
    case UNPICKABLE:
        return UNPICKABLE;
    default:
        return SHAPE;
    }
}

void PickStyle::doAction(Action& action) {
    action.state().add(*this);
}

} // namespace volsg
