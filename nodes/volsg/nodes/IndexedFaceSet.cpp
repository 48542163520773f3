#include <volsg/geometry/IndexedMeshes.h>
#include <volsg/geometry/MeshKey.h>
#include <volsg/nodes/Coordinate3.h>
#include <volsg/nodes/IndexedFaceSet.h>
#include <volsg/nodes/Normal.h>
#include <volsg/state/State.h>

#include <span>

namespace volsg {

void IndexedFaceSet::buildMesh(const State& state, Mesh& out) const {
    // Without a Coordinate3 in scope there are no points, so every polygon is skipped.
    const Coordinate3* coords = state.nearestNode<Coordinate3>();
    const Normal* normals = state.nearestNode<Normal>();
    std::span<const glm::vec3> points, vectors;
    if (coords) points = coords->point.getValues();
    if (normals) vectors = normals->vector.getValues();
    buildFaceSetMesh(points, coordIndex.getValues(), vectors, normalIndex.getValues(), out);
}

std::uint64_t IndexedFaceSet::meshKey(const State& state) const {
    // Which Coordinate3/Normal is in scope (address) and what it holds (version).
    std::uint64_t key = version();
    for (const Node* n : {static_cast<const Node*>(state.nearestNode<Coordinate3>()),
                          static_cast<const Node*>(state.nearestNode<Normal>())}) {
        key = combineMeshKey(key, reinterpret_cast<std::uintptr_t>(n));
        key = combineMeshKey(key, n ? n->version() : 0);
    }
    return key;
}

} // namespace volsg
