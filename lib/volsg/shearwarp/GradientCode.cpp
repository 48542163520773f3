#include <volsg/shearwarp/GradientCode.h>

#include <algorithm>
#include <cmath>

namespace volsg {

namespace {

float signNotZero(float v) {
    return v < 0.0f ? -1.0f : 1.0f;
}

} // namespace

std::uint16_t GradientCode::encode(const glm::vec3& d) {
    const float l1 = std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
    if (!(l1 > 0.0f)) return encode(glm::vec3(0.0f, 0.0f, 1.0f));
    glm::vec2 p(d.x / l1, d.y / l1);
    if (d.z < 0.0f) // fold the lower hemisphere over the diagonals
        p = glm::vec2((1.0f - std::abs(p.y)) * signNotZero(p.x),
                      (1.0f - std::abs(p.x)) * signNotZero(p.y));
    const int u = std::clamp(int((p.x * 0.5f + 0.5f) * side), 0, side - 1);
    const int v = std::clamp(int((p.y * 0.5f + 0.5f) * side), 0, side - 1);
    return std::uint16_t(u + side * v);
}

glm::vec3 GradientCode::decode(std::uint16_t code) {
    const float u = (float(code % side) + 0.5f) / float(side) * 2.0f - 1.0f;
    const float v = (float((code / side) % side) + 0.5f) / float(side) * 2.0f - 1.0f;
    glm::vec3 n(u, v, 1.0f - std::abs(u) - std::abs(v));
    if (n.z < 0.0f) {
        const float x = n.x;
        n.x = (1.0f - std::abs(n.y)) * signNotZero(x);
        n.y = (1.0f - std::abs(x)) * signNotZero(n.y);
    }
    return glm::normalize(n);
}

} // namespace volsg
