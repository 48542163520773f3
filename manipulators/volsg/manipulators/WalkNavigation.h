#pragma once
// Inventor's walk viewer as UI-free camera math: the eye stays at its height above the ground
// plane (the plane perpendicular to the camera's up when walking starts); the mouse's
// left/right offset from the window centre turns about the up direction, its up/down offset
// walks forwards/backwards along the heading (the view direction flattened onto the ground),
// and tilt() looks up or down without changing the path. The camera never rolls.

#include <glm/glm.hpp>

#include <volsg/nodes/Camera.h>

namespace volsg {

class WalkNavigation {
public:
    /// Turn rate at the window's edge, radians per second (proportional to the offset inside).
    static constexpr double kTurnRate = 1.0;
    /// How far (radians) tilt() may raise or lower the view from the horizon.
    static constexpr double kMaxTilt = 1.4835298641951802; // 85 degrees

    /// Walks `camera`: its up direction now defines the ground plane, its position now the eye
    /// height (the position's component along up, kept exactly for an axis-aligned up).
    explicit WalkNavigation(ref_ptr<Camera> camera, int width = 1, int height = 1);

    Camera& camera() const { return *camera_; }
    void setViewport(int width, int height);
    const glm::dvec3& upDirection() const { return up_; }
    /// The eye's height: position . up, held on every move.
    double eyeHeight() const { return eyeHeight_; }

    /// World units per second at the window's top edge (the viewer: a tenth of the scene's
    /// diagonal).
    void setWalkSpeed(double unitsPerSecond) { walkSpeed_ = unitsPerSecond; }
    double walkSpeed() const { return walkSpeed_; }

    /// One time step of `seconds`: the turn of kTurnRate * (x offset) * seconds to the right,
    /// then a walk of walkSpeed * (y offset) * seconds along the new heading.
    void step(const glm::dvec2& mouse, double seconds);
    /// Turns by `radians` about up (positive: to the left, counter-clockwise seen from above).
    void turn(double radians);
    /// Walks `distance` along the heading (negative: backwards).
    void walk(double distance);
    /// Raises (positive) or lowers the view by `radians`, clamped to kMaxTilt from the horizon.
    void tilt(double radians);

    /// The unit direction of travel: the view direction flattened onto the ground plane.
    glm::dvec3 heading() const;
    /// Radians above the horizon the camera looks.
    double elevation() const;

private:
    void look(const glm::dvec3& heading, double elevation);
    ref_ptr<Camera> camera_;
    int width_ = 1, height_ = 1;
    glm::dvec3 up_{0.0, 1.0, 0.0};
    double eyeHeight_ = 0.0;
    double walkSpeed_ = 1.0;
};

} // namespace volsg
