#include <volsg/geometry/MeshKey.h>
#include <volsg/geometry/PrimitiveMeshes.h>
#include <volsg/nodes/PrimitiveComplexity.h>
#include <volsg/nodes/Sphere.h>

#include <cmath>

namespace volsg {

Box3 Sphere::objectBox() const {
    const double r = std::abs(double(radius()));
    return {glm::dvec3(-r), glm::dvec3(r)};
}

std::uint64_t Sphere::meshKey(const State& state) const {
    const float c = primitiveComplexity(state, objectBox());
    return combineMeshKey(Shape::meshKey(state), std::uint64_t(sphereSlicesFor(c)) << 32 |
                                                     std::uint64_t(sphereStacksFor(c)));
}

void Sphere::buildMesh(const State& state, Mesh& out) const {
    const float c = primitiveComplexity(state, objectBox());
    buildSphereMesh(radius(), sphereSlicesFor(c), sphereStacksFor(c), out);
}

} // namespace volsg
