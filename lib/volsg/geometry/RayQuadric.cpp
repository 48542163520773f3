#include <volsg/geometry/RayQuadric.h>

#include <algorithm>
#include <cmath>

namespace volsg {

namespace {

/// The real roots of a t^2 + b t + c = 0 (a != 0), in the numerically stable form.
std::vector<double> quadraticRoots(double a, double b, double c) {
    if (!(a != 0.0) || !std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c)) return {};
    const double discriminant = b * b - 4.0 * a * c;
    if (!(discriminant >= 0.0)) return {};
    const double root = std::sqrt(discriminant);
    const double q = -0.5 * (b + std::copysign(root, b));
    if (q == 0.0) return {0.0};
    const double t0 = q / a, t1 = c / q;
    if (t0 == t1) return {t0};
    return {std::min(t0, t1), std::max(t0, t1)};
}

bool usable(double radius, double height) {
    return radius > 0.0 && height > 0.0 && std::isfinite(radius) && std::isfinite(height);
}

} // namespace

std::vector<QuadricHit> intersectSphere(const Ray& ray, double radius) {
    std::vector<QuadricHit> hits;
    if (!(radius > 0.0) || !std::isfinite(radius)) return hits;
    const glm::dvec3 &o = ray.origin, &d = ray.direction;
    for (const double t :
         quadraticRoots(glm::dot(d, d), 2.0 * glm::dot(o, d), glm::dot(o, o) - radius * radius)) {
        const glm::dvec3 p = ray.at(t);
        hits.push_back({t, p, p / radius});
    }
    return hits;
}

std::vector<QuadricHit> intersectCylinderSide(const Ray& ray, double radius, double height) {
    std::vector<QuadricHit> hits;
    if (!usable(radius, height)) return hits;
    const glm::dvec3 &o = ray.origin, &d = ray.direction;
    const double a = d.x * d.x + d.z * d.z, b = 2.0 * (o.x * d.x + o.z * d.z),
                 c = o.x * o.x + o.z * o.z - radius * radius;
    for (const double t : quadraticRoots(a, b, c)) {
        const glm::dvec3 p = ray.at(t);
        if (std::abs(p.y) > 0.5 * height) continue;
        hits.push_back({t, p, glm::dvec3(p.x, 0.0, p.z) / radius});
    }
    return hits;
}

std::vector<QuadricHit> intersectDisc(const Ray& ray, double radius, double y, double normalY) {
    if (!(radius > 0.0) || !std::isfinite(radius) || !(ray.direction.y != 0.0)) return {};
    const double t = (y - ray.origin.y) / ray.direction.y;
    glm::dvec3 p = ray.at(t);
    p.y = y; // exactly in the plane
    if (!std::isfinite(t) || !(p.x * p.x + p.z * p.z <= radius * radius)) return {};
    return {{t, p, glm::dvec3(0.0, normalY, 0.0)}};
}

std::vector<QuadricHit> intersectConeSide(const Ray& ray, double bottomRadius, double height) {
    std::vector<QuadricHit> hits;
    if (!usable(bottomRadius, height)) return hits;
    // x^2 + z^2 = k^2 (apex - y)^2 with k = bottomRadius / height; with the apex as origin.
    const double k = bottomRadius / height, k2 = k * k, apex = 0.5 * height;
    const glm::dvec3 o(ray.origin.x, ray.origin.y - apex, ray.origin.z), &d = ray.direction;
    const double a = d.x * d.x + d.z * d.z - k2 * d.y * d.y;
    const double b = 2.0 * (o.x * d.x + o.z * d.z - k2 * o.y * d.y);
    const double c = o.x * o.x + o.z * o.z - k2 * o.y * o.y;
    for (const double t : quadraticRoots(a, b, c)) {
        const glm::dvec3 p = ray.at(t);
        if (p.y > apex || p.y < -apex) continue; // the mirrored cone above the apex, or below
        const double r = std::sqrt(p.x * p.x + p.z * p.z);
        // The gradient of x^2 + z^2 - k^2 (apex - y)^2, with k (apex - y) = r.
        glm::dvec3 n(p.x, k * r, p.z);
        const double length = glm::length(n);
        n = length > 0.0 ? n / length : glm::dvec3(0.0, 1.0, 0.0); // the apex itself
        hits.push_back({t, p, n});
    }
    return hits;
}

} // namespace volsg
