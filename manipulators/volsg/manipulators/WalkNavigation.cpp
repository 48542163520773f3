#include <volsg/manipulators/WalkNavigation.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include <volsg/manipulators/DragMath.h>
#include <volsg/manipulators/FlyNavigation.h>

namespace volsg {

WalkNavigation::WalkNavigation(ref_ptr<Camera> camera, int width, int height)
    : camera_(std::move(camera)) {
    setViewport(width, height);
    up_ = glm::normalize(camera_->orientation().quat() * glm::dvec3(0.0, 1.0, 0.0));
    eyeHeight_ = glm::dot(glm::dvec3(camera_->position()), up_);
}

void WalkNavigation::setViewport(int width, int height) {
    width_ = std::max(width, 1);
    height_ = std::max(height, 1);
}

glm::dvec3 WalkNavigation::heading() const {
    const glm::dquat q = camera_->orientation().quat();
    glm::dvec3 flat = q * glm::dvec3(0.0, 0.0, -1.0);
    flat -= up_ * glm::dot(flat, up_);
    if (glm::length(flat) < 1e-9) { // looking straight down (or up): the camera's up leads
        flat = q * glm::dvec3(0.0, 1.0, 0.0);
        flat -= up_ * glm::dot(flat, up_);
    }
    return glm::normalize(flat);
}

double WalkNavigation::elevation() const {
    const glm::dvec3 forward = camera_->orientation().quat() * glm::dvec3(0.0, 0.0, -1.0);
    return std::asin(std::clamp(glm::dot(glm::normalize(forward), up_), -1.0, 1.0));
}

void WalkNavigation::look(const glm::dvec3& heading, double elevation) {
    const glm::dvec3 forward = heading * std::cos(elevation) + up_ * std::sin(elevation);
    camera_->orientation = rotationFromQuat(levelOrientation(forward, up_));
}

void WalkNavigation::turn(double radians) {
    look(glm::angleAxis(radians, up_) * heading(), elevation());
}

void WalkNavigation::tilt(double radians) {
    look(heading(), std::clamp(elevation() + radians, -kMaxTilt, kMaxTilt));
}

void WalkNavigation::walk(double distance) {
    glm::dvec3 p = glm::dvec3(camera_->position()) + heading() * distance;
    p -= up_ * (glm::dot(p, up_) - eyeHeight_); // back onto the eye-height plane
    camera_->position = glm::vec3(p);
}

void WalkNavigation::step(const glm::dvec2& mouse, double seconds) {
    const glm::dvec2 steer = steeringOffset(mouse, width_, height_);
    turn(-steer.x * kTurnRate * seconds);
    walk(steer.y * walkSpeed_ * seconds);
}

} // namespace volsg
