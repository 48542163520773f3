#include <volsg/geometry/PrimitiveMeshes.h>
#include <volsg/nodes/Cube.h>

namespace volsg {

void Cube::buildMesh(const State&, Mesh& out) const {
    buildBoxMesh(glm::vec3(width(), height(), depth()), out);
}

} // namespace volsg
