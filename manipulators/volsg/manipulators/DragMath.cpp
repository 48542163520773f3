#include <volsg/manipulators/DragMath.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace volsg {

std::optional<double> intersectRayPlane(const Ray& ray, const glm::dvec3& normal, double distance) {
    const double denom = glm::dot(normal, ray.direction);
    if (std::abs(denom) <= 1e-12 * glm::length(normal) * glm::length(ray.direction))
        return std::nullopt;
    const double t = (distance - glm::dot(normal, ray.origin)) / denom;
    if (!(t >= 0.0)) return std::nullopt;
    return t;
}

std::optional<BoxHit> intersectRayBox(const Ray& ray, const Box3& box) {
    if (box.isEmpty()) return std::nullopt;
    // Slabs: the entry is the largest near-t over the axes, the exit the smallest far-t.
    double tEnter = -std::numeric_limits<double>::infinity();
    double tExit = std::numeric_limits<double>::infinity();
    int enterFace = -1, exitFace = -1;
    for (int axis = 0; axis < 3; ++axis) {
        const double o = ray.origin[axis], d = ray.direction[axis];
        if (d == 0.0) {
            if (o < box.min[axis] || o > box.max[axis]) return std::nullopt;
            continue;
        }
        double tNear = (box.min[axis] - o) / d, tFar = (box.max[axis] - o) / d;
        int nearFace = 2 * axis, farFace = 2 * axis + 1;
        if (tNear > tFar) {
            std::swap(tNear, tFar);
            std::swap(nearFace, farFace);
        }
        if (tNear > tEnter) {
            tEnter = tNear;
            enterFace = nearFace;
        }
        if (tFar < tExit) {
            tExit = tFar;
            exitFace = farFace;
        }
    }
    if (tEnter > tExit || tExit < 0.0) return std::nullopt;
    if (tEnter >= 0.0 && enterFace >= 0) return BoxHit{tEnter, enterFace};
    if (exitFace < 0) return std::nullopt; // a zero direction inside the box: no face
    return BoxHit{tExit, exitFace};
}

std::optional<double> intersectRaySphere(const Ray& ray, const glm::dvec3& center, double radius) {
    const glm::dvec3 oc = ray.origin - center;
    const double a = glm::dot(ray.direction, ray.direction);
    if (a == 0.0) return std::nullopt;
    const double b = glm::dot(oc, ray.direction);
    const double c = glm::dot(oc, oc) - radius * radius;
    const double disc = b * b - a * c;
    if (disc < 0.0) return std::nullopt;
    const double root = std::sqrt(disc);
    const double t0 = (-b - root) / a, t1 = (-b + root) / a;
    if (t0 >= 0.0) return t0;
    if (t1 >= 0.0) return t1;
    return std::nullopt;
}

std::optional<double> closestLineParameter(const Ray& ray, const glm::dvec3& linePoint,
                                           const glm::dvec3& lineDirection) {
    // Minimise |(o + t d) - (p + s u)| over s and t (the closest points of two lines).
    const double lu = glm::length(lineDirection), ld = glm::length(ray.direction);
    if (lu == 0.0 || ld == 0.0) return std::nullopt;
    const glm::dvec3 u = lineDirection / lu, d = ray.direction / ld;
    const glm::dvec3 w = linePoint - ray.origin;
    const double b = glm::dot(u, d);
    const double denom = 1.0 - b * b;
    if (denom < 1e-9) return std::nullopt;
    const double s = (b * glm::dot(w, d) - glm::dot(w, u)) / denom;
    return s / lu; // in units of the given direction
}

glm::dvec3 trackballPoint(const Ray& ray, const glm::dvec3& center, double radius) {
    const glm::dvec3 d = glm::normalize(ray.direction);
    const glm::dvec3 oc = center - ray.origin;
    const double along = glm::dot(oc, d);
    const glm::dvec3 nearest = ray.origin + along * d; // point of the ray line nearest the centre
    const glm::dvec3 off = nearest - center;
    const double dist2 = glm::dot(off, off);
    if (dist2 <= radius * radius) {
        const double back = std::sqrt(radius * radius - dist2);
        return nearest - back * d; // the near side
    }
    return center + off * (radius / std::sqrt(dist2));
}

glm::dquat rotationBetween(const glm::dvec3& from, const glm::dvec3& to) {
    const double lf = glm::length(from), lt = glm::length(to);
    if (lf == 0.0 || lt == 0.0) return glm::dquat(1.0, 0.0, 0.0, 0.0);
    const glm::dvec3 a = from / lf, b = to / lt;
    const double c = glm::dot(a, b);
    if (c < -1.0 + 1e-12) {
        glm::dvec3 axis = glm::cross(a, glm::dvec3(1.0, 0.0, 0.0));
        if (glm::length(axis) < 1e-6) axis = glm::cross(a, glm::dvec3(0.0, 1.0, 0.0));
        return glm::angleAxis(glm::pi<double>(), glm::normalize(axis));
    }
    // Half-angle form: q = (1 + c, a x b), normalised.
    const glm::dvec3 axis = glm::cross(a, b);
    return glm::normalize(glm::dquat(1.0 + c, axis.x, axis.y, axis.z));
}

Rotation rotationFromQuat(const glm::dquat& q) {
    glm::dquat n = glm::normalize(q);
    if (n.w < 0.0) n = -n;
    const double s = std::sqrt(std::max(0.0, 1.0 - n.w * n.w));
    if (s < 1e-12) return Rotation{};
    return Rotation{glm::vec3(float(n.x / s), float(n.y / s), float(n.z / s)),
                    float(2.0 * std::acos(std::clamp(n.w, -1.0, 1.0)))};
}

} // namespace volsg
