#include <volsg/geometry/PrimitiveMeshes.h>
#include <volsg/nodes/Cylinder.h>

namespace volsg {

const EnumValues Cylinder::partNames{
    {"SIDES", SIDES}, {"TOP", TOP}, {"BOTTOM", BOTTOM}, {"ALL", ALL}};

void Cylinder::buildMesh(const State&, Mesh& out) const {
    const int p = parts();
    buildCylinderMesh(radius(), height(), (p & SIDES) != 0, (p & TOP) != 0, (p & BOTTOM) != 0,
                      kRoundSlices, out);
}

} // namespace volsg
