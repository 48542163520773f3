#include <volsg/geometry/PrimitiveMeshes.h>
#include <volsg/nodes/PrimitiveParts.h>
#include <volsg/nodes/ShapeState.h>
#include <volsg/nodes/Sphere.h>

#include <algorithm>

namespace volsg {

void Sphere::buildMesh(const State& state, Mesh& out) const {
    const int slices = roundSlicesFor(gatherShapeState(state, nullptr).complexityValue());
    buildSphereMesh(radius(), slices, std::max(3, slices / 2), out);
}

} // namespace volsg
