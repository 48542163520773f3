#pragma once
// Inventor's examiner viewer as UI-free camera math: trackball rotation about the focal point,
// pan, dolly, zoom, view all, seek (at once or animated), perspective/orthographic toggle and
// home. Mouse positions are window pixels, origin top-left, y down (as GLFW and
// PickAction::setPixel give them).

#include <optional>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <volsg/math/Box3.h>
#include <volsg/math/Ray.h>
#include <volsg/nodes/Camera.h>

namespace volsg {

/// The camera fields a seek moves: where it is, where it looks and how far its focal point is.
struct CameraPose {
    glm::dvec3 position{0.0};
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};
    double focalDistance = 1.0;
};

/// The pose a fraction `s` in [0, 1] of the way from `from` to `to`: position and focal
/// distance linear, orientation by slerp (the shorter way round), so the focal point moves on
/// the straight line between the two focal points when the orientation stays.
CameraPose interpolatePose(const CameraPose& from, const CameraPose& to, double s);

/// Smoothstep easing s^2 (3 - 2 s) of s clamped to [0, 1]: starts and stops at rest.
double seekEasing(double s);

class ExaminerNavigation {
public:
    /// Navigates `camera` (its fields are changed) in a viewport of width x height pixels.
    explicit ExaminerNavigation(ref_ptr<Camera> camera, int width = 1, int height = 1);

    Camera& camera() const { return *camera_; }
    ref_ptr<Camera> cameraPtr() const { return camera_; }
    void setViewport(int width, int height);
    double aspect() const { return double(width_) / double(height_); }

    /// The point the camera turns about: position + focalDistance along the view direction.
    glm::dvec3 focalPoint() const;
    glm::dvec3 viewDirection() const; ///< unit, world coordinates
    glm::dvec3 upDirection() const;   ///< unit, world coordinates

    /// Turns the camera about the focal point as a virtual trackball would turn the scene: a
    /// drag from `from` to `to` rotates the scene the way the mouse moved.
    void rotate(const glm::dvec2& from, const glm::dvec2& to);
    /// Moves the camera sideways so that the point at the focal distance follows the mouse.
    void pan(const glm::dvec2& from, const glm::dvec2& to);
    /// Moves towards the focal point: the focal distance is multiplied by `factor` (< 1 closer).
    /// An orthographic camera scales its height instead, which is what moving closer looks like.
    void dolly(double factor);
    /// Narrows (factor < 1) or widens the view angle (or an orthographic camera's height).
    void zoom(double factor);
    /// The whole box in view (Camera::viewAll) at the current viewport's aspect.
    void viewAll(const Box3& box);
    /// Moves `fraction` of the way to a picked point, which becomes the focal point, keeping the
    /// orientation (Inventor's seek without the animation). A point not in front of the camera
    /// leaves it where it is.
    void seek(const glm::dvec3& point, double fraction = 0.5);
    /// Inventor's animated seek (SoSeekTime): over `duration` seconds the camera flies from its
    /// pose now to the one seek(point, fraction) gives, eased by seekEasing() and interpolated
    /// by interpolatePose(); stepSeek() advances it by the viewer's frame time. At the end the
    /// camera's fields are exactly those seek() sets. A duration <= 0 seeks at once. False (and
    /// nothing changes) for a point not in front of the camera.
    bool startSeek(const glm::dvec3& point, double fraction = 0.5, double duration = 0.5);
    /// Advances a running seek by `seconds` and moves the camera there; true while it still
    /// runs afterwards.
    bool stepSeek(double seconds);
    bool isSeeking() const { return seek_.has_value(); }
    /// Ends a running seek where the camera is now (any other navigation does this too).
    void stopSeek() { seek_.reset(); }
    /// The running seek's camera `t` seconds after its start (t clamped to [0, duration]).
    CameraPose seekPose(double t) const;
    /// The camera's pose now.
    CameraPose pose() const;
    /// Switches between a perspective and an orthographic camera showing the same thing at the
    /// focal distance; camera() is the new camera afterwards.
    void toggleProjection();
    bool isOrthographic() const;
    /// Remembers the current camera fields as home / goes back to them.
    void saveHome();
    void goHome();
    /// Near and far distances around the box (Inventor's auto clipping planes); an
    /// orthographic camera inside the box steps back so that nothing is cut away.
    void adjustClipping(const Box3& box);

    /// The world ray through the centre of pixel (x, y) of the viewport (as PickAction casts
    /// it: x + 0.5, y + 0.5 for integer pixels is the caller's choice).
    Ray pixelRay(const glm::dvec2& pixel) const;

private:
    glm::dvec3 trackballVector(const glm::dvec2& pixel) const;
    std::optional<CameraPose> seekTarget(const glm::dvec3& point, double fraction) const;
    void applyPose(const CameraPose& pose);
    double worldUnitsPerPixel() const;
    ref_ptr<Camera> camera_;
    int width_ = 1, height_ = 1;
    struct Home {
        bool orthographic = false;
        glm::vec3 position{0.0f};
        Rotation orientation;
        float focalDistance = 5.0f, nearDistance = 1.0f, farDistance = 10.0f;
        float heightAngle = 0.785398163f, height = 2.0f;
    } home_;
    struct Seek {
        CameraPose from, to;
        Rotation endOrientation; ///< the field value seek() leaves, set exactly at the end
        double duration = 0.5, elapsed = 0.0;
    };
    std::optional<Seek> seek_;
};

} // namespace volsg
