#pragma once
// Inventor's fly viewer as UI-free camera math: the mouse's offset from the window centre
// steers (left/right turns about the world up, up/down raises or lowers the nose), the camera
// moves along its view direction at the current speed, and the speed goes up or down in steps
// (Inventor: left click faster, middle click slower). The horizon stays level: the camera never
// rolls, and the nose stays within kMaxElevation of the horizon so that "up" keeps a meaning.

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <volsg/nodes/Camera.h>

namespace volsg {

/// The mouse's offset from the centre of a width x height window (pixels, origin top-left, y
/// down) as steering in [-1, 1]^2: x right, y up; the window's edges are +-1.
glm::dvec2 steeringOffset(const glm::dvec2& mouse, int width, int height);

/// The orientation that looks along `forward` with no roll about it: the camera's x axis is
/// horizontal (perpendicular to `up`). `forward` must not be parallel to `up`.
glm::dquat levelOrientation(const glm::dvec3& forward, const glm::dvec3& up);

class FlyNavigation {
public:
    /// Turn rate at the window's edge, radians per second (proportional to the offset inside).
    static constexpr double kTurnRate = 1.0;
    /// How far (radians) above or below the horizon the nose may point.
    static constexpr double kMaxElevation = 1.4835298641951802; // 85 degrees
    /// speedUp() from rest starts at the base speed; each further step doubles or halves.
    static constexpr double kSpeedStep = 2.0;

    /// Flies `camera` (its position and orientation fields change); the world up is the
    /// camera's up direction now.
    explicit FlyNavigation(ref_ptr<Camera> camera, int width = 1, int height = 1);

    Camera& camera() const { return *camera_; }
    void setCamera(ref_ptr<Camera> camera) { camera_ = std::move(camera); }
    void setViewport(int width, int height);
    void setUpDirection(const glm::dvec3& up) { up_ = glm::normalize(up); }
    const glm::dvec3& upDirection() const { return up_; }

    /// World units per second of the first speed step (the viewer uses a tenth of the scene's
    /// diagonal, so that crossing the scene takes ten seconds at that speed).
    void setBaseSpeed(double unitsPerSecond) { baseSpeed_ = unitsPerSecond; }
    double baseSpeed() const { return baseSpeed_; }
    /// Signed speed along the view direction (negative flies backwards), world units / second.
    double speed() const { return speed_; }
    /// From rest: the base speed forwards; forwards: twice as fast; backwards: half as fast,
    /// and to rest once slower than the base speed. slowDown() is the mirror image.
    void speedUp();
    void slowDown();
    void stop() { speed_ = 0.0; }

    /// One time step of `seconds`: first the turn the steering asks for (kTurnRate * offset *
    /// seconds about the up direction and about the camera's horizontal axis, the elevation
    /// clamped to kMaxElevation), then the move of speed * seconds along the new view direction.
    void step(const glm::dvec2& mouse, double seconds);

private:
    ref_ptr<Camera> camera_;
    int width_ = 1, height_ = 1;
    glm::dvec3 up_{0.0, 1.0, 0.0};
    double baseSpeed_ = 1.0, speed_ = 0.0;
};

} // namespace volsg
