#include <volsg/geometry/PrimitiveMeshes.h>
#include <volsg/nodes/Sphere.h>

namespace volsg {

void Sphere::buildMesh(const State&, Mesh& out) const {
    buildSphereMesh(radius(), kRoundSlices, kSphereStacks, out);
}

} // namespace volsg
