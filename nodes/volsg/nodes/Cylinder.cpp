#include <volsg/geometry/PrimitiveMeshes.h>
#include <volsg/nodes/Cylinder.h>
#include <volsg/nodes/PrimitiveParts.h>
#include <volsg/nodes/ShapeState.h>

#include <algorithm>

namespace volsg {

const EnumValues Cylinder::partNames{
    {"SIDES", SIDES}, {"TOP", TOP}, {"BOTTOM", BOTTOM}, {"ALL", ALL}};

void Cylinder::buildMesh(const State& state, Mesh& out) const {
    const int p = parts();
    const int slices = roundSlicesFor(gatherShapeState(state, nullptr).complexityValue());
    PartStarts starts;
    buildCylinderMesh(radius(), height(), (p & SIDES) != 0, (p & TOP) != 0, (p & BOTTOM) != 0,
                      slices, out, &starts);
    std::vector<int> built;
    if (p & SIDES) built.push_back(0);
    if (p & TOP) built.push_back(1);
    if (p & BOTTOM) built.push_back(2);
    colorPrimitiveParts(state, starts, built, out);
}

} // namespace volsg
