#pragma once
// A ray: origin + t * direction, t >= 0.

#include <glm/glm.hpp>

namespace volsg {

struct Ray {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, -1.0}; ///< not necessarily unit length after a transform

    glm::dvec3 at(double t) const { return origin + t * direction; }
    /// The same ray in the coordinates that `m` maps to (t values are preserved).
    Ray transformed(const glm::dmat4& m) const {
        return {glm::dvec3(m * glm::dvec4(origin, 1.0)),
                glm::dvec3(m * glm::dvec4(direction, 0.0))};
    }
};

} // namespace volsg
