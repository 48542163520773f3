#include <volsg/nodes/PrimitiveParts.h>

#include <volsg/nodes/ShapeState.h>

namespace volsg {

void colorPrimitiveParts(const State& state, const PartStarts& starts,
                         const std::vector<int>& allParts, Mesh& mesh) {
    const ShapeState shape = gatherShapeState(state, nullptr);
    VertexArrays storage;
    const VertexAttributes a = vertexAttributes(shape, storage);
    if (a.materialBinding == Binding::Overall || a.colors.empty()) return;
    mesh.colors.resize(mesh.positions.size());
    for (std::size_t p = 0; p < starts.size(); ++p) {
        const std::size_t end = p + 1 < starts.size() ? starts[p + 1] : mesh.positions.size();
        const std::size_t material = std::min(std::size_t(allParts[p]), a.colors.size() - 1);
        for (std::size_t v = starts[p]; v < end; ++v)
            mesh.colors[v] = a.colors[material];
    }
}

} // namespace volsg
