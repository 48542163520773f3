#pragma once
// Cameras: where the scene is seen from. The first camera met in traversal order sets the view
// (its model matrix applies to it).
#include <string>

#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>
#include <volsg/math/Box3.h>

namespace volsg {

class Camera : public Inherit<Node, Camera> {
public:
    static constexpr const char* typeName = "Camera";
    enum ViewportMapping {
        CROP_VIEWPORT_FILL_FRAME,
        CROP_VIEWPORT_LINE_FRAME,
        CROP_VIEWPORT_NO_FRAME,
        ADJUST_CAMERA,
        LEAVE_ALONE
    };
    static const EnumValues viewportMappingNames;

    SFEnum viewportMapping{this, "viewportMapping", viewportMappingNames, ADJUST_CAMERA};
    SFVec3f position{this, "position", glm::vec3(0.0f, 0.0f, 1.0f)};
    SFRotation orientation{this, "orientation"};
    SFFloat aspectRatio{this, "aspectRatio", 1.0f};
    SFFloat nearDistance{this, "nearDistance", 1.0f};
    SFFloat farDistance{this, "farDistance", 10.0f};
    SFFloat focalDistance{this, "focalDistance", 5.0f};

    /// World to eye, given the model matrix above the camera.
    glm::dmat4 viewMatrix(const glm::dmat4& model = glm::dmat4(1.0)) const;
    /// Eye to clip for a viewport of this width/height (ADJUST_CAMERA: the view is widened,
    /// never cropped, to fill it).
    virtual glm::dmat4 projectionMatrix(double viewportAspect) const = 0;
    /// Throws Error (naming this camera and, when it was read from a file, its place) for a
    /// camera no renderer can draw with: a field that is not finite, far not beyond near, a
    /// perspective camera with near <= 0 or heightAngle outside (0, pi), an orthographic one
    /// with height <= 0, or a model matrix `model` that is singular or not finite. Every render
    /// path (GL and the reference ray caster) asks this first, so they agree on what a
    /// degenerate camera is.
    void check(const glm::dmat4& model = glm::dmat4(1.0)) const;
    /// Moves the camera (keeping its orientation) so that the box fills the view; sets near,
    /// far and focal distances around it (Inventor's viewAll).
    virtual void viewAll(const Box3& box, double viewportAspect) = 0;

protected:
    ~Camera() override = default;
    /// What is wrong with this kind of camera's own fields (empty: nothing).
    virtual std::string problem() const;
};

class PerspectiveCamera : public Inherit<Camera, PerspectiveCamera> {
public:
    static constexpr const char* typeName = "PerspectiveCamera";
    static constexpr bool inventorBuiltin() { return true; }
    SFFloat heightAngle{this, "heightAngle", 0.785398163f};

    glm::dmat4 projectionMatrix(double viewportAspect) const override;
    void viewAll(const Box3& box, double viewportAspect) override;

protected:
    ~PerspectiveCamera() override = default;
    std::string problem() const override;
};

class OrthographicCamera : public Inherit<Camera, OrthographicCamera> {
public:
    static constexpr const char* typeName = "OrthographicCamera";
    static constexpr bool inventorBuiltin() { return true; }
    SFFloat height{this, "height", 2.0f};

    glm::dmat4 projectionMatrix(double viewportAspect) const override;
    void viewAll(const Box3& box, double viewportAspect) override;

protected:
    ~OrthographicCamera() override = default;
    std::string problem() const override;
};

} // namespace volsg
