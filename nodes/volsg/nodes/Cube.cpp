#include <volsg/geometry/PrimitiveMeshes.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/PrimitiveParts.h>
#include <volsg/nodes/ShapeState.h>

namespace volsg {

void Cube::buildMesh(const State& state, Mesh& out) const {
    PartStarts faces;
    buildBoxMesh(glm::vec3(width(), height(), depth()), out, &faces);
    colorPrimitiveParts(state, faces, {0, 1, 2, 3, 4, 5}, out);
}

} // namespace volsg
