#include <volsg/manipulators/FlyNavigation.h>

#include <algorithm>
#include <cmath>

#include <volsg/manipulators/DragMath.h>

namespace volsg {

glm::dvec2 steeringOffset(const glm::dvec2& mouse, int width, int height) {
    const glm::dvec2 half(0.5 * std::max(width, 1), 0.5 * std::max(height, 1));
    const glm::dvec2 o((mouse.x - half.x) / half.x, (half.y - mouse.y) / half.y);
    return glm::clamp(o, glm::dvec2(-1.0), glm::dvec2(1.0));
}

glm::dquat levelOrientation(const glm::dvec3& forward, const glm::dvec3& up) {
    const glm::dvec3 back = -glm::normalize(forward);
    const glm::dvec3 right = glm::normalize(glm::cross(up, back));
    const glm::dvec3 cameraUp = glm::cross(back, right);
    return glm::normalize(glm::quat_cast(glm::dmat3(right, cameraUp, back)));
}

FlyNavigation::FlyNavigation(ref_ptr<Camera> camera, int width, int height)
    : camera_(std::move(camera)) {
    setViewport(width, height);
    up_ = glm::normalize(camera_->orientation().quat() * glm::dvec3(0.0, 1.0, 0.0));
}

void FlyNavigation::setViewport(int width, int height) {
    width_ = std::max(width, 1);
    height_ = std::max(height, 1);
}

void FlyNavigation::speedUp() {
    if (speed_ == 0.0)
        speed_ = baseSpeed_;
    else if (speed_ > 0.0)
        speed_ *= kSpeedStep;
    else
        speed_ = -speed_ / kSpeedStep < baseSpeed_ * (1.0 - 1e-9) ? 0.0 : speed_ / kSpeedStep;
}

void FlyNavigation::slowDown() {
    if (speed_ == 0.0)
        speed_ = -baseSpeed_;
    else if (speed_ < 0.0)
        speed_ *= kSpeedStep;
    else
        speed_ = speed_ / kSpeedStep < baseSpeed_ * (1.0 - 1e-9) ? 0.0 : speed_ / kSpeedStep;
}

void FlyNavigation::step(const glm::dvec2& mouse, double seconds) {
    const glm::dvec2 steer = steeringOffset(mouse, width_, height_);
    glm::dvec3 forward = glm::normalize(camera_->orientation().quat() * glm::dvec3(0.0, 0.0, -1.0));
    // Heading and elevation about the world up: turning never rolls the camera.
    const double along = std::clamp(glm::dot(forward, up_), -1.0, 1.0);
    glm::dvec3 heading = forward - up_ * along;
    if (glm::length(heading) < 1e-9) // straight up or down: the camera's own up gives the heading
        heading = (along > 0.0 ? -1.0 : 1.0) *
                  (camera_->orientation().quat() * glm::dvec3(0.0, 1.0, 0.0));
    heading = glm::normalize(heading - up_ * glm::dot(heading, up_));
    const double yaw = -steer.x * kTurnRate * seconds;
    heading = glm::angleAxis(yaw, up_) * heading;
    const double elevation =
        std::clamp(std::asin(along) + steer.y * kTurnRate * seconds, -kMaxElevation, kMaxElevation);
    forward = heading * std::cos(elevation) + up_ * std::sin(elevation);
    camera_->orientation = rotationFromQuat(levelOrientation(forward, up_));
    camera_->position = glm::vec3(glm::dvec3(camera_->position()) + forward * (speed_ * seconds));
}

} // namespace volsg
