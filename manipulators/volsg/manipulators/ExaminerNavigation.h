#pragma once
// Inventor's examiner viewer as UI-free camera math: trackball rotation about the focal point,
// pan, dolly, zoom, view all, seek, perspective/orthographic toggle and home. Mouse positions
// are window pixels, origin top-left, y down (as GLFW and PickAction::setPixel give them).

#include <glm/glm.hpp>

#include <volsg/math/Box3.h>
#include <volsg/math/Ray.h>
#include <volsg/nodes/Camera.h>

namespace volsg {

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
    /// orientation (Inventor's seek without the animation).
    void seek(const glm::dvec3& point, double fraction = 0.5);
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
};

} // namespace volsg
