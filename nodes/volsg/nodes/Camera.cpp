#include <volsg/nodes/Camera.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace volsg {

const EnumValues Camera::viewportMappingNames{
    {"CROP_VIEWPORT_FILL_FRAME", CROP_VIEWPORT_FILL_FRAME},
    {"CROP_VIEWPORT_LINE_FRAME", CROP_VIEWPORT_LINE_FRAME},
    {"CROP_VIEWPORT_NO_FRAME", CROP_VIEWPORT_NO_FRAME},
    {"ADJUST_CAMERA", ADJUST_CAMERA},
    {"LEAVE_ALONE", LEAVE_ALONE}};

glm::dmat4 Camera::viewMatrix(const glm::dmat4& model) const {
    const glm::dmat4 cameraToWorld =
        model * glm::translate(glm::dmat4(1.0), glm::dvec3(position())) * orientation().matrix();
    return glm::inverse(cameraToWorld);
}

namespace {
// Inventor's ADJUST_CAMERA: a viewport narrower than it is tall widens the view vertically so
// the camera's height still fits across.
double adjustedHalfHeight(double halfHeight, double aspect) {
    return aspect < 1.0 ? halfHeight / aspect : halfHeight;
}
double sphereRadius(const Box3& box) {
    return std::max(glm::length(box.size()) * 0.5, 1e-6);
}
glm::dvec3 backwards(const Rotation& r) {
    return glm::dvec3(r.matrix() * glm::dvec4(0, 0, 1, 0));
}
} // namespace

glm::dmat4 PerspectiveCamera::projectionMatrix(double aspect) const {
    const double n = nearDistance(), f = farDistance();
    const double halfH = adjustedHalfHeight(n * std::tan(0.5 * double(heightAngle())), aspect);
    const double halfW = halfH * aspect;
    return glm::frustum(-halfW, halfW, -halfH, halfH, n, f);
}

void PerspectiveCamera::viewAll(const Box3& box, double /*aspect*/) {
    if (box.isEmpty()) return;
    const double r = sphereRadius(box);
    // ADJUST_CAMERA keeps heightAngle across the narrower side, so it bounds the sphere.
    const double half = 0.5 * double(heightAngle());
    const double distance = r / std::sin(half);
    position = glm::vec3(box.center() + backwards(orientation()) * distance);
    nearDistance = float(std::max(distance - r, distance * 1e-3));
    farDistance = float(distance + r);
    focalDistance = float(distance);
}

glm::dmat4 OrthographicCamera::projectionMatrix(double aspect) const {
    const double halfH = adjustedHalfHeight(0.5 * double(height()), aspect);
    const double halfW = halfH * aspect;
    return glm::ortho(-halfW, halfW, -halfH, halfH, double(nearDistance()), double(farDistance()));
}

void OrthographicCamera::viewAll(const Box3& box, double /*aspect*/) {
    if (box.isEmpty()) return;
    const double r = sphereRadius(box);
    const double distance = 2.0 * r;
    position = glm::vec3(box.center() + backwards(orientation()) * distance);
    height = float(2.0 * r); // across the narrower side, as ADJUST_CAMERA maps it
    nearDistance = float(distance - r);
    farDistance = float(distance + r);
    focalDistance = float(distance);
}

} // namespace volsg
