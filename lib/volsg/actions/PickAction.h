#pragma once
// Casts a ray through a pixel and finds the first shape it hits.

#include <optional>
#include <vector>

#include <volsg/actions/Action.h>
#include <volsg/math/Ray.h>

namespace volsg {

class Camera;

/// What a pick found: the point and normal in world coordinates, the distance along the ray,
/// the path to the shape, and which primitive (triangle or segment) of its mesh.
struct PickedPoint {
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0.0};
    double distance = 0.0; ///< along the world ray, in world units
    std::vector<Node*> path;
    std::size_t primitiveIndex = 0;
};

class PickAction : public Action {
public:
    /// The ray through pixel (x, y) (origin top-left, pixel centres at +0.5) of a viewport of
    /// width x height seen by `camera` with `cameraModel` above it. Without a camera, the
    /// scene's own (findOrMakeCamera) is used.
    void setPixel(double x, double y, int width, int height);
    void setCamera(ref_ptr<Camera> camera, const glm::dmat4& cameraModel = glm::dmat4(1.0));
    /// A world-space ray directly (for manipulators and tests).
    void setRay(const Ray& worldRay, double nearDistance = 0.0);

    /// Called by shapes: a hit at parameter t along the current local ray.
    const Ray& worldRay() const { return worldRay_; }
    /// Shapes report hits in local coordinates; the action keeps the nearest and passes
    /// clip planes in scope (a hit on the removed side of a ClipPlane does not count).
    void addLocalHit(const glm::dvec3& localPoint, const glm::dvec3& localNormal,
                     std::size_t primitiveIndex);

    const std::optional<PickedPoint>& picked() const { return picked_; }

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
    std::optional<PickedPoint> picked_;
};

} // namespace volsg
