#include <volsg/geometry/PrimitiveMeshes.h>
#include <volsg/nodes/Cone.h>

namespace volsg {

const EnumValues Cone::partNames{{"SIDES", SIDES}, {"BOTTOM", BOTTOM}, {"ALL", ALL}};

void Cone::buildMesh(const State&, Mesh& out) const {
    const int p = parts();
    buildConeMesh(bottomRadius(), height(), (p & SIDES) != 0, (p & BOTTOM) != 0, kRoundSlices, out);
}

} // namespace volsg
