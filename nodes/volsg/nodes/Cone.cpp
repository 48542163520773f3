#include <volsg/geometry/MeshKey.h>
#include <volsg/geometry/PrimitiveMeshes.h>
#include <volsg/nodes/Cone.h>
#include <volsg/nodes/PrimitiveComplexity.h>
#include <volsg/nodes/PrimitiveParts.h>

#include <algorithm>
#include <cmath>

namespace volsg {

const EnumValues Cone::partNames{{"SIDES", SIDES}, {"BOTTOM", BOTTOM}, {"ALL", ALL}};

Box3 Cone::objectBox() const {
    const double r = std::abs(double(bottomRadius())), h = 0.5 * std::abs(double(height()));
    return {glm::dvec3(-r, -h, -r), glm::dvec3(r, h, r)};
}

std::uint64_t Cone::meshKey(const State& state) const {
    return combineMeshKey(Shape::meshKey(state),
                          std::uint64_t(roundSlicesFor(primitiveComplexity(state, objectBox()))));
}

void Cone::buildMesh(const State& state, Mesh& out) const {
    const int p = parts();
    const int slices = roundSlicesFor(primitiveComplexity(state, objectBox()));
    PartStarts starts;
    buildConeMesh(bottomRadius(), height(), (p & SIDES) != 0, (p & BOTTOM) != 0, slices, out,
                  &starts);
    std::vector<int> built;
    if (p & SIDES) built.push_back(0);
    if (p & BOTTOM) built.push_back(1);
    colorPrimitiveParts(state, starts, built, out);
}

void Cone::buildCoarserMeshes(const State& state, std::vector<CoarserMesh>& out) const {
    const int p = parts();
    const int slices = roundSlicesFor(primitiveComplexity(state, objectBox()));
    std::vector<int> built;
    if (p & SIDES) built.push_back(0);
    if (p & BOTTOM) built.push_back(1);
    for (int s : coarserSliceCounts(slices, 4)) {
        if (roundMeshDeviation(1.0f, s) > kCoarsestRelativeDeviation) break;
        CoarserMesh& level = out.emplace_back();
        PartStarts starts;
        buildConeMesh(bottomRadius(), height(), (p & SIDES) != 0, (p & BOTTOM) != 0, s, level.mesh,
                      &starts);
        colorPrimitiveParts(state, starts, built, level.mesh);
        level.deviation = roundMeshDeviation(bottomRadius(), s);
    }
}

} // namespace volsg
