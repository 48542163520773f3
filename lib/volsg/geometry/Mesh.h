#pragma once
// Triangles or lines with per-vertex normals: what every shape node turns into, for drawing,
// bounding boxes and picking alike.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/math/Box3.h>

namespace volsg {

struct Mesh {
    enum class Primitive { Triangles, Lines };
    Primitive primitive = Primitive::Triangles;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;     ///< one per position (empty for lines)
    std::vector<glm::vec4> colors;      ///< optional, one per position (overrides diffuse)
    std::vector<std::uint32_t> indices; ///< 3 per triangle or 2 per line segment

    Box3 bounds() const {
        Box3 b;
        for (const auto& p : positions)
            b.extendBy(glm::dvec3(p));
        return b;
    }
    std::size_t primitiveCount() const {
        return indices.size() / (primitive == Primitive::Triangles ? 3 : 2);
    }
};

} // namespace volsg
