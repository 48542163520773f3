#include <volsg/geometry/IndexedMeshes.h>
#include <volsg/geometry/MeshKey.h>
#include <volsg/nodes/Coordinate3.h>
#include <volsg/nodes/IndexedLineSet.h>
#include <volsg/state/State.h>

#include <span>

namespace volsg {

void IndexedLineSet::buildMesh(const State& state, Mesh& out) const {
    const Coordinate3* coords = state.nearestNode<Coordinate3>();
    std::span<const glm::vec3> points;
    if (coords) points = coords->point.getValues();
    buildLineSetMesh(points, coordIndex.getValues(), out);
}

std::uint64_t IndexedLineSet::meshKey(const State& state) const {
    const Coordinate3* coords = state.nearestNode<Coordinate3>();
    std::uint64_t key = combineMeshKey(version(), reinterpret_cast<std::uintptr_t>(coords));
    return combineMeshKey(key, coords ? coords->version() : 0);
}

} // namespace volsg
