#include <volsg/geometry/PrimitiveMeshes.h>
#include <volsg/nodes/Cone.h>
#include <volsg/nodes/PrimitiveParts.h>
#include <volsg/nodes/ShapeState.h>

#include <algorithm>

namespace volsg {

const EnumValues Cone::partNames{{"SIDES", SIDES}, {"BOTTOM", BOTTOM}, {"ALL", ALL}};

void Cone::buildMesh(const State& state, Mesh& out) const {
    const int p = parts();
    const int slices = roundSlicesFor(gatherShapeState(state, nullptr).complexityValue());
    PartStarts starts;
    buildConeMesh(bottomRadius(), height(), (p & SIDES) != 0, (p & BOTTOM) != 0, slices, out,
                  &starts);
    std::vector<int> built;
    if (p & SIDES) built.push_back(0);
    if (p & BOTTOM) built.push_back(1);
    colorPrimitiveParts(state, starts, built, out);
}

} // namespace volsg
