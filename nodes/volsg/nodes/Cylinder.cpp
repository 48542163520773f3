#include <volsg/geometry/MeshKey.h>
#include <volsg/geometry/PrimitiveMeshes.h>
#include <volsg/nodes/Cylinder.h>
#include <volsg/nodes/PrimitiveComplexity.h>
#include <volsg/nodes/PrimitiveParts.h>

#include <algorithm>
#include <cmath>

namespace volsg {

const EnumValues Cylinder::partNames{
    {"SIDES", SIDES}, {"TOP", TOP}, {"BOTTOM", BOTTOM}, {"ALL", ALL}};

Box3 Cylinder::objectBox() const {
    const double r = std::abs(double(radius())), h = 0.5 * std::abs(double(height()));
    return {glm::dvec3(-r, -h, -r), glm::dvec3(r, h, r)};
}

std::uint64_t Cylinder::meshKey(const State& state) const {
    return combineMeshKey(Shape::meshKey(state),
                          std::uint64_t(roundSlicesFor(primitiveComplexity(state, objectBox()))));
}

void Cylinder::buildMesh(const State& state, Mesh& out) const {
    const int p = parts();
    const int slices = roundSlicesFor(primitiveComplexity(state, objectBox()));
    PartStarts starts;
    buildCylinderMesh(radius(), height(), (p & SIDES) != 0, (p & TOP) != 0, (p & BOTTOM) != 0,
                      slices, out, &starts);
    std::vector<int> built;
    if (p & SIDES) built.push_back(0);
    if (p & TOP) built.push_back(1);
    if (p & BOTTOM) built.push_back(2);
    colorPrimitiveParts(state, starts, built, out);
}

void Cylinder::buildCoarserMeshes(const State& state, std::vector<CoarserMesh>& out) const {
    const int p = parts();
    const int slices = roundSlicesFor(primitiveComplexity(state, objectBox()));
    std::vector<int> built;
    if (p & SIDES) built.push_back(0);
    if (p & TOP) built.push_back(1);
    if (p & BOTTOM) built.push_back(2);
    for (int s : coarserSliceCounts(slices, 4)) {
        if (roundMeshDeviation(1.0f, s) > kCoarsestRelativeDeviation) break;
        CoarserMesh& level = out.emplace_back();
        PartStarts starts;
        buildCylinderMesh(radius(), height(), (p & SIDES) != 0, (p & TOP) != 0, (p & BOTTOM) != 0,
                          s, level.mesh, &starts);
        colorPrimitiveParts(state, starts, built, level.mesh);
        level.deviation = roundMeshDeviation(radius(), s);
    }
}

} // namespace volsg
