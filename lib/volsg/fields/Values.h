#pragma once
// Value types of fields that GLM does not provide directly.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace volsg {

/// Rotation by `angle` radians about `axis`, stored as written so files round-trip exactly.
struct Rotation {
    glm::vec3 axis{0.0f, 0.0f, 1.0f};
    float angle = 0.0f;

    glm::dquat quat() const; ///< unit quaternion (identity for a zero axis)
    glm::dmat4 matrix() const;
    bool operator==(const Rotation&) const = default;
};

/// Plane `normal . p = distance` (Inventor's SbPlane: a b c d).
struct Plane {
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    float distance = 0.0f;
    bool operator==(const Plane&) const = default;
};

/// An SFImage value: width x height pixels of 0 to 4 byte components each, rows bottom to
/// top (Inventor's layout). Empty is 0 0 0.
struct ImageValue {
    int width = 0;
    int height = 0;
    int components = 0;
    std::vector<std::uint8_t> pixels; ///< width * height * components bytes
    bool empty() const { return width <= 0 || height <= 0 || components <= 0; }
    bool operator==(const ImageValue&) const = default;
};

} // namespace volsg
