#include <volsg/shearwarp/ShadingTable.h>

#include <algorithm>
#include <cmath>

#include <volsg/shearwarp/GradientCode.h>

namespace volsg {

namespace {

template <class F> std::vector<float> tabulate(const glm::dmat3& localToEye, F intensity) {
    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(localToEye));
    std::vector<float> table(GradientCode::count);
    for (int code = 0; code < GradientCode::count; ++code) {
        const glm::dvec3 n =
            glm::normalize(normalMatrix * glm::dvec3(GradientCode::decode(std::uint16_t(code))));
        table[std::size_t(code)] = float(std::clamp(intensity(n), 0.0, 1.0));
    }
    return table;
}

} // namespace

std::vector<float> ShadingTable::phong(const glm::dmat3& localToEye, const glm::dvec3& light,
                                       float shininess) {
    const glm::dvec3 l = glm::normalize(light);
    const glm::dvec3 h = glm::normalize(l + glm::dvec3(0.0, 0.0, 1.0));
    return tabulate(localToEye, [&](const glm::dvec3& n) {
        return ambient + diffuse * std::abs(glm::dot(n, l)) +
               specular * std::pow(std::abs(glm::dot(n, h)), double(shininess));
    });
}

std::vector<float> ShadingTable::contour(const glm::dmat3& localToEye, float sharpness) {
    return tabulate(localToEye, [&](const glm::dvec3& n) {
        return std::pow(1.0 - std::abs(n.z), double(sharpness));
    });
}

} // namespace volsg
