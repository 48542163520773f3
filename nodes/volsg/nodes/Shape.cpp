// Everything shapes share: the cached mesh, its bounding box and ray picking against it.
// (Shape::render lives with the renderer in lib/volsg/render/.)
#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/actions/PickAction.h>
#include <volsg/geometry/RayIntersect.h>
#include <volsg/nodes/Shape.h>

#include <cmath>

namespace volsg {

const Mesh& Shape::mesh(const State& state) const {
    const std::uint64_t key = meshKey(state);
    if (!meshValid_ || key != meshKey_) {
        meshValid_ = false; // stays invalid if building throws
        buildMesh(state, mesh_);
        meshKey_ = key;
        meshValid_ = true;
    }
    return mesh_;
}

std::uint64_t Shape::meshKey(const State&) const {
    return version();
}

void Shape::getBoundingBox(BoundingBoxAction& action) {
    action.extendByLocal(mesh(action.state()).bounds());
}

// Triangles only: lines have no area, and a pick radius would have to be in pixels to feel
// right, which a world-space ray does not know. So IndexedLineSet is not pickable.
void Shape::pick(PickAction& action) {
    const Mesh& m = mesh(action.state());
    if (m.primitive != Mesh::Primitive::Triangles || m.indices.size() < 3) return;
    const glm::dmat4& model = action.state().modelMatrix();
    const double det = glm::determinant(model);
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return; // flattened: nothing to hit
    // Ray::transformed keeps t, so t stays the world distance along the (unit) world ray.
    const Ray local = action.worldRay().transformed(glm::inverse(model));
    const bool smooth = m.normals.size() == m.positions.size();
    const std::size_t triangles = m.indices.size() / 3;
    for (std::size_t i = 0; i < triangles; ++i) {
        const std::uint32_t ia = m.indices[3 * i], ib = m.indices[3 * i + 1],
                            ic = m.indices[3 * i + 2];
        if (ia >= m.positions.size() || ib >= m.positions.size() || ic >= m.positions.size())
            continue;
        const glm::dvec3 a(m.positions[ia]), b(m.positions[ib]), c(m.positions[ic]);
        const auto hit = intersectTriangle(local, a, b, c);
        if (!hit) continue;
        glm::dvec3 normal(0.0);
        if (smooth)
            normal = (1.0 - hit->u - hit->v) * glm::dvec3(m.normals[ia]) +
                     hit->u * glm::dvec3(m.normals[ib]) + hit->v * glm::dvec3(m.normals[ic]);
        if (!(glm::length(normal) > 0.0)) normal = glm::cross(b - a, c - a);
        const glm::dvec3 point = (1.0 - hit->u - hit->v) * a + hit->u * b + hit->v * c;
        action.addLocalHit(point, glm::normalize(normal), i);
    }
}

} // namespace volsg
