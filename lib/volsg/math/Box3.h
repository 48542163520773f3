#pragma once
// Axis-aligned box in double precision; empty until a point is added.

#include <limits>

#include <glm/glm.hpp>

namespace volsg {

struct Box3 {
    glm::dvec3 min{std::numeric_limits<double>::infinity()};
    glm::dvec3 max{-std::numeric_limits<double>::infinity()};

    bool isEmpty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    glm::dvec3 center() const { return (min + max) * 0.5; }
    glm::dvec3 size() const { return isEmpty() ? glm::dvec3(0.0) : max - min; }
    void extendBy(const glm::dvec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extendBy(const Box3& b) {
        if (b.isEmpty()) return;
        extendBy(b.min);
        extendBy(b.max);
    }
    /// The box of `b`'s eight corners transformed by `m`.
    void extendBy(const Box3& b, const glm::dmat4& m) {
        if (b.isEmpty()) return;
        for (int i = 0; i < 8; ++i) {
            glm::dvec3 c((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                         (i & 4) ? b.max.z : b.min.z);
            extendBy(glm::dvec3(m * glm::dvec4(c, 1.0)));
        }
    }
    bool contains(const glm::dvec3& p) const {
        return p.x >= min.x && p.y >= min.y && p.z >= min.z && p.x <= max.x && p.y <= max.y &&
               p.z <= max.z;
    }
};

} // namespace volsg
