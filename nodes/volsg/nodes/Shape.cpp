// Everything shapes share: the mesh, built from the fields and state, cached by its key.
#include <volsg/geometry/MeshKey.h>
#include <volsg/nodes/Shape.h>
#include <volsg/nodes/ShapeState.h>

namespace volsg {

const Mesh& Shape::mesh(const State& state) const {
    const std::uint64_t key = meshKey(state);
    if (!meshValid_ || key != meshKey_) {
        meshValid_ = false; // stays invalid if building throws
        buildMesh(state, mesh_);
        meshBounds_ = mesh_.bounds();
        meshKey_ = key;
        meshValid_ = true;
    }
    return mesh_;
}

const Box3& Shape::meshBounds(const State& state) const {
    (void)mesh(state);
    return meshBounds_;
}

std::uint64_t Shape::meshKey(const State& state) const {
    return combineMeshKey(version(), gatherShapeState(state, nullptr).meshKey());
}

void Shape::buildCoarserMeshes(const State&, std::vector<CoarserMesh>&) const {}

} // namespace volsg
