#include <volsg/fields/Values.h>

namespace volsg {

glm::dquat Rotation::quat() const {
    const glm::dvec3 a(axis);
    const double len = glm::length(a);
    if (len == 0.0 || !(len == len)) return glm::dquat(1.0, 0.0, 0.0, 0.0);
    return glm::angleAxis(double(angle), a / len);
}

glm::dmat4 Rotation::matrix() const {
    return glm::mat4_cast(quat());
}

} // namespace volsg
