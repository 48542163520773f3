#include <volsg/nodes/Camera.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include <volsg/core/Error.h>

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

std::string Camera::problem() const {
    const glm::vec3 p = position();
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        return "position is not finite";
    const Rotation& r = orientation();
    if (!std::isfinite(r.angle) || !std::isfinite(r.axis.x) || !std::isfinite(r.axis.y) ||
        !std::isfinite(r.axis.z))
        return "orientation is not finite";
    if (!std::isfinite(nearDistance()) || !std::isfinite(farDistance()))
        return "nearDistance and farDistance must be finite";
    if (!(farDistance() > nearDistance()))
        return "farDistance (" + std::to_string(farDistance()) + ") must be beyond nearDistance (" +
               std::to_string(nearDistance()) + ")";
    return {};
}

std::string PerspectiveCamera::problem() const {
    if (!(nearDistance() > 0.0f)) return "a PerspectiveCamera needs nearDistance > 0";
    if (!(heightAngle() > 0.0f && heightAngle() < 3.14159265f))
        return "a PerspectiveCamera needs heightAngle in (0, pi)";
    return Camera::problem();
}

std::string OrthographicCamera::problem() const {
    if (!(height() > 0.0f) || !std::isfinite(height()))
        return "an OrthographicCamera needs a finite height > 0";
    return Camera::problem();
}

void Camera::check(const glm::dmat4& model) const {
    std::string problem = this->problem();
    if (problem.empty()) {
        const double det = glm::determinant(glm::dmat3(model));
        bool finite = std::isfinite(det);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                finite = finite && std::isfinite(model[c][r]);
        if (!finite || det == 0.0)
            problem = "the transform above the camera is singular or not finite";
    }
    if (problem.empty()) {
        const glm::dmat4 view = viewMatrix(model), projection = projectionMatrix(1.0);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(view[c][r]) || !std::isfinite(projection[c][r]))
                    problem = "its view or projection is not finite (extreme values)";
    }
    if (problem.empty()) return;
    const Error e("the camera cannot be drawn with: " + problem);
    if (!sourcePlace().file) throw Error(description() + ": " + e.message());
    throw Error::atSceneNode(e, description(), *sourcePlace().file, sourcePlace().line,
                             sourcePlace().column);
}

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
