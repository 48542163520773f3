#pragma once
// Four floats in one SSE/NEON register (GCC/Clang vector extension, no -march needed): the
// same IEEE operations per component as glm::vec4's, done at once, so images stay bit for bit.

#include <cstring>

#include <glm/glm.hpp>

namespace volsg::lanes {

using V4 = float __attribute__((vector_size(16)));

inline V4 loadV4(const glm::vec4& v) {
    V4 r;
    std::memcpy(&r, &v, sizeof r);
    return r;
}
inline void storeV4(glm::vec4& d, V4 v) {
    std::memcpy(&d, &v, sizeof v);
}
inline glm::vec4 toVec4(V4 v) {
    return glm::vec4(v[0], v[1], v[2], v[3]);
}

} // namespace volsg::lanes
