#include <volsg/geometry/Mesh.h>
#include <volsg/render/VertexLighting.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace volsg {

namespace {

constexpr double kInfinite = std::numeric_limits<double>::infinity();

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
    // atan2 of |a x b| and a.b: accurate for small angles, where acos is not.
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

double largestStep(const glm::vec4& a, const glm::vec4& b) {
    const glm::vec4 d = glm::abs(a - b);
    return double(std::max({d.r, d.g, d.b}));
}

double maxChannel(const glm::vec3& c) {
    return double(std::max({c.r, c.g, c.b, 0.0f}));
}

} // namespace

ShadingSpread measureShadingSpread(const Mesh& mesh) {
    ShadingSpread out;
    const std::size_t n = mesh.positions.size();
    if (mesh.normals.size() != n) {
        out.normal = std::numeric_limits<float>::infinity();
        return out;
    }
    for (const glm::vec3& v : mesh.normals)
        if (!(glm::dot(v, v) > 0.0f) || !std::isfinite(glm::dot(v, v))) {
            out.normal = std::numeric_limits<float>::infinity();
            return out;
        }
    const bool colors = mesh.colors.size() == n;
    const std::size_t k = mesh.verticesPerPrimitive();
    double weights = 0.0, normal4 = 0.0, colorNormal2 = 0.0, color2 = 0.0, longest = 0.0;
    for (std::size_t p = 0; p + k <= mesh.indices.size(); p += k) {
        const std::uint32_t* v = &mesh.indices[p];
        if (std::any_of(v, v + k, [n](std::uint32_t i) { return i >= n; })) continue;
        double angle = 0.0, step = 0.0, edge = 0.0;
        for (std::size_t a = 0; a < k; ++a)
            for (std::size_t b = a + 1; b < k; ++b) {
                angle = std::max(angle, angleBetween(mesh.normals[v[a]], mesh.normals[v[b]]));
                edge = std::max(edge,
                                double(glm::distance(mesh.positions[v[a]], mesh.positions[v[b]])));
                if (colors)
                    step = std::max(step, largestStep(mesh.colors[v[a]], mesh.colors[v[b]]));
            }
        double weight = 1.0;
        if (k == 3) {
            const glm::dvec3 p0(mesh.positions[v[0]]), p1(mesh.positions[v[1]]),
                p2(mesh.positions[v[2]]);
            weight = 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
        } else if (k == 2) {
            weight = edge;
        }
        if (!std::isfinite(weight) || !std::isfinite(edge)) {
            out.normal = std::numeric_limits<float>::infinity();
            return out;
        }
        weights += weight;
        normal4 += weight * angle * angle * angle * angle;
        colorNormal2 += weight * (step * angle) * (step * angle);
        color2 += weight * step * step;
        longest = std::max(longest, edge);
    }
    if (weights > 0.0) {
        out.normal = float(std::pow(normal4 / weights, 0.25));
        out.colorTimesNormal = float(std::sqrt(colorNormal2 / weights));
        out.color = float(std::sqrt(color2 / weights));
    }
    out.longestEdge = float(longest);
    return out;
}

double predictVertexLightingError(const VertexLightingCase& c) {
    if (!std::isfinite(c.spread.normal) || c.bounds.isEmpty()) return kInfinite;
    // The model's largest and smallest stretch (its columns; exact for axis-aligned scales):
    // an uneven scale bends normals apart by up to their ratio.
    const glm::dmat3 m(c.model);
    const double s0 = glm::length(m[0]), s1 = glm::length(m[1]), s2 = glm::length(m[2]);
    const double largest = std::max({s0, s1, s2}), smallest = std::min({s0, s1, s2});
    if (!(smallest > 0.0) || !std::isfinite(largest)) return kInfinite;
    const double normalAngle = double(c.spread.normal) * (largest / smallest);
    const double edge = double(c.spread.longestEdge) * largest;
    const glm::dvec3 centre = glm::dvec3(c.model * glm::dvec4(c.bounds.center(), 1.0));
    const double radius = 0.5 * glm::length(c.bounds.size()) * largest;
    // The nearest a point comes to the bounds (<= 0 inside them), and how far the direction
    // to it turns across the longest edge from there (all the way from inside).
    const auto distanceTo = [&](const glm::dvec3& point) {
        return glm::distance(point, centre) - radius;
    };
    const auto turnAt = [edge](double distance) {
        return distance > 0.0 ? edge / distance : kInfinite;
    };
    const double viewAngle = c.viewer.w != 0.0 ? turnAt(distanceTo(glm::dvec3(c.viewer))) : 0.0;

    const glm::dvec3 att(c.attenuation);
    const double diffuse = c.vertexColors ? 1.0 : maxChannel(c.diffuse);
    const double specular = maxChannel(c.specular);
    const double power = std::max(double(c.shininess), 1.0);
    double error = 0.0;
    for (const SceneLight& l : c.lights) {
        if (l.vector.w != 0.0f && l.spotCosCutOff >= -1.0f) return kInfinite; // a cone's edge
        double strength = 1.0, lightAngle = 0.0;
        if (l.vector.w != 0.0f) {
            const double distance = distanceTo(glm::dvec3(l.vector));
            lightAngle = turnAt(distance);
            if (!std::isfinite(lightAngle)) return kInfinite;
            if (att.x < 0.0 || att.y < 0.0 || att.z < 0.0) return kInfinite;
            // Nonnegative coefficients: the strength 1/a is largest at the nearest point.
            const double a = att.z + att.y * distance + att.x * distance * distance;
            if (a > 0.0) {
                strength = 1.0 / a;
                // And it bends along an edge: (1/a)'' = (2 a'^2 - a a'') / a^3.
                const double slope = att.y + 2.0 * att.x * distance;
                const double bend = std::abs(2.0 * slope * slope - a * 2.0 * att.x) / (a * a * a);
                error += maxChannel(l.color) * bend * edge * edge / 11.0 * (diffuse + specular);
            }
        }
        const double diffuseAngle = normalAngle + lightAngle;
        const double halfAngle = normalAngle + 0.5 * (viewAngle + lightAngle);
        const double term =
            diffuse * diffuseAngle * diffuseAngle / 11.0 +
            (double(c.spread.colorTimesNormal) + double(c.spread.color) * lightAngle) / 5.5 +
            specular * std::min(1.0, power * halfAngle * halfAngle / 11.0);
        error += maxChannel(l.color) * strength * term;
    }
    return std::isfinite(error) ? error : kInfinite;
}

} // namespace volsg
