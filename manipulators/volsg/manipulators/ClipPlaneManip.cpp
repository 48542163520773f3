#include <volsg/manipulators/ClipPlaneManip.h>

#include <volsg/manipulators/DragMath.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/Cylinder.h>
#include <volsg/nodes/Sphere.h>

namespace volsg {

namespace {
glm::dvec3 unitNormal(const Plane& p) {
    const glm::dvec3 n(p.normal);
    const double l = glm::length(n);
    return l > 0.0 ? n / l : glm::dvec3(0.0, 0.0, 1.0);
}
double unitDistance(const Plane& p) {
    const double l = glm::length(glm::dvec3(p.normal));
    return l > 0.0 ? double(p.distance) / l : double(p.distance);
}
constexpr double kArmLength = 0.35; // of the handle size
} // namespace

void ClipPlaneManip::buildHandles(DraggerGeometry& parts) {
    parts.addPart(Cube::create(), glm::vec3(0.3f, 0.6f, 1.0f), 0.65f);
    parts.addPart(Cylinder::create(), glm::vec3(0.9f, 0.9f, 0.9f));
    parts.addPart(Sphere::create(), glm::vec3(1.0f, 0.35f, 0.2f));
}

glm::dvec3 ClipPlaneManip::handleCenter() const {
    const glm::dvec3 n = unitNormal(plane());
    const glm::dvec3 a = localAnchor();
    return a - (glm::dot(n, a) - unitDistance(plane())) * n;
}

void ClipPlaneManip::placeHandles() {
    const double size = localHandleSize();
    const glm::dvec3 n = unitNormal(plane());
    const glm::dvec3 c = handleCenter();
    auto& square = static_cast<Cube&>(handles().shape(Square));
    if (square.width() != float(size)) {
        square.width = float(size);
        square.height = float(size);
        square.depth = float(size * 0.004);
    }
    auto& arm = static_cast<Cylinder&>(handles().shape(Arm));
    if (arm.height() != float(size * kArmLength)) {
        arm.height = float(size * kArmLength);
        arm.radius = float(size * 0.008);
    }
    auto& knob = static_cast<Sphere&>(handles().shape(Knob));
    if (knob.radius() != float(size * 0.035)) knob.radius = float(size * 0.035);
    handles().place(Square, c, rotationBetween({0.0, 0.0, 1.0}, n));
    handles().place(Arm, c + n * (0.5 * size * kArmLength), rotationBetween({0.0, 1.0, 0.0}, n));
    handles().place(Knob, c + n * (size * kArmLength));
}

void ClipPlaneManip::startDrag(int part, const Ray& localRay) {
    startNormal_ = unitNormal(plane());
    startDistance_ = unitDistance(plane());
    startCenter_ = handleCenter();
    if (part == Knob) {
        startGrab_ = trackballPoint(localRay, startCenter_, localHandleSize() * kArmLength);
    } else {
        const auto s = closestLineParameter(localRay, startCenter_, startNormal_);
        lineValid_ = s.has_value();
        startLine_ = s.value_or(0.0);
    }
}

void ClipPlaneManip::continueDrag(int part, const Ray& localRay) {
    if (part == Knob) {
        const glm::dvec3 grab =
            trackballPoint(localRay, startCenter_, localHandleSize() * kArmLength);
        const glm::dvec3 n = glm::normalize(
            rotationBetween(startGrab_ - startCenter_, grab - startCenter_) * startNormal_);
        // Turn about the handle centre: the plane keeps passing through it.
        plane = Plane{glm::vec3(n), float(glm::dot(n, startCenter_))};
        return;
    }
    if (!lineValid_) { // the view was along the normal at the start: try again from here
        startDrag(part, localRay);
        return;
    }
    const auto s = closestLineParameter(localRay, startCenter_, startNormal_);
    if (!s) return;
    plane = Plane{glm::vec3(startNormal_), float(startDistance_ + (*s - startLine_))};
}

} // namespace volsg
