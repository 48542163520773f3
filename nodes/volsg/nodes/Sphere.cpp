#include <volsg/geometry/MeshKey.h>
#include <volsg/geometry/PrimitiveMeshes.h>
#include <volsg/nodes/PrimitiveComplexity.h>
#include <volsg/nodes/Sphere.h>

#include <algorithm>
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

void Sphere::buildCoarserMeshes(const State& state, std::vector<CoarserMesh>& out) const {
    const float c = primitiveComplexity(state, objectBox());
    const int slices = sphereSlicesFor(c), stacks = sphereStacksFor(c);
    // Half as many bands as sides balances the two terms of the deviation: the first level
    // keeps the sides and halves Coin's bands, the next ones have fewer sides too.
    std::vector<int> sides = coarserSliceCounts(slices, 4);
    if ((slices + 1) / 2 < stacks) sides.insert(sides.begin(), slices);
    for (int s : sides) {
        const int bands = std::clamp((s + 1) / 2, 2, stacks);
        if (sphereMeshDeviation(1.0f, s, bands) > kCoarsestRelativeDeviation) break;
        CoarserMesh& level = out.emplace_back();
        buildSphereMesh(radius(), s, bands, level.mesh);
        level.deviation = sphereMeshDeviation(radius(), s, bands);
    }
}

} // namespace volsg
