#pragma once
// Shading tables: 4096 intensities indexed by a 12-bit gradient code (RTVR section 3.4),
// rebuilt when the view or the light changes.

#include <vector>

#include <glm/glm.hpp>

namespace volsg {

/// Normals are decoded from GradientCode in the volume's local coordinates and taken to eye
/// coordinates by the inverse transpose of `localToEye`; `light` is the direction towards the
/// light and the viewer looks down -z (parallel projection), both in eye coordinates.
/// Lighting is two-sided (|n.l|), as for shapes.
class ShadingTable {
public:
    static constexpr float ambient = 0.15f, diffuse = 0.65f, specular = 0.2f;

    /// ambient + diffuse |n.l| + specular |n.h|^shininess, in [0, 1].
    static std::vector<float> phong(const glm::dmat3& localToEye, const glm::dvec3& light,
                                    float shininess);
    /// Contour intensity (1 - |n.v|)^sharpness: 1 where the surface is seen edge-on.
    static std::vector<float> contour(const glm::dmat3& localToEye, float sharpness);
};

} // namespace volsg
