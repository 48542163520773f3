#pragma once
// Casts a ray through a pixel and finds the first shape it hits.

#include <limits>
#include <optional>
#include <vector>

#include <volsg/actions/Action.h>
#include <volsg/actions/ActionMethods.h>
#include <volsg/math/Ray.h>

namespace volsg {

class Camera;

/// What a pick on a planar section (OrthoSlice, ObliqueSlice) found in its volume.
struct PickedVoxel {
    glm::ivec3 index{0};     ///< the nearest voxel (i, j, k): the one whose cell holds the point
    double voxelValue = 0.0; ///< its raw data value
    double value = 0.0;      ///< the value the slice shows there (trilinear or nearest)
    int tag = -1;            ///< the voxel's tag, -1 without tags
};

/// What a pick found: the point and normal in world coordinates, the distance along the ray,
/// the path to the shape, and which primitive (triangle) of its mesh.
struct PickedPoint {
    glm::dvec3 point{0.0};
    /// The mesh's normal there (interpolated vertex normals, else the face normal), unit
    /// length, in world coordinates. Not flipped towards the viewer: a back face hit reports
    /// its outward normal.
    glm::dvec3 normal{0.0};
    double distance = 0.0; ///< along the world ray from its origin, in world units
    std::vector<Node*> path;
    std::size_t primitiveIndex = 0;
    std::optional<PickedVoxel> voxel; ///< set by slices
};

/// Inventor's SoRayPickAction, nearest hit only. Shapes with triangle meshes are pickable;
/// line sets are not (a pick radius would have to be in pixels, which the ray does not know).
///
/// For a pixel, the ray starts at the camera (the eye point of a perspective camera, the
/// camera's plane for an orthographic one) with a unit direction, so `distance` is the
/// distance from the camera; hits nearer than the near plane or beyond the far plane do not
/// count, as they would not be drawn.
class PickAction : public Action {
public:
    /// The pick methods by node type (see RenderAction::methods()): shapes, slices and glTF
    /// models test the ray against what they draw.
    static ActionMethods& methods();

    /// The ray through the centre of pixel (x, y) of a viewport of width x height: origin
    /// top-left, y down, pixel (i, j)'s centre at window position (i + 0.5, j + 0.5), so
    /// integer x, y pick whole pixels as the renderer draws them. Seen by the camera given to
    /// setCamera, or else the scene's own (findOrMakeCamera, at apply time).
    void setPixel(double x, double y, int width, int height);
    void setCamera(ref_ptr<Camera> camera, const glm::dmat4& cameraModel = glm::dmat4(1.0));
    /// A world-space ray directly (for manipulators and tests). The direction is normalized;
    /// hits count between nearDistance and farDistance along it.
    void setRay(const Ray& worldRay, double nearDistance = 0.0,
                double farDistance = std::numeric_limits<double>::infinity());

    /// The ray being cast, in world coordinates, unit direction.
    const Ray& worldRay() const { return worldRay_; }
    /// Shapes report hits in the current node's local coordinates; the action converts them to
    /// world, keeps the nearest, and drops hits outside [near, far] or on the removed side of
    /// any ClipPlane in scope. Slices pass the voxel they hit.
    void addLocalHit(const glm::dvec3& localPoint, const glm::dvec3& localNormal,
                     std::size_t primitiveIndex, std::optional<PickedVoxel> voxel = std::nullopt);

    const std::optional<PickedPoint>& picked() const { return picked_; }

    /// For a pixel pick, once apply() has begun: the view the ray was cast in (the camera's
    /// view and projection, the viewport's size). Screen-space shapes (Text2) test their
    /// screen rectangle in it, as Coin's SoRayPickAction gives them its view volume.
    struct PixelView {
        glm::dmat4 view{1.0}, projection{1.0};
        int width = 1, height = 1;
    };
    const std::optional<PixelView>& pixelView() const { return pixelView_; }

protected:
    void beginTraversal(Node& root) override;
    void dispatch(Node& node) override;

private:
    bool hasPixel_ = false;
    double px_ = 0, py_ = 0;
    int width_ = 1, height_ = 1;
    ref_ptr<Camera> camera_;
    glm::dmat4 cameraModel_{1.0};
    Ray worldRay_;
    double near_ = 0.0;
    double far_ = std::numeric_limits<double>::infinity();
    bool rayValid_ = true;
    std::optional<PickedPoint> picked_;
    std::optional<PixelView> pixelView_;
};

} // namespace volsg
